"""The lid-driven cavity against Ghia, Ghia & Shin (1982), shared by the models' cavity figures
(superfluid_cavity.py, two_fluid_cavity.py): the reference profiles, the centre-line velocities of
a particle state (Shepard averages, core's Wendland C2 kernel) and their L-infinity errors, and
the steps of their figures: measuring and drawing the runs, writing the figure, the table and the
report lines, and the main() of such a figure script."""

import csv
from typing import NamedTuple

import numpy as np

from revsph_runs import REPO, chosen_runs_main, read_csv, save_figure
from shtc_fluids import shepard

REFDATA = REPO.parent / "shared" / "refdata"


def ghia(re):
    u = read_csv(REFDATA / "ghia1982_u_vertical_centerline.csv")
    v = read_csv(REFDATA / "ghia1982_v_horizontal_centerline.csv")
    return u["y"], u[f"Re{re}"], v["x"], v[f"Re{re}"]


class CentreLines:
    """u on x = 1/2 and v on y = 1/2 of a state (positions, velocities of fluid and walls), and
    the largest distance from Ghia's points at Reynolds number `re`: everywhere (`error`) and
    at Ghia's points at least one support inside the cavity (`interior`)."""

    def __init__(self, position, velocity, support, re):
        self.position, self.velocity, self.support = position, velocity, support
        y_ref, u_ref, x_ref, v_ref = ghia(re)
        u_error = np.abs(self.u_at(y_ref) - u_ref)
        v_error = np.abs(self.v_at(x_ref) - v_ref)
        u_inside = (y_ref >= support) & (y_ref <= 1.0 - support)
        v_inside = (x_ref >= support) & (x_ref <= 1.0 - support)
        self.error = max(u_error.max(), v_error.max())
        self.interior = max(u_error[u_inside].max(), v_error[v_inside].max())

    def u_at(self, y):
        points = np.column_stack([np.full_like(y, 0.5), y])
        return shepard(points, self.position, self.velocity, self.support)[:, 0]

    def v_at(self, x):
        points = np.column_stack([x, np.full_like(x, 0.5)])
        return shepard(points, self.position, self.velocity, self.support)[:, 1]


def draw_ghia(u_axis, v_axis, re):
    """Ghia's points on a u(y) and a v(x) axis, labelled and with legends."""
    y_ref, u_ref, x_ref, v_ref = ghia(re)
    u_axis.plot(u_ref, y_ref, "ko", ms=3, mfc="none", label="Ghia et al. (1982)")
    v_axis.plot(x_ref, v_ref, "ko", ms=3, mfc="none", label="Ghia et al. (1982)")
    u_axis.set(xlabel="u on x = 1/2", ylabel="y", title=f"Re = {re}")
    v_axis.set(xlabel="x", ylabel="v on y = 1/2", title=f"Re = {re}")
    u_axis.legend(fontsize=7)
    v_axis.legend(fontsize=7)


class CavityResult(NamedTuple):
    """One run's L-infinity errors against Ghia at the end: everywhere (`error`) and away from
    the walls (`interior`), at `time`."""

    name: str
    re: int
    n: int
    error: float
    interior: float
    time: float


# The CSV column of each number of a CavityResult.
ERROR_COLUMNS = {"error": "linf_error", "interior": "linf_error_interior", "time": "time"}


def measure_runs(runs, names, final_state, run_of, profile_axes):
    """The runs' results, their u(y) and v(x) on the centre lines drawn on profile_axes[re]
    (a u and a v axis) with Ghia's points. final_state(run directory) gives the positions and
    velocities of fluid and walls and the time, run_of(name) the run's Re, N and kernel
    support (a length)."""
    line = np.linspace(0.0, 1.0, 101)
    results = []
    for name in names:
        re, n, support = run_of(name)
        position, velocity, time = final_state(runs / name)
        lines = CentreLines(position, velocity, support, re)
        results.append(CavityResult(name, re, n, lines.error, lines.interior, time))
        u_axis, v_axis = profile_axes[re]
        u_axis.plot(lines.u_at(line), line, label=f"N = {n}")
        v_axis.plot(line, lines.v_at(line), label=f"N = {n}")
    for re in sorted({r.re for r in results}):
        draw_ghia(*profile_axes[re], re)
    return results


def save_cavity_results(fig, out, stem, results, numbers, time_decimals, report):
    """Writes out/stem.png (fig) and out/stem.csv (run, Re, N, then the CavityResult fields
    `numbers` to 6 digits: each model keeps the column order its table has always had) and
    puts each run's errors, its time with `time_decimals` decimals, at the head of report."""
    fig.tight_layout()
    save_figure(fig, out / f"{stem}.png")
    with open(out / f"{stem}.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["run", "Re", "N", *(ERROR_COLUMNS[k] for k in numbers)])
        writer.writerows([r.name, r.re, r.n, *(f"{getattr(r, k):.6g}" for k in numbers)]
                         for r in results)
    report[:0] = [(f"{r.name}: L-infinity error against Ghia at t = {r.time:.{time_decimals}f} "
                   f"(away from the walls)", f"{r.error:.4f} ({r.interior:.4f})") for r in results]


def cavity_main(doc, default_runs, runs_table, command, draw_figure, stem, numbers, time_decimals):
    """main() of a model's cavity script: the options of chosen_runs_main (command(name): the
    revsph arguments of run `name`); draw_figure(runs, report, names) draws the chosen runs
    (with measure_runs) and returns the figure and the results, which save_cavity_results
    writes as out/stem.* with the table's `numbers` and the times' `time_decimals`."""

    def make_figures(runs, out, report, names):
        fig, results = draw_figure(runs, report, names)
        save_cavity_results(fig, out, stem, results, numbers, time_decimals, report)

    return chosen_runs_main(doc, default_runs, runs_table, command, make_figures, f"{stem}.md")
