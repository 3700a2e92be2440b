#!/usr/bin/python3
"""Paper 5's entropy-wave benchmark (Tsuzuki 2021, sec. V.2, Figs. 7-8): the wave equation on the
unit square, mode (4, 3), with the SPH Laplacian of App. A on a lattice whose particles are shifted
by dl in random directions; the relative error E_r at t = 0.03 s against the volume fluctuation
rate dD, for c = 135 and 20 m/s, and S at a probe particle against t.

Usage: /usr/bin/python3 tools/plots/two_fluid_entropy_wave.py [--make-runs] [--quick] [--runs DIR]
           [--out DIR] [--tool PATH] [--fits]

--make-runs runs the tool (default build/bin/revsph_two_fluid_entropy_wave) on one thread for
every run missing in RUNS (default out/two_fluid_entropy_wave, with --quick
out/two_fluid_entropy_wave_quick), each for c = 135 and 20 on 400 x 400 particles (--quick:
100 x 100): the sph Laplacian at dD = 0, 0.25, 0.5, 1, 1.5, 2, 3 % with the default kernel
(Wendland quintic, support 3 l, dt = 0.1 l / c) and with the short one near its stability limit
(support 2 l, dt = 0.9 l / c), the Brookshaw form at dD = 0 and 0.5 %, the 5-point finite
difference (no particle positions, so dD = 0 only); and at dD = 0.5 % the scan of support
(1.5, 2, 2.5, 3 l) and dt (up to the largest stable one) at c = 135, of support at c = 20.
56 runs, 13 min on one core; --quick about 15 s.
Writes into --out (default docs/figures; with --quick RUNS, and the names end in _quick):
  two_fluid_entropy_wave.csv  the summary rows of every run (columns: the tool's source,
                              tools/analysis/two_fluid_entropy_wave_main.cpp).
  two_fluid_entropy_wave.png  (a), (b) as the paper's Fig. 8: E_r against dD for c = 135 and 20,
                              both kernels, both denominators, with the least-squares fits
                              E_r = a + b dD^p over dD > 0 (printed), FD, Brookshaw and the
                              paper's value with a factor-2 bar. (c) as Fig. 7: S at the particle
                              of the lattice cell holding (0.3, 0.4) for c = 135, dD = 0.5 and
                              3 %, FD and the exact curve; (d) their differences from the exact
                              curve. (e) E_r at c = 135, dD = 0.5 % against dt for each support;
                              (f) E_r at c = 20 against the support.

--fits makes no runs and no figure: it reads --out's two_fluid_entropy_wave.csv and writes
two_fluid_entropy_wave_fits.csv there, the fit E_r = a + b dD^p over dD > 0 for each speed, kernel
(support, dt) and denominator (the fits the figure draws).

E_r = mean_i |S_i - S_a| / (|S_a| + 1) x 100; the paper prints |S_a + A| (zero where S_a = -1),
also reported ("|S_a + A|", open symbols).
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
# (method, c, dD, support / l, dt / (l / c)): the default sph (support 3 l, dt 0.1 l / c), the
# short kernel near its stability limit (support 2 l, dt 0.9 l / c; the smallest E_r at c = 135
# is at 0.95, panel e, where dD = 3 % is already unstable), Brookshaw, FD, and the scan of panels
# (e), (f) at dD = 0.5.
DEFAULT, SHORT = (3.0, 0.1), (2.0, 0.9)
# The last dt of each support is the largest stable one found (unstable by 0.72, 0.96, 1.15, 1.49
# at 400^2, c = 135, seed 1).
SCAN_STEPS = {1.5: (0.1, 0.4, 0.6, 0.7), 2.0: (0.1, 0.4, 0.6, 0.8, 0.9, 0.95),
              2.5: (0.1, 0.4, 0.8, 1.0, 1.14), 3.0: (0.1, 0.4, 0.8, 1.2, 1.4, 1.47)}
RUNS = ([("sph", c, d, *DEFAULT) for c in SPEEDS for d in FLUCTUATIONS]
        + [("sph", c, d, *SHORT) for c in SPEEDS for d in FLUCTUATIONS]
        + [("brookshaw", c, d, *DEFAULT) for c in SPEEDS for d in (0, 0.5)]
        + [("fd", c, 0, *DEFAULT) for c in SPEEDS]
        + [("sph", 135, 0.5, s, f) for s, steps in SCAN_STEPS.items() for f in steps]
        + [("sph", 20, 0.5, s, 0.1) for s in SCAN_STEPS])
RUNS = list(dict.fromkeys(RUNS))
PAPER = {135: 0.018, 20: 0.012}  # E_r [%] at dD = 0.5 (sec. V.2)


def run_name(method, speed, fluctuation, support=DEFAULT[0], dt_factor=DEFAULT[1]):
    tail = "" if (support, dt_factor) == DEFAULT else f"-s{support:g}-dt{dt_factor:g}"
    return f"{method}-c{speed}-dD{fluctuation}{tail}"


def make_missing_runs(runs, tool, particles):
    runs.mkdir(parents=True, exist_ok=True)
    environment = dict(os.environ, OMP_NUM_THREADS="1", OMP_WAIT_POLICY="passive")
    for run in RUNS:
        method, speed, fluctuation, support, dt_factor = run
        prefix = runs / run_name(*run)
        if (prefix.parent / (prefix.name + ".csv")).is_file():
            continue
        command = [str(tool), "--method", method, "--speed", str(speed), "--fluctuation",
                   str(fluctuation), "--support", str(support), "--dt-factor", str(dt_factor),
                   "--particles", str(particles), "--out", str(prefix)]
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


def write_fits(out, suffix):
    """The fits of E_r = a + b dD^p of the summary CSV in `out`, into a CSV beside it."""
    rows = read_rows(out / f"two_fluid_entropy_wave{suffix}.csv")
    fits = []
    for speed in SPEEDS:
        for support, dt_factor in (DEFAULT, SHORT):
            chosen = sorted((r for r in rows if r["method"] == "sph" and
                             int(float(r["speed"])) == speed and
                             float(r["support_over_l"]) == support and
                             # the tool rounds dt to whole steps to t_end: within 2 %
                             abs(float(r["dt"]) * speed * float(r["particles"]) / dt_factor - 1)
                             < 0.02),
                            key=lambda r: float(r["fluctuation"]))
            for column in ("mean_error_percent", "literal_error_percent"):
                fit = power_fit([float(r["fluctuation"]) for r in chosen],
                                [float(r[column]) for r in chosen])
                fits.append([speed, support, dt_factor, column, len(chosen)] +
                            (["nan"] * 3 if fit is None else [f"{v:.4g}" for v in fit]))
    with open(out / f"two_fluid_entropy_wave_fits{suffix}.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["speed", "support_over_l", "dt_over_l_per_c", "error", "points", "a",
                         "b", "p"])
        writer.writerows(fits)
    print("\n".join(",".join(str(v) for v in row) for row in fits))


def error_panel(ax, table, speed, report):
    def series(support_dt, method="sph", column="mean_error_percent"):
        runs = sorted((r for r in table if r[0] == method and r[1] == speed and
                       r[3:] == support_dt), key=lambda r: r[2])
        return (np.array([r[2] for r in runs]),
                np.array([float(table[r][column]) for r in runs]))

    for support_dt, colour, marker in ((DEFAULT, "tab:blue", "o"), (SHORT, "tab:green", "^")):
        label = f"SPH (App. A), support {support_dt[0]:g} l, dt {support_dt[1]:g} l/c"
        for column, fill, kind in (("mean_error_percent", colour, "E_r"),
                                   ("literal_error_percent", "none", "E_r, |S_a + A|")):
            d, error = series(support_dt, column=column)
            ax.semilogy(d, error, marker, color=colour, mfc=fill, label=f"{label}: {kind}")
            fit = power_fit(d, error)
            if fit is not None:
                line = np.linspace(0.0, d.max(), 200)
                ax.semilogy(line, fit[0] + fit[1] * line ** fit[2], "-" if fill != "none" else
                            ":", color=colour, linewidth=0.8)
                report.append(f"c = {speed}, {label}, {kind}: fit {fit[0]:.4g} + {fit[1]:.4g} "
                              f"dD^{fit[2]:.3f}")
            report.extend(f"c = {speed}, {label}, {kind}(dD = {v:g}) = {e:.4g} %"
                          for v, e in zip(d, error))
        d, off_mode = series(support_dt, column="off_mode_error_percent")
        report.append(f"c = {speed}, {label}: part outside the mode at dD = 0.5: "
                      f"{off_mode[d == 0.5][0]:.4g} %")
    _, fd = series(DEFAULT, "fd")
    _, fd_literal = series(DEFAULT, "fd", "literal_error_percent")
    ax.axhline(fd[0], color="k", linestyle="--", label=f"FD (5-point) {fd[0]:.3g} %")
    report.append(f"c = {speed}: fd E_r = {fd[0]:.4g} %, with |S_a + A| {fd_literal[0]:.4g} %")
    d, brookshaw = series(DEFAULT, "brookshaw")
    ax.semilogy(d, brookshaw, "s", color="tab:red", label="Brookshaw (eq. 14 x 2)")
    report.extend(f"c = {speed}: brookshaw E_r(dD = {v:g}) = {e:.4g} %"
                  for v, e in zip(d, brookshaw))
    paper = PAPER[speed]
    ax.errorbar([0.5], [paper], yerr=[[paper / 2], [paper]], fmt="*", color="k", markersize=10,
                capsize=3, label=f"paper {paper} % (bar: factor 2)")
    ax.set(xlabel="volume fluctuation rate dD [%]", ylabel="$E_r$ [%]",
           title=f"c = {speed} m/s (paper's Fig. 8{'a' if speed == 135 else 'b'})")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=6, loc="lower right")


def scan_panels(ax_dt, ax_support, table, report):
    """(e) E_r at c = 135, dD = 0.5 against dt per support, up to the last stable dt; (f) E_r at
    c = 20, dD = 0.5 against the support."""
    for support, steps in SCAN_STEPS.items():
        runs = [("sph", 135, 0.5, support, f) for f in steps]
        for column, fill in (("mean_error_percent", None), ("literal_error_percent", "none")):
            error = [float(table[r][column]) for r in runs]
            line, = ax_dt.semilogy(steps, error, "o-" if fill is None else "o:", mfc=fill,
                                   label=f"support {support:g} l" if fill is None else None)
            if fill is not None:
                line.set_color(ax_dt.lines[-2].get_color())
            report.append(f"c = 135, dD = 0.5, support {support:g} l, "
                          f"{'|S_a + A|' if fill else 'E_r'}: " +
                          ", ".join(f"dt {f:g}: {e:.4g}" for f, e in zip(steps, error)))
    ax_dt.axhspan(PAPER[135] / 2, PAPER[135] * 2, color="0.85", label="paper's 0.018 %, factor 2")
    ax_dt.set(xlabel="dt / (l / c) (last point: the largest stable one of the scan)",
              ylabel="$E_r$ [%] (filled: |S_a| + A; open: |S_a + A|)",
              title="c = 135, dD = 0.5 %: the leapfrog's lead against the Laplacian's lag")
    supports = list(SCAN_STEPS)
    for column, marker, kind in (("mean_error_percent", "o-", "|S_a| + A"),
                                 ("literal_error_percent", "s:", "|S_a + A| (as printed)")):
        error = [float(table[("sph", 20, 0.5, s, 0.1)][column]) for s in supports]
        ax_support.semilogy(supports, error, marker, label=f"E_r with {kind}")
        report.append(f"c = 20, dD = 0.5, dt 0.1, {kind}: " +
                      ", ".join(f"support {s:g}: {e:.4g}" for s, e in zip(supports, error)))
    ax_support.axhspan(PAPER[20] / 2, PAPER[20] * 2, color="0.85", label="paper's 0.012 %, factor 2")
    ax_support.set(xlabel="kernel support / l", ylabel="$E_r$ [%]",
                   title="c = 20, dD = 0.5 %, dt = 0.1 l / c")
    for ax in (ax_dt, ax_support):
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)


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
    parser.add_argument("--fits", action="store_true")
    args = parser.parse_args()
    suffix = "_quick" if args.quick else ""
    runs = Path(args.runs or REPO / "out" / f"two_fluid_entropy_wave{suffix}")
    out = Path(args.out or (runs if args.quick else REPO / "docs" / "figures"))
    out.mkdir(parents=True, exist_ok=True)
    if args.fits:
        write_fits(out, suffix)
        return 0
    if args.make_runs:
        make_missing_runs(runs, Path(args.tool), 100 if args.quick else 400)
    missing = [run_name(*r) for r in RUNS if not (runs / (run_name(*r) + ".csv")).is_file()]
    if missing:
        print(f"missing runs {', '.join(missing)} in {runs} (use --make-runs)")
        return 1

    table = {r: read_rows(runs / (run_name(*r) + ".csv"))[0] for r in RUNS}
    rows = list(table.values())
    with open(out / f"two_fluid_entropy_wave{suffix}.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)

    report = []
    fig, axes = plt.subplots(3, 2, figsize=(12, 13))
    for ax, speed in zip(axes[0], SPEEDS):
        error_panel(ax, table, speed, report)
    probe_panels(axes[1, 0], axes[1, 1], runs)
    scan_panels(axes[2, 0], axes[2, 1], table, report)
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
