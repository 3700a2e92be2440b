"""The lid-driven cavity with the two-fluid model's normal fluid alone (paper 5 sec. IV.5, Fig. 4)
against Ghia, Ghia & Shin (1982): centre-line velocities at t = 30 and the L-infinity error at
Re = 100 and 1000, two resolutions each.

Usage: /usr/bin/python3 tools/plots/two_fluid_cavity.py [--make-runs] [--runs DIR] [--out DIR]
           [--revsph PATH] [--threads N] [--only NAME ...]

--make-runs runs models/two_fluid/cases/two-fluid-cavity-re100.toml with dr = 1 / N and
eta = 1 / Re into RUNS/NAME (default RUNS = out/two_fluid): N = 40, 60 at Re = 100 and N = 60, 80
at Re = 1000 (N = 80: about 5 minutes on one thread).
Writes into --out (default docs/figures):
  two_fluid_cavity.png  u on x = 1/2 and v on y = 1/2 against Ghia at each Re and N
  two_fluid_cavity.csv  run, Re, N, L-infinity error, the same away from the walls, time
  two_fluid_cavity.md   the numbers (also printed)

The velocity at a point is the kernel-weighted (Shepard) average over the normal particles and
the walls (walls with their own velocity), support 3 dr as in the case; "away from the walls"
keeps Ghia's points at least one support inside the cavity.
"""

import csv
import sys
from pathlib import Path

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from cavity_ghia import CentreLines, draw_ghia  # noqa: E402
from revsph_runs import REPO, chosen_runs, figure_parser, figure_script_main, save_figure, snapshots  # noqa: E402,E501

CASE = REPO / "models" / "two_fluid" / "cases" / "two-fluid-cavity-re100.toml"
RUNS = {f"cavity-re{re}-n{n}": (re, n) for re, ns in ((100, (40, 60)), (1000, (60, 80)))
        for n in ns}


def command(re, n):
    dr = 1.0 / n
    top = 1.0 + 3.0 * dr  # three layers of lid
    return ["run", str(CASE), "--set", f"discretisation.dr={dr!r}",
            "--set", f"particles[1].max=[1.0, {top!r}]", "--set", f"particles[2].max=[1.0, {top!r}]",
            "--set", f"physics.normal_viscosity={1.0 / re!r}",
            "--set", "output.snapshot_every=1000000000"]


def final_state(run):
    with h5py.File(snapshots(run)[-1]) as f:
        normal, wall = f["particles/normal"], f["particles/wall"]
        velocity = normal["momentum"][...] / normal["mass"][...].reshape(-1, 1)
        position = np.concatenate([normal["position"][...], wall["position"][...]])
        velocity = np.concatenate([velocity, wall["velocity"][...]])
        return position, velocity, float(f.attrs["time"])


def make_figures(runs, out, report, names):
    fig, axes = plt.subplots(2, 2, figsize=(10, 8))
    line = np.linspace(0.0, 1.0, 101)
    rows = []
    for name in names:
        re, n = RUNS[name]
        position, velocity, time = final_state(runs / name)
        lines = CentreLines(position, velocity, 3.0 / n, re)
        rows.append((name, re, n, lines.error, lines.interior, time))
        row = 0 if re == 100 else 1
        axes[row, 0].plot(lines.u_at(line), line, label=f"N = {n}")
        axes[row, 1].plot(line, lines.v_at(line), label=f"N = {n}")
    for re in sorted({r[1] for r in rows}):
        draw_ghia(*axes[0 if re == 100 else 1], re)
    fig.tight_layout()
    save_figure(fig, out / "two_fluid_cavity.png")
    with open(out / "two_fluid_cavity.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["run", "Re", "N", "linf_error", "linf_error_interior", "time"])
        writer.writerows([r[0], r[1], r[2], f"{r[3]:.6g}", f"{r[4]:.6g}", f"{r[5]:.6g}"]
                         for r in rows)
    report[:0] = [(f"{r[0]}: L-infinity error against Ghia at t = {r[5]:.1f} (away from the "
                   f"walls)", f"{r[3]:.4f} ({r[4]:.4f})") for r in rows]


def main():
    parser = figure_parser(__doc__, "out/two_fluid", REPO / "docs" / "figures", RUNS)
    args = parser.parse_args()
    names = chosen_runs(parser, args, RUNS)
    return figure_script_main(
        args, {n: command(*RUNS[n]) for n in names},
        [(names, lambda runs, out, report: make_figures(runs, out, report, names))],
        "two_fluid_cavity.md")


if __name__ == "__main__":
    sys.exit(main())
