#!/usr/bin/python3
"""Resolution studies of paper 2's benchmarks (SHTC-SPH): how the beryllium plate's period, the
Taylor-Couette error and the cavity's error against Ghia change with dr. CSV + figures.

Usage: /usr/bin/python3 tools/plots/shtc_convergence.py [--runs DIR] [--out DIR] [--make-runs]
           [--revsph PATH] [--threads N] [--refdata DIR]

  --runs DIR   where the runs live, one subdirectory per run (default: out/shtc)
  --out DIR    where the CSV files and figures go (default: docs/figures/shtc)
  --make-runs  first make every missing run (present = its summary.json exists), printing each
               revsph command; about 3.5 h on 2 cores in all (plate W/80, cavity dr = 1/70 and
               plate W/60 twice are 45, 40 and 2 x 25 min of it, each on one core)
  --revsph     the revsph binary (default: build/bin/revsph, else build-*/bin/revsph)
  --threads N  passed to revsph (default: revsph's own, all cores)
  --refdata D  where the Ghia et al. (1982) CSV files are (default /work/shared/refdata)

Runs: the beryllium plate at dr = W/20, W/30, W/40 (the case), W/60 and W/80, each on the
isometric grid fitted to the plate (see plate_overrides), and at W/20 ... W/60 with a tenth of
eq. (56)'s amplitude (linear regime), and at W/30 at both amplitudes with the tensile penalty's
cp = 5 c0 and 2.5 c0 (paper: 10 c0); at W/20 with time-step factors 0.1, 0.025 and 0.0125 (eq. 58:
0.05); at W/40 with the paper's Cayley update of A (plate-cayley); Taylor-Couette at dr = 1/10, 1/20, 1/30 (matched splitting,
time-step factor 0.1); the cavity at Re 100 with dr = 1/20, 1/30, 1/50 (the case), 1/70
(matched splitting, factor 0.1). The runs the other two scripts share (beryllium-plate,
taylor-couette-coarse, taylor-couette, cavity-re100) have their names.

Writes:
  plate_convergence.csv/.png    fitted period of the centre point against dr, at both
                                amplitudes, with eq. (56)'s 2 pi / omega (and its 5 % band), the
                                Timoshenko beam of the model's moduli and the period of the
                                continuum model itself (finite elements, plate_fe.py); and, at
                                W/30, against the penalty's cp (plate_penalty.csv)
  plate_energy_error.csv/.png   the largest relative energy error over the run against the time
                                step (W/20) and against dr, and with the Cayley update (W/40)
  couette_convergence.csv/.png  paper 2 Fig. 10 (left): max |v_theta - eq. 64| on y = 0 at t = 10
  cavity_convergence.csv/.png   paper 2 Fig. 13 (left): L-inf error of u and v against Ghia at
                                Re 100, t = 10
  shtc_convergence.md           the numbers printed below, as a table
Exit status 0 only if every figure was made.
"""

import json
import math
import sys
from pathlib import Path

import plate_fe
import shtc_fluids
from revsph_runs import case_of, figure_parser, figure_script_main, save_figure, write_csv
from shtc_fluids import cavity_at_ghia_points, couette_on_segment, couette_ring_means
from shtc_solids import model_timoshenko, plate_period

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

DPI = 110
PLATE_LENGTH, PLATE_THICKNESS = plate_fe.LENGTH, plate_fe.THICKNESS


def plate_overrides(n):
    """--set overrides for the plate at dr = W/n on the isometric (triangular) grid fitted to the
    plate: a whole number of rows, round(W / row period), with the spacing stretched so that they
    fill W exactly and sit symmetrically about y = 0; even rows of N particles, odd rows N - 1
    (shifted half a spacing), N chosen so that the mean row, (N - 1/2) spacing, is nearest L. A
    lattice cut at the box instead loses a row when the row period does not divide W (W/40: 42
    rows of 2.33e-4 m for a thickness of 43 such rows, 2.3 % thinner and off-centre by 0.11 mm;
    the bending period goes as 1/W)."""
    dr = PLATE_THICKNESS / n
    row_period = dr * math.sqrt(2.0 / math.sqrt(3.0)) * math.sqrt(3.0) / 2.0
    rows = round(PLATE_THICKNESS / row_period)
    spacing = 2.0 * PLATE_THICKNESS / (rows * math.sqrt(3.0))
    columns = round(PLATE_LENGTH / spacing + 0.5)
    half_length = 0.5 * columns * spacing
    half_thickness = 0.5 * PLATE_THICKNESS
    return ["run", "beryllium-plate", "--set", f"discretisation.dr={dr!r}",
            "--set", f"particles[0].spacing={spacing!r}",
            "--set", f"particles[0].min=[{-half_length!r}, {-half_thickness!r}]",
            "--set", f"particles[0].max=[{half_length!r}, {half_thickness!r}]",
            "--set", "output.snapshot_every=100000"]


def couette_overrides(n):
    """Taylor-Couette at dr = 1/n: two wall rings inside R1 and outside R2."""
    dr = 1.0 / n
    return ["run", "taylor-couette", "--set", f"discretisation.dr={dr!r}",
            "--set", f"particles[1].inner_radius={1.0 - 2.0 * dr!r}",
            "--set", f"particles[2].outer_radius={2.0 + 2.0 * dr!r}"]


def cavity_overrides(n):
    """The Re 100 cavity at dr = 1/n: walls and lid two layers deep."""
    dr = 1.0 / n
    top = f"[1.0, {1.0 + 2.0 * dr!r}]"
    return ["run", "cavity-re100", "--set", f"discretisation.dr={dr!r}",
            "--set", f"particles[1].max={top}", "--set", f"particles[2].max={top}"]


PLATE = {"plate-w20": plate_overrides(20), "plate-w30": plate_overrides(30),
         "beryllium-plate": ["run", "beryllium-plate"], "plate-w60": plate_overrides(60),
         "plate-w80": plate_overrides(80)}
# The same at a tenth of eq. (56)'s amplitude: the paper's A bends the plate to a surface strain
# of 12 % (curvature A alpha^2 |mode''| = 25 /m at the centre), far from linear theory.
LINEAR_AMPLITUDE = ["--set", "initial.amplitude=4.3369e-6"]
PLATE_LINEAR = {"plate-linear-w20": plate_overrides(20) + LINEAR_AMPLITUDE,
                "plate-linear-w30": plate_overrides(30) + LINEAR_AMPLITUDE,
                "plate-linear-w40": plate_overrides(40) + LINEAR_AMPLITUDE,
                "plate-linear-w60": plate_overrides(60) + LINEAR_AMPLITUDE}
# The tensile penalty's share of the stiffness: the plate at W/30, at both amplitudes, with
# cp = 5 c0 and 2.5 c0 besides the paper's 10 c0 (without it, cp = 0, the plate clumps: no period
# to fit).
PENALTY_SPEEDS = {"cp5": "penalty.speed=45232.95", "cp2.5": "penalty.speed=22616.475"}
PLATE_PENALTY = {**{f"plate-w30-{key}": plate_overrides(30) + ["--set", value]
                    for key, value in PENALTY_SPEEDS.items()},
                 **{f"plate-linear-w30-{key}": plate_overrides(30) + LINEAR_AMPLITUDE +
                    ["--set", value] for key, value in PENALTY_SPEEDS.items()}}
# The energy error against the time step (W/20, time-step factors 0.1 ... 0.0125; plate-w20 is the
# paper's 0.05) and with the paper's Cayley update of A at the case's dr and dt.
PLATE_TIME_STEP = {f"plate-w20-dt{factor}": plate_overrides(20) +
                   ["--set", f"discretisation.time_step_factor={factor}"]
                   for factor in ("0.1", "0.025", "0.0125")}
PLATE_CAYLEY = {"plate-cayley": ["run", "beryllium-plate", "--set",
                                 "discretisation.distortion_update=cayley"]}
COUETTE = {"taylor-couette-dr10": couette_overrides(10),
           "taylor-couette-coarse": ["run", "taylor-couette-coarse"],
           "taylor-couette": ["run", "taylor-couette"]}
CAVITY = {"cavity-re100-dr20": cavity_overrides(20), "cavity-re100-dr30": cavity_overrides(30),
          "cavity-re100": ["run", "cavity-re100"], "cavity-re100-dr70": cavity_overrides(70)}
PLATE_ALL = {**PLATE, **PLATE_LINEAR, **PLATE_PENALTY}
PLATE_ENERGY = {**PLATE, **PLATE_LINEAR, **PLATE_TIME_STEP, **PLATE_CAYLEY}
RUNS = {**PLATE_ALL, **PLATE_TIME_STEP, **PLATE_CAYLEY, **COUETTE, **CAVITY}


def resolution_label(dr, unit):
    """'W/40' for the plate (unit "W", the thickness), '1/50' for the unit-sized fluid domains."""
    size = PLATE_THICKNESS if unit == "W" else 1.0
    return f"{unit}/{round(size / dr)}"


def plate_periods(runs, table):
    """(dr, fitted period, name) of each run of `table`, coarsest first."""
    rows = []
    for name in table:
        _, _, fitted, _ = plate_period(runs / name)
        rows.append((case_of(runs / name)["discretisation"]["dr"], 2.0 * math.pi / fitted, name))
    return sorted(rows, reverse=True)


def continuum_periods():
    """The plate's period in the continuum model itself (plate_fe.py: finite elements, Q2 24 x 4,
    converged to 0.01 % in mesh and time step there), at eq. (56)'s amplitude and a tenth of it."""
    periods = {}
    for fraction in (1.0, 0.1):
        t, y, _, _ = plate_fe.solve(24, 4, fraction * plate_fe.AMPLITUDE)
        periods[fraction] = plate_fe.period_of(t, y)[0]
    return periods


def plate_convergence(runs, out, report):
    case = case_of(runs / "beryllium-plate")
    linear = 2.0 * math.pi / case["initial"]["omega"]
    timoshenko = 2.0 * math.pi / model_timoshenko(case)
    continuum = continuum_periods()
    fig, (ax, penalty_ax) = plt.subplots(1, 2, figsize=(11, 4.5),
                                         gridspec_kw={"width_ratios": [1.6, 1]})
    columns = {}
    for (table, what, key), colour, fraction in zip(
            ((PLATE, "eq. (56)'s amplitude", "paper_amplitude"),
             (PLATE_LINEAR, "a tenth of it", "tenth_amplitude")), ("tab:blue", "tab:orange"),
            (1.0, 0.1)):
        rows = plate_periods(runs, table)
        dr = np.array([r[0] for r in rows])
        period = np.array([r[1] for r in rows])
        columns.update({f"{key}_W_over_dr": PLATE_THICKNESS / dr, f"{key}_period": period,
                        f"{key}_period_over_eq56": period / linear,
                        f"{key}_period_over_continuum": period / continuum[fraction]})
        report.append((f"plate, {what}: period of the continuum model (finite elements, "
                       "plate_fe.py), against eq. (56)",
                       f"{continuum[fraction]:.5e}, {continuum[fraction] / linear - 1:+.2%}"))
        for d, p, name in rows:
            report.append((f"plate, {what}, dr = {resolution_label(d, 'W')} ({name}): fitted "
                           "period (s), against eq. (56), the Timoshenko beam, the continuum "
                           "model", f"{p:.5e}, {p / linear - 1:+.2%}, {p / timoshenko - 1:+.2%}, "
                           f"{p / continuum[fraction] - 1:+.2%}"))
        ax.plot(PLATE_THICKNESS / dr, period * 1e6, "o-", color=colour, label=f"revsph, {what}")
        ax.axhline(continuum[fraction] * 1e6, color=colour, ls="--", lw=1,
                   label=f"continuum model (finite elements), {what}")
    longest = max(len(c) for c in columns.values())
    write_csv(out / "plate_convergence.csv",
              {k: np.pad(c, (0, longest - len(c)), constant_values=np.nan)
               for k, c in columns.items()})
    ax.axhline(linear * 1e6, color="k", lw=1, label="2 pi / omega, eq. (56)")
    ax.axhspan(linear * 0.95e6, linear * 1.05e6, color="k", alpha=0.08, label="eq. (56) ± 5 %")
    ax.axhline(timoshenko * 1e6, color="tab:green", ls="-.",
               label="Timoshenko beam, the model's moduli (plane strain)")
    ax.set_xlabel("W / dr")
    ax.set_ylabel("fitted period of the centre point (µs)")
    ax.set_title("Beryllium plate: period against resolution and amplitude")
    ax.legend(fontsize=7)
    # The tensile penalty stiffens the plate: period against cp at W/30, both amplitudes.
    penalty_columns = {}
    for stem, what, key, colour, fraction in (
            ("plate-w30", "eq. (56)'s amplitude", "paper_amplitude", "tab:blue", 1.0),
            ("plate-linear-w30", "a tenth of it", "tenth_amplitude", "tab:orange", 0.1)):
        speeds, periods = [], []
        for name in (f"{stem}-cp2.5", f"{stem}-cp5", stem):
            _, _, fitted, _ = plate_period(runs / name)
            speeds.append(case_of(runs / name)["penalty"]["speed"] /
                          case["material"]["sound_speed"])
            periods.append(2.0 * math.pi / fitted)
            report.append((f"plate, {what}, W/30, cp = {speeds[-1]:g} c0 ({name}): period, "
                           "against eq. (56), against the continuum model",
                           f"{periods[-1]:.5e}, {periods[-1] / linear - 1:+.2%}, "
                           f"{periods[-1] / continuum[fraction] - 1:+.2%}"))
        periods = np.array(periods)
        penalty_columns.update({f"{key}_cp_over_c0": np.array(speeds), f"{key}_period": periods,
                                f"{key}_period_over_continuum": periods / continuum[fraction]})
        penalty_ax.plot(speeds, periods * 1e6, "o-", color=colour, label=f"revsph W/30, {what}")
        penalty_ax.plot([0.0], [continuum[fraction] * 1e6], "s", color=colour, mfc="none",
                        label=f"continuum model, {what}")
    write_csv(out / "plate_penalty.csv", penalty_columns)
    penalty_ax.axhline(linear * 1e6, color="k", lw=1, label="2 pi / omega")
    penalty_ax.set_xlabel("tensile penalty speed cp / c0 (paper: 10)")
    penalty_ax.set_ylabel("fitted period of the centre point (µs)")
    penalty_ax.set_title("The penalty (eq. 39) stiffens the plate")
    penalty_ax.legend(fontsize=7)
    save_figure(fig, out / "plate_convergence.png", DPI)


def energy_error_of(run):
    return json.loads((run / "summary.json").read_text())["energy"]["max_relative_error"]


def plate_energy(runs, out, report):
    """The plate's largest relative energy error over t = 3e-5 s: against dt at W/20, against dr
    at eq. (58)'s dt, and with the paper's Cayley update of A at W/40."""
    time_step = []
    for name in ("plate-w20-dt0.1", "plate-w20", "plate-w20-dt0.025", "plate-w20-dt0.0125"):
        time_step.append((case_of(runs / name)["discretisation"]["time_step_factor"],
                          energy_error_of(runs / name), name))
    def against_dr(table):
        return sorted((PLATE_THICKNESS / case_of(runs / name)["discretisation"]["dr"],
                       energy_error_of(runs / name), name) for name in table)

    resolution, linear_resolution = against_dr(PLATE), against_dr(PLATE_LINEAR)
    for factor, error, name in time_step:
        report.append((f"plate W/20, dt = {factor} dr / sqrt(c0^2 + 4/3 cs^2) ({name}): "
                       "max relative energy error", f"{error:.3e}"))
    for rows, what in ((resolution, "eq. (56)'s amplitude"), (linear_resolution, "a tenth of it")):
        for n, error, name in rows:
            report.append((f"plate W/{n:.0f}, {what}, eq. (58)'s dt ({name}): max relative "
                           "energy error", f"{error:.3e}"))
    cayley = energy_error_of(runs / "plate-cayley")
    report.append(("plate W/40, the paper's Cayley update of A (plate-cayley): max relative "
                   "energy error; the exact update (beryllium-plate)",
                   f"{cayley:.3e}; {energy_error_of(runs / 'beryllium-plate'):.3e}"))
    factor, error = (np.array([r[k] for r in time_step]) for k in range(2))
    write_csv(out / "plate_energy_error.csv", {"time_step_factor_w20": factor,
                                               "max_relative_error_w20": error})
    fig, (dt_ax, dr_ax) = plt.subplots(1, 2, figsize=(10, 4))
    dt_ax.loglog(factor, error, "o-", label="revsph, W/20")
    dt_ax.loglog(factor, error[1] * (factor / factor[1]) ** 2, "k:", label="second order")
    dt_ax.set_xticks(factor, [f"{f:g}" for f in factor])
    dt_ax.minorticks_off()
    dt_ax.set_xlabel("time-step factor (eq. 58: 0.05)")
    dt_ax.set_ylabel("max |E(t) - E(0)| / E(0), t <= 3e-5 s")
    dt_ax.set_title("Energy error against dt")
    dt_ax.legend(fontsize=8)
    n, error = (np.array([r[k] for r in resolution]) for k in range(2))
    dr_ax.semilogy(n, error, "o-", label="revsph, eq. (56)'s amplitude")
    dr_ax.semilogy(*(np.array([r[k] for r in linear_resolution]) for k in range(2)), "o-",
                   label="revsph, a tenth of it")
    dr_ax.semilogy([40], [cayley], "s", mfc="none", label="the paper's Cayley update (eq. 49)")
    dr_ax.axhline(5e-6, color="k", lw=1, label="paper: within 5e-6 at W/40")
    dr_ax.set_xlabel("W / dr (dt of eq. 58)")
    dr_ax.set_title("Energy error against resolution")
    dr_ax.legend(fontsize=8)
    save_figure(fig, out / "plate_energy_error.png", DPI)


def error_figure(out, stem, dr, curves, title, ylabel):
    fig, ax = plt.subplots(figsize=(6, 4.2))
    for label, error in curves.items():
        ax.loglog(dr, error, "o-", label=label)
    reference = dr / dr[-1] * max(e[-1] for e in curves.values())
    ax.loglog(dr, reference, "k:", lw=1, label="first order")
    ax.set_xlabel("dr")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.legend(fontsize=8)
    save_figure(fig, out / f"{stem}.png", DPI)


def couette_convergence(runs, out, report):
    rows = []
    for name in COUETTE:
        dr = case_of(runs / name)["discretisation"]["dr"]
        r, tangential, exact, time = couette_on_segment(runs / name)
        error = np.abs(tangential - exact)
        _, means, ring_exact = couette_ring_means(runs / name)
        rows.append((dr, error.max(), error.mean(), np.abs(means - ring_exact).max(), time, name))
    rows.sort(reverse=True)
    dr, maximum, mean, ring = (np.array([r[k] for r in rows]) for k in range(4))
    write_csv(out / "couette_convergence.csv", {"dr": dr, "max_error": maximum,
                                                "mean_error": mean, "max_ring_mean_error": ring})
    for d, m, a, g, time, name in rows:
        report.append((f"Taylor-Couette dr = {resolution_label(d, '1')} ({name}), t = {time:.2f}: "
                       "max, mean |v_theta - eq. (64)| on y = 0; max over rings of the ring mean's "
                       "error", f"{m:.4f}, {a:.4f}; {g:.4f}"))
    error_figure(out, "couette_convergence", dr,
                 {"max on y = 0 (L-inf)": maximum, "mean on y = 0": mean,
                  "max of the ring means (systematic)": ring},
                 "Taylor-Couette, t = 10 (paper 2, Fig. 10 left)", "|v_theta - exact|")


def cavity_convergence(runs, out, report):
    rows = []
    for name in CAVITY:
        dr = case_of(runs / name)["discretisation"]["dr"]
        points = cavity_at_ghia_points(runs / name)
        rows.append((dr, np.abs(points["u"] - points["u_ghia"]).max(),
                     np.abs(points["v"] - points["v_ghia"]).max(), points["u"].min(),
                     points["time"], name))
    rows.sort(reverse=True)
    dr, u_error, v_error, u_min = (np.array([r[k] for r in rows]) for k in range(4))
    write_csv(out / "cavity_convergence.csv", {"dr": dr, "u_linf": u_error, "v_linf": v_error,
                                               "u_min_on_ghia_points": u_min})
    for d, u, v, low, time, name in rows:
        report.append((f"cavity Re 100 dr = {resolution_label(d, '1')} ({name}), t = {time:.2f}: "
                       "L-inf error of u, v at the 17 Ghia points; min u there (Ghia -0.2109)",
                       f"{u:.4f}, {v:.4f}; {low:.4f}"))
    error_figure(out, "cavity_convergence", dr, {"u on x = 1/2": u_error, "v on y = 1/2": v_error},
                 "Lid-driven cavity Re 100 (paper 2, Fig. 13 left)", "L-inf error against Ghia")


def main():
    parser = figure_parser(__doc__)
    parser.add_argument("--refdata", default=str(shtc_fluids.REFDATA))
    args = parser.parse_args()
    shtc_fluids.REFDATA = Path(args.refdata)
    return figure_script_main(
        args, RUNS,
        [(PLATE_ALL, plate_convergence), (PLATE_ENERGY, plate_energy),
         (COUETTE, couette_convergence),
         (CAVITY, cavity_convergence)],
        "shtc_convergence.md")


if __name__ == "__main__":
    sys.exit(main())
