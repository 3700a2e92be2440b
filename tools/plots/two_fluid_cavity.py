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


def support_of(name):
    """Re, N and the kernel's support (a length: 3 dr, as in the case) of run `name`."""
    re, n = RUNS[name]
    return re, n, 3.0 / n


def draw_figure(runs, report, names):
    """The centre lines at Re = 100 (top) and 1000 (bottom); the figure and the results."""
    fig, axes = plt.subplots(2, 2, figsize=(10, 8))
    return fig, measure_runs(runs, names, final_state, support_of, {100: axes[0], 1000: axes[1]})


def main():
    return cavity_main(__doc__, "out/two_fluid", RUNS, lambda name: command(*RUNS[name]),
                       draw_figure, "two_fluid_cavity", ("error", "interior", "time"), 1)


if __name__ == "__main__":
    sys.exit(main())
