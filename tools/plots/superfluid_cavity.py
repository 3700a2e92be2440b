#!/usr/bin/python3
"""The lid-driven cavity with the superfluid model's classical special case chi_s = 0 (paper 3
sec. III.A, Table I, Figs. 1-4) against Ghia, Ghia & Shin (1982): centre-line velocities at the
end (t = 40) and the L-infinity error against dr, with its regression slope (the paper: 0.998 at
Re = 100 and 1.189 at Re = 400).

Usage: /usr/bin/python3 tools/plots/superfluid_cavity.py [--make-runs] [--runs DIR] [--out DIR]
           [--revsph PATH] [--threads N] [--only NAME ...]

--make-runs runs models/superfluid/cases/superfluid-cavity-re100.toml with N = 20, 30, 40
(dr = 1 / N) at Re = 100 and 400 (mu = 1 / Re) into RUNS/NAME (default RUNS = out/superfluid);
a run takes about 4 N^2 / 1600 * 30 minutes on one thread (N = 40: half an hour).
Writes into --out (default docs/figures):
  superfluid_cavity.png  u on x = 1/2 and v on y = 1/2 against Ghia at each Re and N; the error
                         against dr (log-log) with the fitted slopes.
  superfluid_cavity.csv  run, Re, N, L-infinity error (the largest distance from Ghia's points).
  superfluid_cavity.md   the numbers (also printed).

The velocity at a point is the kernel-weighted (Shepard) average over the fluid and the walls
(walls with their own velocity), support 2h as in the model.
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
from revsph_runs import REPO, chosen_runs, figure_parser, figure_script_main, read_csv, save_figure, snapshots  # noqa: E402,E501
from shtc_fluids import shepard  # noqa: E402

CASE = REPO / "models" / "superfluid" / "cases" / "superfluid-cavity-re100.toml"
REFDATA = REPO.parent / "shared" / "refdata"
RUNS = {f"cavity-re{re}-n{n}": (re, n) for re in (100, 400) for n in (20, 30, 40)}


def command(re, n):
    top = 1.0 + 6.0 / n  # six layers of wall above the lid line: the support is 6 dr
    return ["run", str(CASE), "--set", f"discretisation.dr={1.0 / n!r}",
            "--set", f"particles[1].max=[1.0, {top!r}]", "--set", f"particles[2].max=[1.0, {top!r}]",
            "--set", f"physics.viscosity={1.0 / re!r}",
            "--set", "output.snapshot_every=1000000000"]


def final_state(run):
    with h5py.File(snapshots(run)[-1]) as f:
        fluid, wall = f["particles/fluid"], f["particles/wall"]
        position = np.concatenate([fluid["position"][...], wall["position"][...]])
        velocity = np.concatenate([fluid["mean_velocity"][...], wall["velocity"][...]])
        return position, velocity, float(f.attrs["time"])


def ghia(re):
    u = read_csv(REFDATA / "ghia1982_u_vertical_centerline.csv")
    v = read_csv(REFDATA / "ghia1982_v_horizontal_centerline.csv")
    return u["y"], u[f"Re{re}"], v["x"], v[f"Re{re}"]


def make_figures(runs, out, report, names):
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.4))
    rows = []
    for name in names:
        re, n = RUNS[name]
        position, velocity, time = final_state(runs / name)
        support = 6.0 / n
        y_ref, u_ref, x_ref, v_ref = ghia(re)
        u = shepard(np.column_stack([np.full_like(y_ref, 0.5), y_ref]), position, velocity,
                    support)[:, 0]
        v = shepard(np.column_stack([x_ref, np.full_like(x_ref, 0.5)]), position, velocity,
                    support)[:, 1]
        error = max(np.max(np.abs(u - u_ref)), np.max(np.abs(v - v_ref)))
        rows.append((name, re, n, error, time))
        axes[0].plot(u, y_ref, label=f"Re {re}, N = {n}")
        axes[1].plot(x_ref, v, label=f"Re {re}, N = {n}")
    for re in sorted({r[1] for r in rows}):
        y_ref, u_ref, x_ref, v_ref = ghia(re)
        axes[0].plot(u_ref, y_ref, "ko", ms=3, mfc="none")
        axes[1].plot(x_ref, v_ref, "ko", ms=3, mfc="none")
        pts = sorted((1.0 / r[2], r[3]) for r in rows if r[1] == re)
        axes[2].loglog([p[0] for p in pts], [p[1] for p in pts], "o-", label=f"Re {re}")
        if len(pts) >= 2:
            slope = np.polyfit(np.log([p[0] for p in pts]), np.log([p[1] for p in pts]), 1)[0]
            report.append((f"Re {re}: slope of the L-infinity error against dr (the paper: "
                           f"{'0.998' if re == 100 else '1.189'})", f"{slope:.3f}"))
    axes[0].set(xlabel="u on x = 1/2", ylabel="y")
    axes[1].set(xlabel="x", ylabel="v on y = 1/2")
    axes[2].set(xlabel="dr", ylabel="max |SPH - Ghia|")
    for ax in axes:
        ax.legend(fontsize=7)
    save_figure(fig, out / "superfluid_cavity.png")
    with open(out / "superfluid_cavity.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["run", "Re", "N", "linf_error", "time"])
        writer.writerows([r[0], r[1], r[2], f"{r[3]:.6g}", f"{r[4]:.6g}"] for r in rows)
    report[:0] = [(f"{r[0]}: L-infinity error against Ghia at t = {r[4]:.2f}", f"{r[3]:.4f}")
                  for r in rows]


def main():
    parser = figure_parser(__doc__, "out/superfluid", REPO / "docs" / "figures", RUNS)
    args = parser.parse_args()
    names = chosen_runs(parser, args, RUNS)
    return figure_script_main(
        args, {n: command(*RUNS[n]) for n in names},
        [(names, lambda runs, out, report: make_figures(runs, out, report, names))],
        "superfluid_cavity.md")


if __name__ == "__main__":
    sys.exit(main())
