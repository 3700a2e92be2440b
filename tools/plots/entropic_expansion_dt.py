#!/usr/bin/python3
"""Paper 4 §4.6 (Fig. 9): the energy error of the adiabatic expansion against the time step for
the mass, entropic, direct and mixed particle volumes.

Usage: /usr/bin/python3 tools/plots/entropic_expansion_dt.py [--make-runs] [--runs DIR]
           [--out DIR] [--revsph PATH] [--threads N] [--set KEY=VALUE ...]

The one command: /usr/bin/python3 tools/plots/entropic_expansion_dt.py --make-runs --threads 1
(24 runs, 290 s of CPU on 1 thread, 5-10 minutes of wall time beside other jobs).

--make-runs runs the case of entropic_expansion_volumes.py (`expansion-small` at dr = 0.0125,
6 320 gas particles, p0 = 30) up to t = 0.1 at the Courant numbers 0.01, 0.005, ..., 0.0003125,
once per volume, into RUNS/VOLUME-cCOURANT (default RUNS = out/entropic/volumes-dt). Every run
writes its energy at the same times (every 5 steps at Courant 0.01: 109 outputs in the window).
The error is the one of the mass-volume Fig. 9 row of models/entropic/README.md: the rms and the
max, over the outputs with 0 < t <= 0.1, of energy.csv's relative_error |E - E0| / |E0|.
--set KEY=VALUE (repeatable) is passed to every run, e.g. with --set
"initial.temperature_gradient=[2.0, 0.0]" --runs out/entropic/volumes-dt-gradient --out
out/entropic/volumes-dt-gradient (see the next paragraph for why).

Noise floor: with equal particle masses (this lattice) the mass volume m_a / sum_b m_b W_ab and
the direct volume 1 / sum_b W_ab are the same number, so the mass and direct runs at one time
step differ only by rounding. The rms over the window of the difference of their signed errors
(E - E0) / |E0| is the part of an error that is not the time step's: differences between
volumes below it mean nothing. In this case every gas particle also has the same entropy S, so
the entropic volume S_a / sum_b S_b W_ab and the mixed one are that number too: all four runs
differ only by rounding. A temperature gradient gives the particles different entropies (equal
masses still), and the entropic and mixed volumes then differ from the mass volume.

Writes into --out (default docs/figures):
  entropic_volumes_dt.png  rms and max error against dt (log-log, one line per volume, a dt^2
                           guide) and the errors over time at the smallest step;
  entropic_volumes_dt.csv  volume, Courant number, dt, steps, rms and max error, wall seconds;
  entropic_volumes_dt.md   ratios per halving, the noise floor, wall times (also printed).
"""

import json
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from entropic_expansion_volumes import REFINED_CASE, VOLUMES  # noqa: E402
from revsph_runs import (  # noqa: E402
    REPO,
    figure_parser,
    figure_script_main,
    read_csv,
    save_figure,
)

COURANTS = [0.01 / 2**k for k in range(6)]
T_END = 0.1


def run_name(volume, courant):
    return f"{volume}-c{courant:g}"


def run_arguments(volume, courant, extra=()):
    # energy every 5 steps at Courant 0.01, scaled so that all runs sample the same times (the
    # Courant numbers differ by powers of 2, so the steps do too, exactly); snapshots only at the
    # start and the end
    every = round(5 * 0.01 / courant)
    return ["run", "expansion-small", *REFINED_CASE,
            "--set", f"physics.particle_volume={volume}",
            "--set", f"discretisation.courant_number={courant}",
            "--set", f"output.energy_every={every}",
            "--set", "output.snapshot_every=100000000", "--t-end", str(T_END),
            *[a for setting in extra for a in ("--set", setting)]]


def signed_error(run):
    """Times in (0, T_END] and (E - E0) / |E0| there. The run's last step passes T_END and is
    left out, so that every run has the same output times."""
    energy = read_csv(run / "energy.csv")
    t, total = energy["time"], energy["total"]
    inside = (t > 0.0) & (t <= T_END + 1e-12)
    return t[inside], (total[inside] - total[0]) / abs(total[0]), energy["relative_error"][inside]


def measure(runs):
    """{(volume, courant): row} with dt, steps, rms and max error, wall seconds."""
    table = {}
    for volume in VOLUMES:
        for courant in COURANTS:
            run = runs / run_name(volume, courant)
            summary = json.loads((run / "summary.json").read_text())
            t, _, error = signed_error(run)
            table[volume, courant] = {
                "dt": summary["dt"], "steps": summary["steps"], "samples": len(t),
                "rms": np.sqrt(np.mean(error**2)), "max": np.max(error),
                "wall": summary["wall_seconds"]}
    return table


def halvings(table, volume, key):
    """Each halving's factor and their geometric mean (4 for second order)."""
    values = np.array([table[volume, c][key] for c in COURANTS])
    factors = values[:-1] / values[1:]
    return factors, (values[0] / values[-1]) ** (1.0 / len(factors))


def noise_floor(runs, courant):
    """rms of the mass-direct difference of the signed errors, and of the mass error itself."""
    t_mass, mass, _ = signed_error(runs / run_name("mass", courant))
    t_direct, direct, _ = signed_error(runs / run_name("direct", courant))
    assert np.allclose(t_mass, t_direct, rtol=1e-12, atol=0.0), "output times differ"
    return np.sqrt(np.mean((mass - direct) ** 2)), np.sqrt(np.mean(mass**2))


def plot(runs, table, path):
    fig, axes = plt.subplots(1, 3, figsize=(16, 4.6))
    dts = {v: np.array([table[v, c]["dt"] for c in COURANTS]) for v in VOLUMES}
    for ax, key in zip(axes[:2], ["rms", "max"]):
        every = []
        for volume, marker in zip(VOLUMES, "osD^"):
            values = np.array([table[volume, c][key] for c in COURANTS])
            ax.loglog(dts[volume], values, marker + "-", ms=5, mfc="none", label=volume)
            every.append(np.log(values) - 2.0 * np.log(dts[volume]))
        # the guide's height is the mean of all points, so it shows the slope, not a fit
        guide = np.exp(np.mean(every)) * dts["mass"] ** 2
        ax.loglog(dts["mass"], guide, "k:", label="dt^2")
        ax.set_xlabel("dt (s)")
        ax.set_ylabel(f"{key} of |E - E0| / E0 over 0 < t <= {T_END:g}")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    ax = axes[2]
    finest = COURANTS[-1]
    for volume in VOLUMES:
        t, _, error = signed_error(runs / run_name(volume, finest))
        # dashed: direct lies on mass (the same volume for equal masses)
        ax.semilogy(t, np.maximum(error, 1e-18), "--" if volume == "direct" else "-", lw=0.9,
                    label=volume)
    t, mass, _ = signed_error(runs / run_name("mass", finest))
    direct = signed_error(runs / run_name("direct", finest))[1]
    ax.semilogy(t, np.maximum(np.abs(mass - direct), 1e-18), "k-", lw=0.8,
                label="|mass - direct| (rounding)")
    ax.set_title(f"Courant {finest:g} (dt = {table['mass', finest]['dt']:.3g} s)")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("|E - E0| / E0")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    save_figure(fig, path)


def write_table(path, table):
    # by hand, not revsph_runs.write_csv: the volume column is a name
    with open(path, "w") as f:
        f.write("volume,courant_number,dt,steps,rms_relative_error,max_relative_error,"
                "wall_seconds\n")
        for (volume, courant), row in table.items():
            f.write(f"{volume},{courant:g},{row['dt']:.10g},{row['steps']},{row['rms']:.6g},"
                    f"{row['max']:.6g},{row['wall']:.3f}\n")


def make_figures(runs, out, report):
    table = measure(runs)
    plot(runs, table, out / "entropic_volumes_dt.png")
    write_table(out / "entropic_volumes_dt.csv", table)
    report.append(("outputs in 0 < t <= 0.1 per run", f"{table['mass', COURANTS[0]]['samples']}"))
    for volume in VOLUMES:
        for key in ["rms", "max"]:
            values = ", ".join(f"{table[volume, c][key]:.3g}" for c in COURANTS)
            factors, mean = halvings(table, volume, key)
            report.append((f"{volume}: {key} at Courant {', '.join(f'{c:g}' for c in COURANTS)}",
                           values))
            report.append((f"{volume}: {key}, factor per halving (each; geometric mean)",
                           f"{', '.join(f'{f:.3g}' for f in factors)}; {mean:.3g}"))
    for courant in COURANTS:
        floor, mass = noise_floor(runs, courant)
        rms_direct = table["direct", courant]["rms"]
        report.append((f"Courant {courant:g}: rms of (E_mass - E_direct) / E0; rms error mass, "
                       "direct", f"{floor:.3g}; {mass:.4g}, {rms_direct:.4g}"))
    for volume in VOLUMES:
        wall = sum(table[volume, c]["wall"] for c in COURANTS)
        report.append((f"{volume}: wall seconds of its {len(COURANTS)} runs", f"{wall:.1f}"))
    report.append(("all runs: wall seconds", f"{sum(r['wall'] for r in table.values()):.1f}"))


def main():
    parser = figure_parser(__doc__)
    parser.set_defaults(runs="out/entropic/volumes-dt", out=str(REPO / "docs" / "figures"))
    parser.add_argument("--set", dest="settings", action="append", default=[])
    args = parser.parse_args()
    runs = {run_name(v, c): run_arguments(v, c, args.settings) for v in VOLUMES for c in COURANTS}
    return figure_script_main(args, runs, [(list(runs), make_figures)], "entropic_volumes_dt.md")


if __name__ == "__main__":
    sys.exit(main())
