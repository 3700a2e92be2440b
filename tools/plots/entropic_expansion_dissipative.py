#!/usr/bin/python3
"""Paper 4 §5.3 (Figs. 10-11): the non-adiabatic expansion, the adiabatic one's vessel and gas
with viscosity mu = 0.001 and heat conduction lambda_F = 0.1, at the paper's settings.

Usage: /usr/bin/python3 tools/plots/entropic_expansion_dissipative.py [--make-runs] [--runs DIR]
           [--out DIR] [--revsph PATH] [--threads N]

--make-runs runs the built-in case `expansion` with those settings and the midpoint splitting
(39 600 gas + 3 056 wall particles, dt = 1.27e-5, t = 15, 1 183 216 steps: about 5.5 h on 2
threads, so in practice segments chained with `revsph run --from`, docs/runs/
entropic-expansion-paper.md) into RUNS/expansion-nonadiabatic (default RUNS = out/entropic).
A run that has not reached t = 15 yet is plotted as far as it goes; segments that continue it
(`revsph run --from SNAPSHOT --out RUNS/expansion-nonadiabatic-2`, then -3, ...) are read in
order. Writes into --out (default docs/figures):
  entropic_expansion_dissipative.png      Fig. 10: the temperature of the particles at four
                                          times; Fig. 11: the relative energy error and the
                                          mass-mean temperature over time; the entropy gained
                                          against M c_V (gamma - 1) ln 2; the temperature along x.
  entropic_expansion_dissipative.csv      t, relative energy error, mass-mean T, kinetic energy,
                                          total entropy gained (per snapshot).
  entropic_expansion_dissipative.md       the measured numbers (also printed).

Checks (issue 16): the mass-mean temperature returns to T0 (the energy stays; the kinetic
energy of the jet turns into heat), the entropy gained against that of Joule's expansion of an
ideal gas into twice its volume, M c_V (gamma - 1) ln 2, and the largest relative energy error
(paper: +0.006 % at t = 15, first order in dt). Until conduction has evened out the
temperature the gas is short of that entropy by the entropy the equalisation at fixed density
would still make, sum_a m_a c_V ln(T_f / T_a) with T_f the mass-mean temperature: the report
gives both.
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from entropic_expansion import (  # noqa: E402
    draw_slice_temperatures, read_gas, snapshot_attribute, temperature_fields)
from revsph_runs import (  # noqa: E402
    REPO, case_of, figure_parser, figure_script_main, label_axes, read_csv, save_figure, snapshots,
    write_csv)

NAME = "expansion-nonadiabatic"
RUNS = {NAME: ["run", "expansion", "--set", "physics.viscosity=0.001", "--set",
               "physics.heat_conductivity=0.1", "--set", "step.splitting=midpoint"]}


def segments(runs):
    """The run and the segments that continue it (`revsph run --from ... --out NAME-2`, NAME-3,
    ...), in order."""
    found = [runs / NAME]
    while (runs / f"{NAME}-{len(found) + 1}").is_dir():
        found.append(runs / f"{NAME}-{len(found) + 1}")
    return found


def chained_csv(dirs, name):
    """A CSV of the segments in time order: each segment's rows after the last time before it."""
    columns = None
    for run in dirs:
        table = read_csv(run / name)
        if columns is None:
            columns = table
            continue
        later = table["time"] > columns["time"][-1]
        columns = {k: np.concatenate([columns[k], table[k][later]]) for k in columns}
    return columns


def make_figures(runs, out, report):
    dirs = segments(runs)
    case = case_of(dirs[0])
    gamma = case["physics"]["gamma"]
    c_v = case["physics"]["heat_capacity"]
    paths = []
    for path in (p for run in dirs for p in snapshots(run)):
        # a segment starts with the snapshot the previous one ended with
        if not paths or snapshot_attribute(path, "time") > snapshot_attribute(paths[-1], "time"):
            paths.append(path)
    first = read_gas(paths[0])
    mass = np.sum(first["m"])
    t0 = np.sum(first["m"] * first["T"]) / mass
    joule = mass * c_v * (gamma - 1.0) * np.log(2.0)
    energy = chained_csv(dirs, "energy.csv")
    # against the first segment's initial energy (a continued run measures from its own start)
    energy["relative_error"] = (energy["total"] - energy["total"][0]) / energy["total"][0]
    diagnostics = chained_csv(dirs, "diagnostics.csv")
    entropy0 = diagnostics["entropy"][0]

    fig = plt.figure(figsize=(15, 8.4))
    # Fig. 10: the temperature field at four times (or as far as the run has come)
    end = snapshot_attribute(paths[-1], "time")
    temperature_fields(fig, paths, [t for t in (0.5, 2.0, 5.0, 15.0) if t <= end + 0.5] or [end],
                       t0)

    # Fig. 11 (left): the relative energy error over time
    ax = fig.add_subplot(3, 2, 3)
    error = energy["relative_error"]
    ax.semilogy(energy["time"][1:], np.maximum(np.abs(error[1:]), 1e-12), lw=0.8,
                label=f"dt = {snapshot_attribute(paths[0], 'dt'):.3g} s, "
                f"{case.get('dissipation', {}).get('splitting', 'strang')}")
    ax.axhline(6e-5, color="grey", ls="--", lw=1, label="paper: 0.006 % at t = 15")
    label_axes(ax, "t (s)", "|E - E0| / E0")

    # Fig. 11 (right): the mass-mean temperature, and the entropy gained
    rows = []
    for path in paths:
        gas = read_gas(path)
        mean_t = np.sum(gas["m"] * gas["T"]) / mass
        k = int(np.argmin(abs(energy["time"] - gas["time"])))
        j = int(np.argmin(abs(diagnostics["time"] - gas["time"])))
        rows.append((gas["time"], mean_t, energy["kinetic"][k],
                     diagnostics["entropy"][j] - entropy0))
    rows = np.array(rows)
    ax = fig.add_subplot(3, 2, 4)
    ax.plot(rows[:, 0], rows[:, 1], "o-", ms=2, label="mass-mean T")
    ax.axhline(t0, color="grey", ls="--", lw=1, label="T0")
    ax.axhline(t0 * 2.0 ** (1.0 - gamma), color="k", ls=":", lw=1,
               label="T0 2^-(gamma-1): adiabatic, uniform fill")
    label_axes(ax, "t (s)", "T (K)")
    ax = fig.add_subplot(3, 2, 5)
    ax.plot(diagnostics["time"], (diagnostics["entropy"] - entropy0) / joule, "-",
            label="sum S - sum S(0)")
    ax.axhline(1.0, color="k", ls=":", lw=1, label="M c_V (gamma - 1) ln 2")
    label_axes(ax, "t (s)", "entropy gained / M c_V (gamma-1) ln 2")
    last = read_gas(paths[-1])
    draw_slice_temperatures(fig.add_subplot(3, 2, 6), last, y=t0, color="grey", ls="--", lw=1,
                            label="T0")
    save_figure(fig, out / "entropic_expansion_dissipative.png")

    end = rows[-1]
    final_t = np.sum(last["m"] * last["T"]) / mass
    equalisation = np.sum(last["m"] * c_v * np.log(final_t / last["T"]))
    left = last["x"][:, 0] < 1.0
    report += [
        ("run reached t", f"{end[0]:.4g} s (of 15), in {len(dirs)} segment(s)"),
        ("max |E - E0| / E0 so far", f"{np.max(np.abs(error)):.3g} (paper: 6e-5 at t = 15)"),
        ("E - E0 over E0 at the end", f"{error[-1]:.3g}"),
        ("T0 (mass mean at t = 0)", f"{t0:.6g}"),
        (f"mass-mean T at t = {end[0]:.4g} s", f"{end[1]:.6g} ({end[1] / t0 - 1.0:+.2e} of T0)"),
        ("kinetic energy left, per M c_V (K)", f"{end[2] / (mass * c_v):.3g}"),
        ("mass-mean T of the left and right box at the end",
         f"{np.sum((last['m'] * last['T'])[left]) / np.sum(last['m'][left]):.4g}, "
         f"{np.sum((last['m'] * last['T'])[~left]) / np.sum(last['m'][~left]):.4g}"),
        ("entropy gained, sum S - sum S(0)", f"{end[3]:.6g} J/K"),
        ("M c_V (gamma - 1) ln 2 (Joule)", f"{joule:.6g} J/K"),
        ("ratio", f"{end[3] / joule:.4f}"),
        ("entropy the equalisation of T at fixed density would add", f"{equalisation:.4g} J/K"),
        ("gained + equalisation, over Joule", f"{(end[3] + equalisation) / joule:.4f}"),
    ]
    write_csv(out / "entropic_expansion_dissipative.csv",
              {"time": rows[:, 0], "mass_mean_temperature": rows[:, 1],
               "kinetic_energy": rows[:, 2], "entropy_gained": rows[:, 3],
               "relative_energy_error": np.interp(rows[:, 0], energy["time"], error)})


def main():
    parser = figure_parser(__doc__, "out/entropic", REPO / "docs" / "figures")
    args = parser.parse_args()
    return figure_script_main(args, RUNS, [([NAME], make_figures)],
                              "entropic_expansion_dissipative.md")


if __name__ == "__main__":
    sys.exit(main())
