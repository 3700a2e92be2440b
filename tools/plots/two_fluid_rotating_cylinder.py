"""The rotating cylinder with Tsuzuki's two-fluid model (paper 5 sec. V.3, Figs. 10-12): helium II
at 1.6 K spun up by its vessel turning at 5 rad/s; |v| against the radius at 0.5 s and 5 s, the
least-squares slope at 5 s against 5 rad/s, and the C_omega scan's two regimes.

Usage: /usr/bin/python3 tools/plots/two_fluid_rotating_cylinder.py [--make-runs] [--runs DIR]
           [--out DIR] [--revsph PATH] [--threads N] [--only NAME ...]

--make-runs runs models/two_fluid/cases/rotating-cylinder-small.toml (vessel diameter 0.2 mm,
32 particles across, about 800 fluid particles; 1.3 minutes per run on one thread) to t = 5 s
into RUNS/NAME (default RUNS = out/two_fluid):
  cylinder-c0.01            the case: C_omega = 0.01, Vinen's decay beta_v = 4.76e-9 m^2/s
  cylinder-c0.01-steady-l   beta_v = 0: the line density stays at L0 = 1e10 1/m^2
  cylinder-cSCAN            C_omega = 0, 0.005, 0.015, 0.02, 0.03, 0.05 (beta_v = 0)
  cylinder-paper            models/two_fluid/cases/rotating-cylinder.toml: the paper's vessel
                            (2 mm), 160 particles across, C_omega = 0.01, beta_v = 4.76e-9
                            (6 minutes on two threads)
Writes into --out (default docs/figures):
  two_fluid_rotating_cylinder.png  |v| against r at 0.5 s and 5 s (both beta_v); the scan:
                                   the normal fluid's departure from rigid rotation against
                                   C_omega; its velocity field at 5 s for C_omega = 0.01, 0.05
  two_fluid_rotating_cylinder.csv  run, C_omega, beta_v, t, kind, slope of |v| against r,
                                   rms departure from rigid rotation at that slope / (5 rad/s R)
  two_fluid_rotating_cylinder.md   the numbers (also printed)

The slope is the least-squares fit |v| = k r through the origin over every particle of a kind.
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
from revsph_runs import REPO, chosen_runs, figure_parser, figure_script_main, save_figure, snapshots  # noqa: E402,E501

CASE = REPO / "models" / "two_fluid" / "cases" / "rotating-cylinder-small.toml"
PAPER_CASE = REPO / "models" / "two_fluid" / "cases" / "rotating-cylinder.toml"
OMEGA = 5.0
RADIUS = {"small": 1.0e-4, "paper": 1.0e-3}
SCAN = (0.0, 0.005, 0.01, 0.015, 0.02, 0.03, 0.05)
RUNS = {"cylinder-c0.01": (0.01, 4.76e-9, "small"), "cylinder-c0.01-steady-l": (0.01, 0.0, "small"),
        "cylinder-paper": (0.01, 4.76e-9, "paper")}
RUNS.update({f"cylinder-c{c}": (c, 0.0, "small") for c in SCAN if c != 0.01})


def command(c_omega, vinen_beta, size):
    if size == "paper":
        return ["run", str(PAPER_CASE)]
    return ["run", str(CASE), "--set", "run.t_end=5.0", "--set", "output.snapshot_every=493",
            "--set", f"spin.coefficient={c_omega!r}",
            "--set", f"mutual_friction.vinen_beta={vinen_beta!r}"]


def state_at(run, time):
    """Positions and velocities of each kind at the snapshot nearest `time`."""
    best = None
    for path in snapshots(run):
        with h5py.File(path) as f:
            t = float(f.attrs["time"])
            if best is None or abs(t - time) < abs(best[0] - time):
                best = (t, path)
    with h5py.File(best[1]) as f:
        kinds = {}
        for kind in ("superfluid", "normal"):
            g = f[f"particles/{kind}"]
            kinds[kind] = (g["position"][...], g["momentum"][...] / g["mass"][...].reshape(-1, 1))
    return best[0], kinds


def rotation_measures(x, v, radius):
    r = np.hypot(x[:, 0], x[:, 1])
    speed = np.hypot(v[:, 0], v[:, 1])
    slope = np.sum(r * speed) / np.sum(r * r)
    rigid = slope * np.column_stack([-x[:, 1], x[:, 0]])
    departure = np.sqrt(np.mean(np.sum((v - rigid) ** 2, axis=1))) / (OMEGA * radius)
    return r, speed, slope, departure


def make_figures(runs, out, report, names):
    fig, axes = plt.subplots(2, 2, figsize=(11, 9))
    rows, scan = [], []
    for name in names:
        c_omega, beta, size = RUNS[name]
        for time in (0.5, 5.0):
            t, kinds = state_at(runs / name, time)
            for kind, (x, v) in kinds.items():
                r, speed, slope, departure = rotation_measures(x, v, RADIUS[size])
                rows.append((name, c_omega, beta, t, kind, slope, departure))
                if c_omega == 0.01:
                    axes[0, 0 if time == 0.5 else 1].plot(
                        r / RADIUS[size], speed / (OMEGA * RADIUS[size]), ".", ms=2,
                        label=f"{size}, {kind}, beta_v = {beta:g}: slope {slope:.2f} rad/s")
                if time == 5.0 and kind == "normal" and size == "small":
                    scan.append((c_omega, beta, departure, name))
        report.append((f"{name}: slope of |v| against r at 5 s, superfluid / normal (rad/s)",
                       " / ".join(f"{r[5]:.3f}" for r in rows[-2:])))
    for column, time in enumerate((0.5, 5.0)):
        axis = axes[0, column]
        axis.plot([0, 1], [0, 1], "k--", lw=1, label="rigid rotation at 5 rad/s")
        axis.set(xlabel="r / R", ylabel="|v| / (5 rad/s R)", title=f"C_omega = 0.01, t = {time} s")
        axis.legend(fontsize=7)
    steady = sorted((c, d) for c, b, d, _ in scan if b == 0.0)
    if steady:
        axes[1, 0].plot([s[0] for s in steady], [s[1] for s in steady], "o-")
    axes[1, 0].set(xlabel="C_omega", ylabel="rms |v - k z x r| / (5 rad/s R), normal fluid",
                   title="departure from rigid rotation at 5 s (beta_v = 0)")
    shown = ([n for n in names if RUNS[n][2] == "paper"] or
             [n for n in names if RUNS[n][:2] == (0.05, 0.0)])
    if shown:
        t, kinds = state_at(runs / shown[0], 5.0)
        x, v = kinds["normal"]
        _, _, slope, _ = rotation_measures(x, v, RADIUS[RUNS[shown[0]][2]])
        rigid = slope * np.column_stack([-x[:, 1], x[:, 0]])
        axes[1, 1].quiver(x[:, 0] * 1e3, x[:, 1] * 1e3, (v - rigid)[:, 0], (v - rigid)[:, 1])
        axes[1, 1].set(aspect="equal", xlabel="x (mm)", ylabel="y (mm)",
                       title=f"{shown[0]}: normal fluid's v minus rigid rotation, t = {t:.2f} s")
    fig.tight_layout()
    save_figure(fig, out / "two_fluid_rotating_cylinder.png")
    with open(out / "two_fluid_rotating_cylinder.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["run", "c_omega", "vinen_beta", "time", "kind", "slope", "departure"])
        writer.writerows([r[0], r[1], r[2], f"{r[3]:.6g}", r[4], f"{r[5]:.6g}", f"{r[6]:.6g}"]
                         for r in rows)
    for c, b, d, name in sorted(scan):
        report.append((f"{name}: normal fluid's rms departure from rigid rotation at 5 s",
                       f"{d:.4f}"))


def main():
    parser = figure_parser(__doc__, "out/two_fluid", REPO / "docs" / "figures", RUNS)
    args = parser.parse_args()
    names = chosen_runs(parser, args, RUNS)
    return figure_script_main(
        args, {n: command(*RUNS[n]) for n in names},
        [(names, lambda runs, out, report: make_figures(runs, out, report, names))],
        "two_fluid_rotating_cylinder.md")


if __name__ == "__main__":
    sys.exit(main())
