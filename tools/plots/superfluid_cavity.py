#!/usr/bin/python3
"""The lid-driven cavity with the superfluid model's classical special case chi_s = 0 (paper 3
sec. III.A, Table I, Figs. 1-4) against Ghia, Ghia & Shin (1982): centre-line velocities at the
end (t = 40) and the L-infinity error against dr, with its regression slope (the paper: 0.998 at
Re = 100 and 1.189 at Re = 400).

Usage: /usr/bin/python3 tools/plots/superfluid_cavity.py [--make-runs] [--runs DIR] [--out DIR]
           [--revsph PATH] [--threads N] [--only NAME ...]

--make-runs runs models/superfluid/cases/superfluid-cavity-re100.toml with N = 20, 30, 40, 60,
80 (dr = 1 / N) at Re = 100 and 400 (mu = 1 / Re), the kernel's support 3 dr (Table I's h as the
authors' code uses it), and N = 20, 30, 40 with support 6 dr (eq. 17 as printed, runs NAME-2h),
into RUNS/NAME (default RUNS = out/superfluid); a run takes about (N / 40)^3 * 8 minutes on one
thread at support 3 dr, four times that at 6 dr.
Writes into --out (default docs/figures):
  superfluid_cavity.png  u on x = 1/2 and v on y = 1/2 against Ghia at each Re and N; the error
                         against dr (log-log) with the fitted slopes.
  superfluid_cavity.csv  run, Re, N, L-infinity error (the largest distance from Ghia's points).
  superfluid_cavity.md   the numbers (also printed).

The velocity at a point is the kernel-weighted (Shepard) average over the fluid and the walls
(walls with their own velocity), with the run's kernel.
"""

import sys
from pathlib import Path

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from cavity_ghia import cavity_main, measure_runs  # noqa: E402
from revsph_runs import REPO, snapshots  # noqa: E402

CASE = REPO / "models" / "superfluid" / "cases" / "superfluid-cavity-re100.toml"
# (Re, N, the kernel's support in dr): 3 dr is Table I's h as the authors' code uses it; the
# "-2h" runs take eq. (17) as printed (support 2h = 6 dr), with dt = h / (10 u1) either way.
RUNS = {f"cavity-re{re}-n{n}": (re, n, 3.0) for re in (100, 400) for n in (20, 30, 40, 60, 80)}
RUNS.update({f"cavity-re{re}-n{n}-2h": (re, n, 6.0) for re in (100, 400) for n in (20, 30, 40)})


def command(re, n, support=3.0):
    layers = int(np.ceil(support - 1e-9))  # wall layers at least as thick as the support
    top = 1.0 + layers / n
    return ["run", str(CASE), "--set", f"discretisation.dr={1.0 / n!r}",
            "--set", f"discretisation.support_radius_over_dr={support!r}",
            "--set", f"discretisation.courant_number={0.3 / support!r}",
            "--set", f"particles[1].layers={layers}",
            "--set", f"particles[1].max=[1.0, {top!r}]", "--set", f"particles[2].max=[1.0, {top!r}]",
            "--set", f"physics.viscosity={1.0 / re!r}",
            "--set", "output.snapshot_every=1000000000"]


def support_of(name):
    """Re, N and the kernel's support (a length) of run `name`."""
    re, n, support = RUNS[name]
    return re, n, support / n


def final_state(run):
    with h5py.File(snapshots(run)[-1]) as f:
        fluid, wall = f["particles/fluid"], f["particles/wall"]
        position = np.concatenate([fluid["position"][...], wall["position"][...]])
        velocity = np.concatenate([fluid["mean_velocity"][...], wall["velocity"][...]])
        return position, velocity, float(f.attrs["time"])


def draw_figure(runs, report, names):
    """The centre lines at Re = 100 (top) and 400 (bottom), and the error against dr with its
    fitted slopes (also into report); the figure and the results."""
    fig = plt.figure(figsize=(14, 8))
    grid = fig.add_gridspec(2, 3)
    profile_axes = {re: (fig.add_subplot(grid[row, 0]), fig.add_subplot(grid[row, 1]))
                    for row, re in enumerate((100, 400))}
    error_axis = fig.add_subplot(grid[:, 2])
    results = measure_runs(runs, names, final_state, support_of, profile_axes)
    for re in sorted({r.re for r in results}):
        pts = sorted((1.0 / r.n, r.error, r.interior) for r in results if r.re == re)
        line_of = error_axis.loglog([p[0] for p in pts], [p[1] for p in pts], "o-",
                                    label=f"Re {re}")
        error_axis.loglog([p[0] for p in pts], [p[2] for p in pts], "s--",
                          color=line_of[0].get_color(), label=f"Re {re}, away from the walls")
        if len(pts) >= 2:
            log_dr = np.log([p[0] for p in pts])
            slope = np.polyfit(log_dr, np.log([p[1] for p in pts]), 1)[0]
            inner = np.polyfit(log_dr, np.log([p[2] for p in pts]), 1)[0]
            report.append((f"Re {re}: slope of the L-infinity error against dr (the paper: "
                           f"{'0.998' if re == 100 else '1.189'})", f"{slope:.3f}"))
            report.append((f"Re {re}: the same away from the walls", f"{inner:.3f}"))
    error_axis.set(xlabel="dr", ylabel="max |SPH - Ghia| at Ghia's points")
    error_axis.legend(fontsize=7)
    return fig, results


def main():
    return cavity_main(__doc__, "out/superfluid", RUNS, lambda name: command(*RUNS[name]),
                       draw_figure, "superfluid_cavity", ("error", "time", "interior"), 2)


if __name__ == "__main__":
    sys.exit(main())
