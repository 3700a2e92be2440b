#!/usr/bin/python3
"""Paper 4 §4.6 (Figs. 8-9): the adiabatic expansion with the mass, entropic, direct and mixed
particle volumes, their temperature profiles along the vessel compared.

Usage: /usr/bin/python3 tools/plots/entropic_expansion_volumes.py [--make-runs] [--runs DIR]
           [--out DIR] [--revsph PATH] [--threads N] [--times T ...] [--non-adiabatic]

--make-runs runs `expansion-small` refined to dr = 0.0125 (6 320 gas particles, Courant number
0.01, t = 15) once per volume into RUNS/mass, RUNS/entropic, RUNS/direct, RUNS/mixed (default
RUNS = out/entropic-volumes; about 3 minutes each on 1 thread). The entropic volume needs positive
particle entropies, so all four start at initial.pressure = 30 (sigma = c_V ln(30 / 10^1.4) =
0.18 > 0; at the case's p = 10 sigma is negative). For each of --times (default 1.5, 7.5, 15 s;
the nearest snapshot) the gas is cut into 10 slices along x and the mass-weighted mean
temperature of each slice compared, and so are the mean temperatures of the whole gas and of the
gas in each box. The slices of one run scatter by a few per cent about a smooth profile (the
particle noise of an expansion into vacuum without viscosity); the report gives that scatter of
the mass volume's profile (rms of its second differences / sqrt 6) as the scale to judge the
differences by. Writes into --out (default docs/figures):
  entropic_expansion_volumes.png  the profiles, one panel per time;
  entropic_expansion_volumes.csv  time, slice centre, mean T per volume;
  entropic_expansion_volumes.md   the largest difference from the mass volume, per volume and
                                  time, relative to the mean temperature (also printed).
--non-adiabatic does the same for §5.3's non-adiabatic expansion (Fig. 10's "quite similar
results" for the other volumes): the runs add the paper's viscosity 0.001 and conduction
lambda_F = 0.1 with the midpoint splitting (as entropic_expansion_dissipative.py), at p0 = 100
(below), for the mass, entropic and mixed volumes (about 13 min each on one thread), into
RUNS/VOLUME-nonadiabatic, and the files are entropic_expansion_volumes_nonadiabatic.*.
"""

import sys
from pathlib import Path

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from revsph_runs import (  # noqa: E402
    REPO,
    figure_parser,
    figure_script_main,
    save_figure,
    snapshots,
)

VOLUMES = ["mass", "entropic", "direct", "mixed"]
SLICES = np.linspace(0.0, 2.0, 11)
# expansion-small at dr = 0.0125: the gas block and the slit wall move with dr (README,
# "Expansion at lower resolution"). REFINED_CASE is the case alone, without output and end time,
# so that entropic_expansion_dt.py runs the same case.
REFINED_CASE = ["--set", "discretisation.dr=0.0125", "--set", "particles[0].max=[0.9875, 1.0]",
                "--set", "particles[2].min=[0.9875, 0.0]",
                "--set", "particles[2].max=[1.0125, 0.4]",
                "--set", "particles[3].min=[0.9875, 0.6]",
                "--set", "particles[3].max=[1.0125, 1.0]", "--set", "initial.pressure=30.0"]
REFINED = [*REFINED_CASE, "--set", "output.snapshot_every=1000", "--t-end", "15"]
RUNS = {v: ["run", "expansion-small", *REFINED, "--set", f"physics.particle_volume={v}"]
        for v in VOLUMES}
# §5.3: the same with the paper's viscosity and heat conduction, at p0 = 100 (sigma0 = 1.38): at
# p0 = 30 (sigma0 = 0.18) conduction drives a particle's entropy towards zero within 1 000 steps
# (2.8e-4 -> 1.8e-7 by step 1 000) and the entropic volume V = S / s breaks down at step 1 018.
DISSIPATION = ["--set", "physics.viscosity=0.001", "--set", "physics.heat_conductivity=0.1",
               "--set", "step.splitting=midpoint", "--set", "initial.pressure=100.0"]
# The paper's Fig. 10 remark names the entropic and mixed volumes; direct is left out here.
NON_ADIABATIC_VOLUMES = ["mass", "entropic", "mixed"]
NON_ADIABATIC = {f"{v}-nonadiabatic": [*RUNS[v], *DISSIPATION] for v in NON_ADIABATIC_VOLUMES}


def profile(path):
    with h5py.File(path) as f:
        gas = f["particles/gas"]
        x = gas["position"][:, 0]
        temperature = gas["temperature"][:]
        mass = gas["density"][:] * gas["volume"][:]
        time = float(f.attrs["time"])
    which = np.digitize(x, SLICES) - 1
    means = np.full(len(SLICES) - 1, np.nan)
    for k in range(len(means)):
        inside = which == k
        if inside.any():
            means[k] = np.sum(mass[inside] * temperature[inside]) / np.sum(mass[inside])
    boxes = [np.sum((mass * temperature)[part]) / np.sum(mass[part])
             for part in (x < 1.0, x >= 1.0, x == x)]
    return time, means, boxes


def nearest(run, time):
    best = None
    for path in snapshots(run):
        with h5py.File(path) as f:
            t = float(f.attrs["time"])
        if best is None or abs(t - time) < abs(best[0] - time):
            best = (t, path)
    return best[1]


def make_figures(runs, out, report, times, suffix="", volumes=VOLUMES):
    centres = 0.5 * (SLICES[1:] + SLICES[:-1])
    fig, axes = plt.subplots(1, len(times), figsize=(5.2 * len(times), 4.2), sharey=True)
    rows = []
    for ax, wanted in zip(np.atleast_1d(axes), times):
        profiles = {v: profile(nearest(runs / (v + suffix), wanted)) for v in volumes}
        time = profiles["mass"][0]
        for volume in volumes:
            ax.plot(centres, profiles[volume][1], ".-", label=volume)
        ax.set_title(f"t = {time:.2f} s")
        ax.set_xlabel("x (m)")
        ax.grid(True, alpha=0.3)
        reference = profiles["mass"][1]
        scale = np.nanmean(reference)
        scatter = np.sqrt(np.nanmean(np.diff(reference, 2) ** 2) / 6.0) / scale
        report.append((f"t = {time:.2f} s: slice-to-slice scatter of T_mass / mean T",
                       f"{scatter:.3g}"))
        for volume in volumes:
            left, right, whole = profiles[volume][2]
            report.append((f"t = {time:.2f} s: {volume}: mean T of the gas (left box, right box)",
                           f"{whole:.5g} ({left:.5g}, {right:.5g})"))
        for volume in volumes[1:]:
            difference = np.nanmax(np.abs(profiles[volume][1] - reference)) / scale
            report.append((f"t = {time:.2f} s: max |T_{volume} - T_mass| / mean T",
                           f"{difference:.3g}"))
        for k, c in enumerate(centres):
            rows.append([time, c] + [profiles[v][1][k] for v in volumes])
    np.atleast_1d(axes)[0].set_ylabel("mass-weighted mean T of the slice (K)")
    np.atleast_1d(axes)[0].legend()
    name = "entropic_expansion_volumes" + suffix.replace("-", "_")
    save_figure(fig, out / f"{name}.png")
    with open(out / f"{name}.csv", "w") as f:
        f.write("time,x," + ",".join(f"temperature_{v}" for v in volumes) + "\n")
        for row in rows:
            f.write(",".join(f"{v:.8g}" for v in row) + "\n")


def main():
    parser = figure_parser(__doc__)
    parser.set_defaults(runs="out/entropic-volumes", out=str(REPO / "docs" / "figures"))
    parser.add_argument("--times", type=float, nargs="*", default=[1.5, 7.5, 15.0])
    parser.add_argument("--non-adiabatic", action="store_true")
    args = parser.parse_args()
    suffix = "-nonadiabatic" if args.non_adiabatic else ""
    runs = NON_ADIABATIC if args.non_adiabatic else RUNS
    volumes = NON_ADIABATIC_VOLUMES if args.non_adiabatic else VOLUMES
    return figure_script_main(
        args, runs,
        [(list(runs), lambda r, out, report: make_figures(r, out, report, args.times, suffix,
                                                          volumes))],
        f"entropic_expansion_volumes{suffix.replace('-', '_')}.md")


if __name__ == "__main__":
    sys.exit(main())
