#!/usr/bin/python3
"""Every figure of paper 1 (Kincl & Pavelka 2023) from revsph runs, with one command.

Usage: /usr/bin/python3 tools/plots/paper1_figures.py [--list] [--runs DIR] [--out DIR]
           [--make-runs] [--no-full] [--no-gresho] [--revsph PATH] [--threads N]
           [--refdata DIR]

  --list       print each figure file, the paper figure it reproduces, and the runs (with their
               revsph commands) it needs, marking runs that are missing; nothing is run
  --runs DIR   where the runs live, one subdirectory per run (default: out/paper1)
  --out DIR    where the figures go (default: docs/figures of this repository)
  --make-runs  first make every missing run (a run counts as present when its summary.json
               exists), printing each revsph command, one at a time
  --no-full    neither make nor use the Table-1 run (80 000 particles, about 1.5 h on 2 cores
               for 1 s forward and back): its figures come from dambreak-small instead, with
               "_dambreak-small" in their names. This also happens, with a note, when the full
               run is simply missing.
  --no-gresho  do not call tools/plots/gresho_table.py
  --revsph     the revsph binary (default: build/bin/revsph, else build-*/bin/revsph)
  --threads N  passed to revsph (default: revsph's own, all cores)
  --refdata    the published reference data for Fig. 4 (default: leading_edge.py's)

Besides the figures, OUT/paper1_numbers.csv gets one row per dam-break run present in RUNS (the
runs below, whichever exist; a run directory holding only summary.json and forward/energy.csv,
such as the committed record of the Table-1 run, counts): dr, dt, particles, the largest
relative energy error |E - E0| / |E0| of the forward run (Fig. 8, sec. 5's "less than 2e-4 %"),
its error bar (how much the maximum changes when only every fifth energy sample is kept: the
samples may miss the peak), the largest |Fig. 5 quantity| (E(t) - E(0)) / (E_g(0) - E_g(t_end)),
the shares of the released potential energy E_g(0) - E_g(t_end) found as kinetic and as
compressional energy at t_end (sec. 5: "approximately 3/4 to the kinetic and 1/4 to the
internal") and, for a reversal, whether it returned bitwise.

Without --make-runs, figures whose runs are missing are skipped (the exit status is then 1).
tools/plots/gresho_table.py (Table 2, Gresho vortex), when present, is called as
`gresho_table.py --runs RUNS --out OUT --revsph REVSPH [--threads N]`; it makes the Gresho runs
it lacks, so it is called only with --make-runs or when RUNS already holds gresho-* runs, all
with summary.json; when absent it is skipped with a note. Exit status 0 only if every figure
was made.
"""

import csv
import json
import os
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np

from docstring_cli import parser_from_docstring

REPO = Path(__file__).resolve().parents[2]
PLOTS = REPO / "tools" / "plots"
PYTHON = "/usr/bin/python3" if os.access("/usr/bin/python3", os.X_OK) else sys.executable
SMALL_TAG = "_dambreak-small"
SIZE_LIMIT = 300_000  # bytes per PNG, so the figures can live in the repository
CASE_DR = {"dambreak": "0.005", "dambreak-small": "0.02"}  # the cases' own dr (m)


class Run:
    def __init__(self, name, arguments, purpose, expected_status=(0,)):
        self.name, self.arguments, self.purpose = name, arguments, purpose
        self.expected_status = expected_status

    def path(self, runs):
        return runs / self.name

    def present(self, runs):
        return (self.path(runs) / "summary.json").is_file()

    def command(self, revsph, runs, threads):
        command = [str(revsph)] + self.arguments + ["--out", str(self.path(runs))]
        if threads:
            command += ["--threads", str(threads)]
        return command


def small(extra, purpose, expected_status=(0,)):
    return ["verify", "dambreak-small", "--t-end", "1"] + extra, purpose, expected_status


FULL = Run("dambreak-full",
           ["verify", "dambreak", "--t-end", "1", "--set", "output.snapshot_every=1000",
            "--set", "output.energy_every=100"],
           "Table 1 (dr = 0.005 m, 80 000 fluid particles, dt = 2.5e-5 s), 1 s forward and "
           "back: about 1.5 h on 2 cores")
SMALL_FIXED = Run("dambreak-small-fixed", *small(
    ["--set", "output.snapshot_every=200", "--set", "output.energy_every=20"],
    "dr = 0.02 m, 5 000 fluid particles, dt = 1e-4 s (Courant 0.2): about 2 min on 1 core"))
SMALL_FLOAT = Run("dambreak-small-float", *small(
    ["--arithmetic", "float", "--set", "output.snapshot_every=200",
     "--set", "output.energy_every=20"],
    "as dambreak-small-fixed in floating point (FloPA); exit status 1 (not reversible) is the "
    "expected outcome. A float run of the full case would cost another 1.5 h, so Fig. 3 uses "
    "dambreak-small for both arithmetics", expected_status=(0, 1)))
SMALL_DT2 = Run("dambreak-small-courant0.1", *small(
    ["--set", "discretisation.courant_number=0.1", "--set", "output.snapshot_every=0",
     "--set", "output.energy_every=40"], "dt/2 = 5e-5 s: about 4 min on 1 core"))
SMALL_DT4 = Run("dambreak-small-courant0.05", *small(
    ["--set", "discretisation.courant_number=0.05", "--set", "output.snapshot_every=0",
     "--set", "output.energy_every=80"], "dt/4 = 2.5e-5 s: about 8 min on 1 core"))
DR01 = Run("dambreak-dr0.01",
           ["run", "dambreak", "--t-end", "1", "--set", "discretisation.dr=0.01",
            "--set", "output.snapshot_every=0", "--set", "output.energy_every=50"],
           "Table 1 at dr = 0.01 m (20 000 fluid particles, dt = 5e-5 s), 1 s forward: the energy "
           "error at a second resolution, about 4 min on 1 core")
RUNS = (FULL, SMALL_FIXED, SMALL_FLOAT, SMALL_DT2, SMALL_DT4, DR01)
NUMBERS = "paper1_numbers.csv"


def figures(use_full):
    """(files, paper figure, runs, how it is made) for every figure. `how` is a tuple:
    ("script", name, argument builder) or ("entropy", run)."""
    main = FULL if use_full else SMALL_FIXED
    tag = "" if use_full else SMALL_TAG
    drift_runs = ([FULL] if use_full else []) + [SMALL_FIXED, SMALL_DT2, SMALL_DT4]
    drift_labels = (["dambreak (Table 1), dt = 2.5e-5 s"] if use_full else []) + [
        "dambreak-small, dt = 1e-4 s (Courant 0.2)", "dambreak-small, dt/2 (Courant 0.1)",
        "dambreak-small, dt/4 (Courant 0.05)"]

    def energy_args(runs, out):
        labels = [a for label in drift_labels for a in ("--label", label)]
        return ([str(r.path(runs)) for r in drift_runs] + labels + ["--out", str(out)]
                + ["--tag", tag])

    return [
        ([f"fixpa_flopa{SMALL_TAG}.png"], "Fig. 3 (FixPA vs FloPA reversal)",
         [SMALL_FIXED, SMALL_FLOAT],
         ("script", "fixpa_flopa.py", lambda runs, out: [
             str(SMALL_FIXED.path(runs)), str(SMALL_FLOAT.path(runs)), "--out", str(out),
             "--tag", SMALL_TAG])),
        ([f"leading_edge{tag}.png"], "Fig. 4 (surge front against experiments)", [main],
         ("script", "leading_edge.py", lambda runs, out: [
             str(main.path(runs)), "--out", str(out), "--tag", tag])),
        ([f"energy_budget{tag}.png", f"energy_drift{tag}.png"],
         "Figs. 8-12 (energy budget, first run) and Fig. 5 (energy drift per dt)",
         drift_runs, ("script", "energy_budget.py", energy_args)),
        ([f"entropy{tag}.png", f"histogram{tag}.png"],
         "Fig. 6 right (Boltzmann entropy) and left (speed histogram)", [main],
         ("entropy", main, tag)),
    ]


def read_columns(path):
    """An energy.csv by column name (header cells are `name [unit]`, or `name` in older runs)."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {key.split(" [")[0]: np.array([float(r[key]) for r in rows]) for key in rows[0]}


def energy_numbers(run_dir):
    """The row of paper1_numbers.csv for one run directory (see the module docstring)."""
    summary = json.loads((run_dir / "summary.json").read_text())
    forward = run_dir / "forward" / "energy.csv"
    energy = read_columns(forward if forward.is_file() else run_dir / "energy.csv")
    error = np.abs(energy["total"] - energy["total"][0]) / abs(energy["total"][0])
    drop = energy["gravitational"][0] - energy["gravitational"][-1]
    overrides = dict(o.split("=", 1) for o in summary.get("overrides", []))
    identical = summary.get("identical")
    return {"run": run_dir.name, "case": summary["case"],
            "dr": overrides.get("discretisation.dr", CASE_DR.get(summary["case"], "")),
            "dt": summary["dt"], "particles": summary["particles"]["fluid"],
            "energy_samples": len(error),
            "max_relative_energy_error": f"{error.max():.4e}",
            "error_bar": f"{error.max() - error[::5].max():.1e}",
            "max_fig5_quantity": f"{np.max(np.abs(energy['total'] - energy['total'][0])) / drop:.4e}",
            "kinetic_share_at_end": f"{(energy['kinetic'][-1] - energy['kinetic'][0]) / drop:.4f}",
            "compressional_share_at_end":
                f"{(energy['compressional'][-1] - energy['compressional'][0]) / drop:.4f}",
            "returned_bitwise": "" if identical is None else str(bool(identical)).lower()}


def write_numbers(runs, out):
    rows = [energy_numbers(r.path(runs)) for r in RUNS if r.present(runs)]
    if not rows:
        return
    with open(out / NUMBERS, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print(f"wrote {out / NUMBERS} ({len(rows)} runs)")


def find_revsph(given):
    if given:
        return Path(given)
    candidates = [REPO / "build" / "bin" / "revsph"] + sorted(REPO.glob("build-*/bin/revsph"))
    for candidate in candidates:
        if os.access(candidate, os.X_OK):
            return candidate
    return candidates[0]


def show(command):
    print("$ " + shlex.join(str(c) for c in command), flush=True)


def environment():
    env = dict(os.environ)
    # Waiting OpenMP threads sleep instead of spinning, so a loaded machine keeps its pace.
    env.setdefault("OMP_WAIT_POLICY", "PASSIVE")
    return env


def make_run(run, revsph, runs, threads):
    command = run.command(revsph, runs, threads)
    if run.path(runs).exists() and any(run.path(runs).iterdir()):
        command.append("--force")  # an interrupted earlier attempt: no summary.json
    show(command)
    status = subprocess.run(command, env=environment()).returncode
    if status not in run.expected_status or not run.present(runs):
        print(f"error: {run.name}: revsph exited with status {status}", file=sys.stderr)
        return False
    return True


def list_figures(table, runs, revsph, threads, out):
    print(f"figures go to {out}; runs live in {runs}\n")
    for files, paper, needed, _ in table:
        print(f"{', '.join(files)}\n    reproduces {paper}\n    needs: "
              + ", ".join(f"{r.name}{'' if r.present(runs) else ' (missing)'}" for r in needed))
    gresho = PLOTS / "gresho_table.py"
    print(f"\nTable 2 (Gresho vortex): {gresho.relative_to(REPO)} --runs RUNS --out OUT "
          f"--revsph REVSPH, with --make-runs or when RUNS holds its gresho-* runs "
          f"({'present' if gresho.is_file() else 'not present: skipped'})")
    print("\nruns (made by --make-runs, one at a time, skipped when summary.json exists):")
    for run in RUNS:
        print(f"  {run.name}: {run.purpose}\n    "
              + shlex.join(run.command(revsph, runs, threads)))
    print("\nFig. 3 uses dambreak-small in both arithmetics, because a float run of the full "
          "case costs another 1.5 h; Fig. 5 compares dt, dt/2, dt/4 on dambreak-small (plus the "
          "full run at its dt).\nWithout dambreak-full (or with --no-full), Figs. 4, 5, 6 and "
          f"8-12 are made from dambreak-small-fixed instead, as *{SMALL_TAG}.png.")


def main(argv=None):
    parser = parser_from_docstring(__doc__)
    parser.add_argument("--list", action="store_true")
    parser.add_argument("--runs", default=str(REPO / "out" / "paper1"))
    parser.add_argument("--out", default=str(REPO / "docs" / "figures"))
    parser.add_argument("--make-runs", action="store_true")
    parser.add_argument("--no-full", action="store_true")
    parser.add_argument("--no-gresho", action="store_true")
    parser.add_argument("--revsph")
    parser.add_argument("--threads", type=int)
    parser.add_argument("--refdata")
    args = parser.parse_args(argv)
    runs, out = Path(args.runs).resolve(), Path(args.out).resolve()
    revsph = find_revsph(args.revsph)

    use_full = not args.no_full and (args.make_runs or FULL.present(runs) or args.list)
    table = figures(use_full)
    if args.list:
        list_figures(table, runs, revsph, args.threads, out)
        return 0
    if not args.no_full and not use_full:
        print(f"note: {FULL.path(runs)}/summary.json is missing: the Table-1 figures are made "
              f"from dambreak-small and named *{SMALL_TAG}.png (--make-runs makes the full run)")

    ok = True
    if args.make_runs:
        if not os.access(revsph, os.X_OK):
            sys.exit(f"no revsph binary at {revsph} (build it, or give --revsph)")
        runs.mkdir(parents=True, exist_ok=True)
        needed = [r for r in RUNS if use_full or r is not FULL]
        for run in needed:
            if run.present(runs):
                print(f"{run.name}: present ({run.path(runs)}/summary.json), not run again")
            elif not make_run(run, revsph, runs, args.threads):
                ok = False

    out.mkdir(parents=True, exist_ok=True)
    made = []
    for files, paper, needed, how in table:
        missing = [r.name for r in needed if not r.present(runs)]
        if missing:
            print(f"skipped {', '.join(files)} ({paper}): missing runs {', '.join(missing)}")
            ok = False
            continue
        if how[0] == "script":
            command = [PYTHON, str(PLOTS / how[1])] + how[2](runs, out)
            if how[1] == "leading_edge.py" and args.refdata:
                command += ["--refdata", args.refdata]
        else:
            command = [str(revsph), "entropy", str(how[1].path(runs))]
        show(command)
        if subprocess.run(command, env=environment()).returncode != 0:
            print(f"error: {paper}: the command failed", file=sys.stderr)
            ok = False
            continue
        if how[0] == "entropy":
            analysis = how[1].path(runs) / "analysis"
            for name, target in zip(("entropy.png", "histogram.png"), files):
                shutil.copyfile(analysis / name, out / target)
        made += files

    write_numbers(runs, out)

    gresho = PLOTS / "gresho_table.py"
    # gresho_table.py makes whatever Gresho runs it lacks, so it is only called where runs may
    # be made (--make-runs) or where its runs are already there.
    gresho_runs = sorted(runs.glob("gresho-*"))
    gresho_ready = bool(gresho_runs) and all((r / "summary.json").is_file() for r in gresho_runs)
    if args.no_gresho:
        pass
    elif not gresho.is_file():
        print(f"note: {gresho.relative_to(REPO)} does not exist: Table 2 (Gresho vortex) skipped")
    elif not (args.make_runs or gresho_ready):
        print(f"note: Table 2 (Gresho vortex) skipped: no gresho-* runs in {runs}; "
              f"--make-runs lets {gresho.name} make them")
    else:
        command = [PYTHON, str(gresho), "--runs", str(runs), "--out", str(out),
                   "--revsph", str(revsph)]
        if args.threads:
            command += ["--threads", str(args.threads)]
        show(command)
        if subprocess.run(command, env=environment()).returncode != 0:
            print("error: gresho_table.py failed", file=sys.stderr)
            ok = False

    for name in made:
        size = (out / name).stat().st_size
        warning = "  (larger than the 300 kB meant for the repository)" \
            if size > SIZE_LIMIT else ""
        print(f"  {out / name}: {size / 1000:.0f} kB{warning}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
