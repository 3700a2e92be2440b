#!/usr/bin/python3
"""Paper 4's implicit volume (eq. 26, W V = 1) at a boundary: why the box stops and the
expansion cannot run (issue 30; models/entropic/README.md, "The implicit volume").

Usage: /usr/bin/python3 tools/plots/entropic_implicit_volume.py [--make-runs] [--runs DIR]
           [--out DIR] [--revsph PATH] [--threads N] [--only NAME ...]

The one command: /usr/bin/python3 tools/plots/entropic_implicit_volume.py --make-runs
--threads 1 (12 runs, about 3 minutes on one thread).

--make-runs runs into RUNS/NAME (default RUNS = out/entropic/implicit-volume):
  box-implicit-c{0.01,0.005,0.0025}  `box-small` (gas in a box of dummy particles that keep
                                     their lattice volume) with the implicit volume at three
                                     Courant numbers, to its stop;
  box-implicit-c0.01-end             the last 150 steps of the first, a snapshot every step;
  box-implicit-g0, box-mass-g0       no gravity (a uniform gas at rest on its lattice): the
                                     implicit and the mass volume;
  box-implicit-s{2.0,2.5}            the implicit box at a kernel support of 2 and 2.5 dr;
  expansion-implicit-s{2.0,2.5,3.0}  `expansion-small` (the walls not in the sums: the gas's
                                     edge is a free surface) with the implicit volume.
Runs stopped by the model's volume fault are the measurement (summary.json says where).

Writes into --out (default docs/figures):
  entropic_implicit_volume.png  (a) y / (p V) against the distance to the wall at t = 0, y the
                                implicit pressure weights of eq. (45b), W_gg y = p on the gas
                                (the dummies' y = 0: their volumes are held); (b) the kinetic
                                energy of the gas at rest without gravity, implicit against mass
                                volume; (c) the closest pair of gas particles in the last steps
                                before the box stops.
  entropic_implicit_volume.csv  run, stop step, stop time, completed.
  entropic_implicit_volume.md   the numbers (also printed).
"""

import csv
import json
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from revsph_runs import (  # noqa: E402
    case_of,
    chosen_runs,
    figure_parser,
    figure_script_main,
    label_axes,
    read_csv,
    save_figure,
    snapshots,
)
import h5py  # noqa: E402

IMPLICIT = ["--set", "physics.particle_volume=implicit"]
RUNS = {}
for _c in (0.01, 0.005, 0.0025):
    RUNS[f"box-implicit-c{_c}"] = ["run", "box-small", *IMPLICIT,
                                   "--set", f"discretisation.courant_number={_c}",
                                   "--set", "output.snapshot_every=200"]
# The 150 steps before the stop at Courant 0.01 (step 3 348), a snapshot each.
RUNS["box-implicit-c0.01-end"] = None  # its command needs --runs: set in main()
for _v in ("implicit", "mass"):
    RUNS[f"box-{_v}-g0"] = ["run", "box-small", "--set", f"physics.particle_volume={_v}",
                            "--set", "physics.gravity=0.0",
                            "--set", "discretisation.courant_number=0.01",
                            "--set", "output.energy_every=5", "--set", "run.t_end=8.0"]
for _s in (2.0, 2.5):
    RUNS[f"box-implicit-s{_s}"] = ["run", "box-small", *IMPLICIT,
                                   "--set", f"discretisation.support_radius_over_dr={_s}",
                                   "--set", "discretisation.courant_number=0.01"]
for _s in (2.0, 2.5, 3.0):
    RUNS[f"expansion-implicit-s{_s}"] = ["run", "expansion-small", *IMPLICIT,
                                         "--set", f"discretisation.support_radius_over_dr={_s}"]


def wendland(r, support):
    """The 2D Wendland quintic of core/kernel_wendland.hpp, support radius `support`."""
    q = r / support
    return np.where(q < 1.0, 7.0 / (np.pi * support**2) * (1.0 - q)**4 * (1.0 + 4.0 * q), 0.0)


def distances(a, b):
    return np.hypot(*(a[:, None, :] - b[None, :, :]).transpose(2, 0, 1))


def support_of(run):
    d = case_of(run)["discretisation"]
    return d["dr"] * d["support_radius_over_dr"], d["dr"]


def implicit_weights(run):
    """y = W_gg^-1 p at the first snapshot (the dummies' y is 0: their volumes are held), the
    distance of each gas particle to the box's wall, and W_gg's condition number."""
    support, _ = support_of(run)
    with h5py.File(snapshots(run)[0]) as f:
        xg = f["particles/gas/position"][:]
        p, volume = f["particles/gas/pressure"][:], f["particles/gas/volume"][:]
    w_gg = wendland(distances(xg, xg), support)
    y = np.linalg.solve(w_gg, p)
    wall = np.minimum(np.minimum(xg[:, 0], 1.0 - xg[:, 0]), np.minimum(xg[:, 1], 1.0 - xg[:, 1]))
    return wall, y / (p * volume), np.linalg.cond(w_gg)


def stop_of(run):
    summary = json.loads((run / "summary.json").read_text())
    return summary["final_step"], summary["time"], summary["completed"], summary["steps_requested"]


def closest_pairs(run, dr):
    """(step, closest gas-gas distance / dr, its pair) for each snapshot of the run."""
    rows = []
    for path in snapshots(run):
        with h5py.File(path) as f:
            x = f["particles/gas/position"][:]
            step = int(f.attrs["step"])
        d = distances(x, x) + np.eye(len(x)) * 1e9
        pair = np.unravel_index(np.argmin(d), d.shape)
        rows.append((step, d[pair] / dr, tuple(int(i) for i in pair)))
    return rows


def make_figures(runs, out, report, names):
    fig, axes = plt.subplots(1, 3, figsize=(16, 4.6))
    with open(out / "entropic_implicit_volume.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["run", "stop_step", "stop_time", "completed"])
        for name in names:
            step, time, completed, requested = stop_of(runs / name)
            writer.writerow([name, step, f"{time:.10g}", int(completed)])
            report.append((f"{name}: {'completed' if completed else 'stopped'}",
                           f"step {step} of {requested}, t = {time:.4g} s"))

    if "box-implicit-g0" in names:
        wall, ratio, condition = implicit_weights(runs / "box-implicit-g0")
        _, dr = support_of(runs / "box-implicit-g0")
        axes[0].plot(wall / dr, ratio, ".", markersize=4)
        label_axes(axes[0], "distance to the wall / dr", "y / (p V) at t = 0", legend=False)
        axes[0].set_title("(a) implicit pressure weights, W_gg y = p")
        report.append(("W_gg condition number at t = 0 (box, 3 dr)", f"{condition:.1f}"))
        for lo, hi in ((0, 1), (1, 2), (2, 3), (3, 6), (6, 12)):
            band = (wall >= lo * dr) & (wall < hi * dr)
            report.append((f"y / (p V) at t = 0, distance to the wall {lo}-{hi} dr",
                           f"{ratio[band].min():.3f} to {ratio[band].max():.3f}"))
    for volume in ("implicit", "mass"):
        name = f"box-{volume}-g0"
        if name not in names:
            continue
        energy = read_csv(runs / name / "energy.csv")
        t, kinetic = np.asarray(energy["time"]), np.asarray(energy["kinetic"])
        axes[1].semilogy(t[1:], kinetic[1:], label=f"{volume} volume")
        early = kinetic[t <= 0.05 + 1e-12][-1]
        report.append((f"{name}: kinetic energy at t = 0.05 s and its largest (J/m)",
                       f"{early:.3g}, {kinetic.max():.3g}"))
    label_axes(axes[1], "t (s)", "kinetic energy (J/m)")
    axes[1].set_title("(b) a gas at rest on its lattice, no gravity")

    if "box-implicit-c0.01-end" in names:
        _, dr = support_of(runs / "box-implicit-c0.01")
        rows = closest_pairs(runs / "box-implicit-c0.01-end", dr)
        axes[2].plot([r[0] for r in rows], [r[1] for r in rows], ".-")
        label_axes(axes[2], "step", "closest gas pair / dr", legend=False)
        axes[2].set_title("(c) before the stop at Courant 0.01")
        last = rows[-1]
        report.append(("closest gas pair in the last snapshot before the stop",
                       f"step {last[0]}: {last[1]:.3f} dr, particles {last[2]}"))
        report.append(("closest gas pair 150 steps earlier", f"{rows[0][1]:.3f} dr"))
    save_figure(fig, out / "entropic_implicit_volume.png")


def main():
    parser = figure_parser(__doc__, "out/entropic/implicit-volume",
                           Path(__file__).resolve().parents[2] / "docs" / "figures", RUNS)
    args = parser.parse_args()
    names = chosen_runs(parser, args, RUNS)
    commands = dict(RUNS)
    commands["box-implicit-c0.01-end"] = [
        "run", "--from", str(Path(args.runs) / "box-implicit-c0.01" / "snapshots" /
                             "step_000003200.h5"),
        "--steps", "150", "--set", "output.snapshot_every=1"]
    return figure_script_main(args, {n: commands[n] for n in names},
                              [(names, lambda runs, out, report: make_figures(runs, out, report,
                                                                              names))],
                              "entropic_implicit_volume.md", may_stop=set(RUNS))


if __name__ == "__main__":
    sys.exit(main())
