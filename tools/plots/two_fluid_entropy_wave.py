#!/usr/bin/python3
"""Paper 5's entropy-wave benchmark (Tsuzuki 2021, sec. V.2, Figs. 7-8): the wave equation on the
unit square, mode (4, 3), with the SPH Laplacian of App. A on a lattice whose particles are shifted
by dl in random directions; the relative error E_r at t = 0.03 s against the volume fluctuation
rate dD, for c = 135 and 20 m/s, and S at a probe particle against t.

Usage: /usr/bin/python3 tools/plots/two_fluid_entropy_wave.py [--make-runs] [--quick] [--runs DIR]
           [--out DIR] [--tool PATH]

--make-runs runs the tool (default build/bin/revsph_two_fluid_entropy_wave) on one thread for
every run missing in RUNS (default out/two_fluid_entropy_wave, with --quick
out/two_fluid_entropy_wave_quick): the sph Laplacian at dD = 0, 0.25, 0.5, 1, 1.5, 2, 3 %, the
Brookshaw form at dD = 0 and 0.5 %, the 5-point finite difference (which has no particle
positions, so dD = 0 only), each for c = 135 and 20, on 400 x 400 particles (--quick: 100 x 100).
A 400 x 400 run takes about 1 min (c = 135, 16 200 steps) or 10 s (c = 20) on one core, the
whole set 10.5 min; --quick 9 s.
Writes into --out (default docs/figures; with --quick RUNS, and the names end in _quick):
  two_fluid_entropy_wave.csv  the summary rows of every run (columns: the tool's source,
                              tools/analysis/two_fluid_entropy_wave_main.cpp).
  two_fluid_entropy_wave.png  (a), (b) as the paper's Fig. 8: E_r against dD for c = 135 and 20
                              with the least-squares fit E_r = a + b dD^p over dD > 0 (p in the
                              legend), FD and Brookshaw; open symbols: the part of E_r outside
                              the mode (the mode's phase error removed). (c) as Fig. 7: S at the
                              particle of the lattice cell holding (0.3, 0.4) for c = 135,
                              dD = 0.5 and 3 %, FD and the exact curve; (d) their differences
                              from the exact curve.

E_r = mean_i |S_i - S_a| / (|S_a| + 1) x 100 (the paper prints |S_a + A|, zero where S_a = -1).
"""

import csv
import os
import shlex
import subprocess
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy.optimize import curve_fit  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from docstring_cli import parser_from_docstring  # noqa: E402

REPO = Path(__file__).resolve().parents[2]
SPEEDS = (135, 20)
FLUCTUATIONS = (0, 0.25, 0.5, 1, 1.5, 2, 3)
RUNS = ([("sph", c, d) for c in SPEEDS for d in FLUCTUATIONS]
        + [("brookshaw", c, d) for c in SPEEDS for d in (0, 0.5)]
        + [("fd", c, 0) for c in SPEEDS])
PAPER = {135: "0.018 % at dD = 0.5", 20: "0.012 % at dD = 0.5"}


def run_name(method, speed, fluctuation):
    return f"{method}-c{speed}-dD{fluctuation}"


def make_missing_runs(runs, tool, particles):
    runs.mkdir(parents=True, exist_ok=True)
    environment = dict(os.environ, OMP_NUM_THREADS="1", OMP_WAIT_POLICY="passive")
    for method, speed, fluctuation in RUNS:
        prefix = runs / run_name(method, speed, fluctuation)
        if (prefix.parent / (prefix.name + ".csv")).is_file():
            continue
        command = [str(tool), "--method", method, "--speed", str(speed), "--fluctuation",
                   str(fluctuation), "--particles", str(particles), "--out", str(prefix)]
        print("+", shlex.join(command), flush=True)
        subprocess.run(command, check=True, env=environment, stdout=subprocess.DEVNULL)


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(row for row in f if not row.startswith("#")))


def power_fit(fluctuation, error):
    """Least-squares E_r = a + b dD^p over dD > 0; None if it does not converge."""
    x, y = np.asarray(fluctuation), np.asarray(error)
    chosen = x > 0
    guess = (max(y.min(), 0.0), max((y[chosen][-1] - y.min()) / x[chosen][-1] ** 2, 1e-12), 2.0)
    try:
        parameters, _ = curve_fit(lambda d, a, b, p: a + b * d ** p, x[chosen], y[chosen],
                                  p0=guess, bounds=([0.0, 0.0, 0.1], [np.inf, np.inf, 6.0]),
                                  maxfev=20000)
    except RuntimeError:
        return None
    return parameters


def error_panel(ax, rows, speed, report):
    def picked(method):
        chosen = sorted((r for r in rows if r["method"] == method and int(float(r["speed"])) ==
                         speed), key=lambda r: float(r["fluctuation"]))
        return (np.array([float(r["fluctuation"]) for r in chosen]),
                np.array([float(r["mean_error_percent"]) for r in chosen]),
                np.array([float(r["off_mode_error_percent"]) for r in chosen]))

    d, error, off_mode = picked("sph")
    ax.semilogy(d, error, "o", color="tab:blue", label="SPH (App. A) $E_r$")
    fit = power_fit(d, error)
    if fit is not None:
        line = np.linspace(0.0, d.max(), 200)
        ax.semilogy(line, fit[0] + fit[1] * line ** fit[2], "-", color="tab:blue",
                    label=f"fit {fit[0]:.3g} + {fit[1]:.2g} dD$^{{{fit[2]:.2f}}}$")
        report.append(f"c = {speed}: sph fit E_r = {fit[0]:.4g} + {fit[1]:.4g} dD^{fit[2]:.3f}")
    positive = d > 0
    ax.semilogy(d[positive], off_mode[positive], "o", mfc="none", color="tab:blue",
                label="SPH, part outside the mode")
    off_fit = power_fit(d, off_mode)
    if off_fit is not None:
        report.append(f"c = {speed}: sph part outside the mode = {off_fit[0]:.3g} + "
                      f"{off_fit[1]:.4g} dD^{off_fit[2]:.3f}")
    for value, e in zip(d, error):
        report.append(f"c = {speed}: sph E_r(dD = {value:g}) = {e:.4g} %")
    fd = picked("fd")
    if len(fd[0]):
        ax.axhline(fd[1][0], color="k", linestyle="--", label=f"FD (5-point) {fd[1][0]:.3g} %")
        report.append(f"c = {speed}: fd E_r = {fd[1][0]:.4g} %")
    b = picked("brookshaw")
    if len(b[0]):
        ax.semilogy(b[0], b[1], "s", color="tab:red", label="Brookshaw (eq. 14 x 2)")
        report.extend(f"c = {speed}: brookshaw E_r(dD = {v:g}) = {e:.4g} %"
                      for v, e in zip(b[0], b[1]))
    ax.set(xlabel="volume fluctuation rate dD [%]", ylabel="$E_r$ [%]",
           title=f"c = {speed} m/s (paper's Fig. 8{'a' if speed == 135 else 'b'}; paper: "
                 f"{PAPER[speed]})")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="upper right" if speed == 135 else "lower right")


def probe_panels(ax_value, ax_difference, runs):
    exact_drawn = False
    for method, fluctuation, style in (("fd", 0, "k-"), ("sph", 0.5, "-"), ("sph", 3, "-")):
        path = runs / (run_name(method, 135, fluctuation) + "_probe.csv")
        if not path.is_file():
            continue
        rows = read_rows(path)
        t = 1e3 * np.array([float(r["time"]) for r in rows])
        s = np.array([float(r["S"]) for r in rows])
        exact = np.array([float(r["S_exact"]) for r in rows])
        if not exact_drawn:
            ax_value.plot(t, exact, color="0.6", linewidth=3, label="exact")
            exact_drawn = True
        label = "FD" if method == "fd" else f"SPH, dD = {fluctuation} %"
        ax_value.plot(t, s, style, linewidth=0.8, label=label)
        ax_difference.plot(t, s - exact, style, linewidth=0.8, label=label)
    ax_value.set(xlabel="t [ms]", ylabel="S at the probe",
                 title="c = 135 m/s, the particle of the cell holding (0.3, 0.4) (paper's Fig. 7)")
    ax_difference.set(xlabel="t [ms]", ylabel="S - S_exact at the probe")
    for ax in (ax_value, ax_difference):
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)


def main():
    parser = parser_from_docstring(__doc__)
    parser.add_argument("--make-runs", action="store_true")
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--runs")
    parser.add_argument("--out")
    parser.add_argument("--tool", default=str(REPO / "build" / "bin" /
                                              "revsph_two_fluid_entropy_wave"))
    args = parser.parse_args()
    suffix = "_quick" if args.quick else ""
    runs = Path(args.runs or REPO / "out" / f"two_fluid_entropy_wave{suffix}")
    out = Path(args.out or (runs if args.quick else REPO / "docs" / "figures"))
    out.mkdir(parents=True, exist_ok=True)
    if args.make_runs:
        make_missing_runs(runs, Path(args.tool), 100 if args.quick else 400)
    missing = [run_name(*r) for r in RUNS if not (runs / (run_name(*r) + ".csv")).is_file()]
    if missing:
        print(f"missing runs {', '.join(missing)} in {runs} (use --make-runs)")
        return 1

    rows = [row for r in RUNS for row in read_rows(runs / (run_name(*r) + ".csv"))]
    with open(out / f"two_fluid_entropy_wave{suffix}.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)

    report = []
    fig, axes = plt.subplots(2, 2, figsize=(12, 8.5))
    for ax, speed in zip(axes[0], SPEEDS):
        error_panel(ax, rows, speed, report)
    probe_panels(axes[1, 0], axes[1, 1], runs)
    fig.suptitle(f"Entropy wave, mode (4, 3), {rows[0]['particles']}$^2$ particles, t = 0.03 s "
                 "(paper 5, sec. V.2)", fontsize=10)
    fig.tight_layout()
    fig.savefig(out / f"two_fluid_entropy_wave{suffix}.png", dpi=120)
    plt.close(fig)
    print("\n".join(report))
    print(f"wrote {out}/two_fluid_entropy_wave{suffix}.csv and .png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
