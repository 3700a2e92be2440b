#!/usr/bin/python3
"""The viscous-fluid benchmarks of paper 2 (SHTC-SPH, §4.3-4.4) from revsph runs: CSV + figures.

Usage: /usr/bin/python3 tools/plots/shtc_fluids.py [--runs DIR] [--out DIR] [--make-runs]
           [--revsph PATH] [--threads N] [--refdata DIR]

  --runs DIR   where the runs live, one subdirectory per run (default: out/shtc)
  --out DIR    where the CSV files and figures go (default: docs/figures/shtc)
  --make-runs  first make every missing run (present = its summary.json exists), printing each
               revsph command; about 2 h 30 min on 2 cores in all
  --revsph     the revsph binary (default: build/bin/revsph, else build-*/bin/revsph)
  --threads N  passed to revsph (default: revsph's own, all cores)
  --refdata D  where ghia1982_u_vertical_centerline.csv and ghia1982_v_horizontal_centerline.csv
               are (default /work/shared/refdata)

Runs (models/shtc/README.md explains the relaxation splittings): taylor-couette-coarse (dr =
1/20) and taylor-couette (dr = 1/30), matched splitting; taylor-couette-step-ends (dr = 1/20,
relaxation at the step ends); taylor-couette-paper (dr = 1/20, the paper's splitting and dt of
eq. 58); taylor-couette-mirrored (dr = 1/20, mirrored walls); cavity-re100, cavity-re400,
cavity-re1000 (dr = 1/50, matched splitting); cavity-re100-step-ends (dr = 1/50, relaxation at
the step ends, dt / tau = 0.3); cavity-re100-mirrored and cavity-re400-mirrored (dr = 1/50,
mirrored walls).

Writes:
  couette_profile.csv/.png   Fig. 8: tangential velocity against r at t = 10 of the particles on
                             the segment y = 0, 1 <= x <= 2 (|y| < dr / 2), with the exact
                             profile of eq. (64); right: v - omega r, as the paper's right panel
  couette_energy.csv/.png    Fig. 10 (right): energies over the final total, and the budget
                             E(t) - E(0) against the work of the wall (taylor-couette-step-ends)
  cavity_centrelines.csv/.png  Fig. 14: u on x = 1/2 and v on y = 1/2 at the end of each cavity
                             run (kernel-weighted average of the particles, walls included with
                             the velocity they pretend), with Ghia et al. (1982)
  cavity_energy.png          Fig. 13 (right): the cavity energies over the final total
  shtc_fluids.md             the numbers printed below, as a table
Exit status 0 only if every figure was made.
"""

import functools
import sys
from pathlib import Path

from revsph_runs import (case_of, figure_parser, figure_script_main, read_csv, save_figure, snapshots,
                         write_csv)

import matplotlib

matplotlib.use("Agg")
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

DPI = 110
REFDATA = Path("/work/shared/refdata")
COUETTE = {
    "taylor-couette-coarse": ["run", "taylor-couette-coarse"],
    "taylor-couette": ["run", "taylor-couette"],
    "taylor-couette-step-ends": ["run", "taylor-couette-coarse", "--set",
                                 "step.splitting=\"strang\""],
    "taylor-couette-paper": ["run", "taylor-couette-coarse", "--set",
                             "material.relaxation_rate=\"paper\"", "--set",
                             "discretisation.time_step_factor=0.05"],
    "taylor-couette-mirrored": ["run", "taylor-couette-coarse", "--set",
                                "walls.no_slip=\"mirrored\""],
    # The relaxation between the halves of the distortion update, matched rate (relaxation.hpp).
    "taylor-couette-midpoint": ["run", "taylor-couette-coarse", "--set",
                                "step.splitting=\"midpoint\""],
}
CAVITY = {
    "cavity-re100": ["run", "cavity-re100"],
    "cavity-re400": ["run", "cavity-re400"],
    "cavity-re1000": ["run", "cavity-re1000"],
    # dt / tau = 0.3 (the matched rate at the step's ends needs < 1/3): factor = 0.3 tau
    # sqrt(c0^2 + 4/3 cs^2) / dr
    "cavity-re100-step-ends": ["run", "cavity-re100", "--set", "step.splitting=\"strang\"", "--set",
                               "discretisation.time_step_factor=0.068738"],
    "cavity-re100-mirrored": ["run", "cavity-re100", "--set", "walls.no_slip=\"mirrored\""],
    "cavity-re400-mirrored": ["run", "cavity-re400", "--set", "walls.no_slip=\"mirrored\""],
}
RUNS = {**COUETTE, **CAVITY}


def run_variant(case):
    """The relaxation splitting of a run and, if not the paper's, its walls: "step_ends" for the
    strang placement, else the rate ("paper", "matched"); runs made before step.splitting name
    it in material.relaxation_splitting."""
    material = case["material"]
    if "relaxation_splitting" in material:
        variant = material["relaxation_splitting"]
    elif case.get("step", {}).get("splitting", "after_centre") == "strang":
        variant = "step_ends"
    elif case.get("step", {}).get("splitting", "after_centre") != "after_centre":
        variant = case["step"]["splitting"]
    else:
        variant = material.get("relaxation_rate", "paper")
    variant += " splitting"
    if case.get("walls", {}).get("no_slip", "pretended") != "pretended":
        variant += ", " + case["walls"]["no_slip"] + " walls"
    return variant


@functools.cache
def final_state(run):
    """Positions and velocities of all carriers at the last snapshot (walls: their pretended
    velocity), the material count and the time. Read once per run: the profile, ring means and
    convergence figures all use it (callers must not modify the arrays)."""
    with h5py.File(snapshots(run)[-1]) as f:
        material = f["particles/material"]
        position = [material["position"][...]]
        velocity = [material["velocity"][...]]
        count = len(position[0])
        if "particles/boundary/position" in f:
            boundary = f["particles/boundary"]
            position.append(boundary["position"][...])
            velocity.append(boundary["velocity"][...] if "velocity" in boundary
                            else np.zeros_like(boundary["position"][...]))
        time = float(f.attrs["time"])
    return np.concatenate(position), np.concatenate(velocity), count, time


def shepard(points, position, values, support):
    """Kernel-weighted average (Wendland C2, the model's kernel) of `values` at `points`."""
    out = np.empty((len(points), values.shape[1]))
    for i, p in enumerate(points):
        q = np.hypot(*(position - p).T) / (0.5 * support)
        w = np.where(q < 2.0, (1.0 - 0.5 * q) ** 4 * (2.0 * q + 1.0), 0.0)
        out[i] = w @ values / w.sum()
    return out


def couette_exact(r, r1, r2, omega):
    return omega * r2 * r2 / (r2 * r2 - r1 * r1) * (r - r1 * r1 / r)  # eq. (64)


def couette_on_segment(run, r1=1.0, r2=2.0, omega=1.0):
    """At the last snapshot: radius and tangential velocity of the material particles on the
    segment y = 0, x > 0 (|y| < dr / 2), sorted by radius; the exact profile there; the time."""
    dr = case_of(run)["discretisation"]["dr"]
    position, velocity, count, time = final_state(run)
    x, v = position[:count], velocity[:count]
    on_segment = (np.abs(x[:, 1]) < 0.5 * dr) & (x[:, 0] > 0)
    r = np.hypot(x[on_segment, 0], x[on_segment, 1])
    order = np.argsort(r)
    tangential = ((x[on_segment, 0] * v[on_segment, 1] - x[on_segment, 1] * v[on_segment, 0])
                  / r)[order]
    r = r[order]
    return r, tangential, couette_exact(r, r1, r2, omega), time


def couette_ring_means(run, r1=1.0, r2=2.0, omega=1.0):
    """The flow is axisymmetric: the tangential velocity averaged over every material particle in
    rings of width dr (centres, means, exact profile there), which separates the systematic error
    from the particles' scatter."""
    dr = case_of(run)["discretisation"]["dr"]
    position, velocity, count, _ = final_state(run)
    x, v = position[:count], velocity[:count]
    r = np.hypot(x[:, 0], x[:, 1])
    tangential = (x[:, 0] * v[:, 1] - x[:, 1] * v[:, 0]) / r
    edges = np.arange(r1, r2 + 0.5 * dr, dr)
    ring = np.digitize(r, edges) - 1
    inside = (ring >= 0) & (ring < len(edges) - 1)
    centres = 0.5 * (edges[1:] + edges[:-1])
    means = np.array([tangential[inside & (ring == k)].mean() for k in range(len(centres))])
    return centres, means, couette_exact(centres, r1, r2, omega)


def couette_figures(runs, out, report):
    r1, r2, omega = 1.0, 2.0, 1.0
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    radius = np.linspace(r1, r2, 101)
    left.plot(radius, couette_exact(radius, r1, r2, omega), "k-", lw=1, label="exact, eq. (64)")
    right.plot(radius, couette_exact(radius, r1, r2, omega) - omega * radius, "k-", lw=1)
    columns = {}
    for name in COUETTE:
        run = runs / name
        case = case_of(run)
        dr = case["discretisation"]["dr"]
        r, tangential, exact, time = couette_on_segment(run)
        error = tangential - exact
        position, velocity, count, _ = final_state(run)
        x, v = position[:count], velocity[:count]
        radius_all = np.hypot(x[:, 0], x[:, 1])
        tangential_all = (x[:, 0] * v[:, 1] - x[:, 1] * v[:, 0]) / radius_all
        error_all = tangential_all - couette_exact(radius_all, r1, r2, omega)
        label = f"dr = 1/{round(1 / dr)}, {run_variant(case)}"
        left.plot(r, tangential, "o", ms=3, label=label)
        right.plot(r, tangential - omega * r, "o-", ms=3, lw=0.8, label=label)
        columns[f"{name}_r"] = r
        columns[f"{name}_v_theta"] = tangential
        report.append((f"Taylor-Couette {name} ({label}), t = {time:.3f}: max |v - exact| on "
                       f"y = 0 ({len(r)} particles); mean", f"{np.max(np.abs(error)):.4f}; "
                       f"{np.mean(np.abs(error)):.4f}"))
        report.append((f"Taylor-Couette {name}: max |v - exact| over all {count} particles "
                       "(the flow is axisymmetric)", f"{np.max(np.abs(error_all)):.4f}"))
        centres, means, exact = couette_ring_means(run)
        report.append((f"Taylor-Couette {name}: max |ring mean of v - exact| over rings of width "
                       "dr (the systematic error); at the innermost ring",
                       f"{np.max(np.abs(means - exact)):.4f}; {means[0] - exact[0]:+.4f}"))
    longest = max(len(c) for c in columns.values())
    write_csv(out / "couette_profile.csv",
              {k: np.pad(c, (0, longest - len(c)), constant_values=np.nan)
               for k, c in columns.items()})
    left.set_xlabel("r = x on y = 0")
    left.set_ylabel("tangential velocity v_y")
    left.set_title("Taylor-Couette at t = 10 (paper 2, Fig. 8)")
    left.legend(fontsize=8)
    right.set_xlabel("r")
    right.set_ylabel("v_y - omega r")
    right.legend(fontsize=8)
    save_figure(fig, out / "couette_profile.png", DPI)
    budget_figure(runs / "taylor-couette-step-ends", out / "couette_energy",
                  "Taylor-Couette dr = 1/20, step_ends (paper 2, Fig. 10 right)", report,
                  "Taylor-Couette")
    for name in COUETTE:
        report.append((f"Taylor-Couette {name}: energy budget (E - E(0) - W) / W at the end "
                       "(W the walls' work)", budget_mismatch(runs / name)))


def wall_work(run):
    """Energy terms and the walls' work W(t): the model's accumulated "wall_work" term (counted
    negative there) when the run has it, else the trapezoid rule on the sampled wall_power."""
    energy = read_csv(run / "energy.csv")
    if "wall_work" in energy:
        return energy, -energy["wall_work"], "accumulated in the step"
    diagnostics = read_csv(run / "diagnostics.csv")
    power = np.interp(energy["time"], diagnostics["time"], diagnostics["wall_power"])
    work = np.concatenate([[0.0], np.cumsum(0.5 * (power[1:] + power[:-1])
                                             * np.diff(energy["time"]))])
    return energy, work, "trapezoid rule on the sampled wall_power"


def physical_energy(energy):
    return sum(energy[n] for n in ("kinetic", "volumetric", "shear", "penalty", "dissipated"))


def budget_mismatch(run):
    """(E - E(0) - W) / W at the end of the run as text: only for runs whose energy carries the
    accumulated wall_work (wall_power sampled at output steps, after the relaxation, does not
    give the work the step pairs with the kicks)."""
    energy, work, how = wall_work(run)
    if "wall_work" not in energy:
        return "not measured (run without the wall_work energy term)"
    total = physical_energy(energy)
    return f"{(total[-1] - total[0] - work[-1]) / work[-1]:.3e}"


def budget_figure(run, stem, title, report, what):
    energy, work, how = wall_work(run)
    total = physical_energy(energy)
    final = total[-1]
    names = ("kinetic", "volumetric", "shear", "penalty", "dissipated")
    columns = {"time": energy["time"], **{n + "_over_final": energy[n] / final for n in names},
               "energy_change": total - total[0], "wall_work": work}
    write_csv(stem.with_suffix(".csv"), columns)
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    for n in names:
        if np.any(energy[n] > 0):
            top.semilogy(energy["time"], np.maximum(energy[n] / final, 1e-12), label=n)
    top.set_ylabel("energy / final total")
    top.set_title(title)
    top.legend(fontsize=8)
    bottom.plot(energy["time"], total - total[0], label="E(t) - E(0)")
    bottom.plot(energy["time"], work, "--", label=f"work of the walls ({how})")
    bottom.set_xlabel("t")
    bottom.set_ylabel("energy")
    bottom.legend(fontsize=8)
    save_figure(fig, stem.with_suffix(".png"), DPI)
    report.append((f"{what}: energy budget at the end, (E - E(0) - W) / W (W the walls' work, "
                   f"{how})", f"{(total[-1] - total[0] - work[-1]) / work[-1]:.3e}"))


def ghia(re):
    u = read_csv(REFDATA / "ghia1982_u_vertical_centerline.csv")
    v = read_csv(REFDATA / "ghia1982_v_horizontal_centerline.csv")
    return u["y"], u[f"Re{re}"], v["x"], v[f"Re{re}"]


def cavity_at_ghia_points(run):
    """u on x = 1/2 and v on y = 1/2 at the last snapshot (kernel-weighted averages of all
    carriers, walls with the velocity they pretend) at Ghia et al.'s points, with Ghia's values;
    also the two interpolating functions and the time."""
    case = case_of(run)
    re = round(1.0 / case["material"]["kinematic_viscosity"])
    support = 2.0 * case["discretisation"]["smoothing_length_over_dr"] * case["discretisation"]["dr"]
    position, velocity, _, time = final_state(run)
    y_ref, u_ref, x_ref, v_ref = ghia(re)

    def u_on_vertical(y):
        return shepard(np.column_stack([np.full_like(y, 0.5), y]), position, velocity,
                       support)[:, 0]

    def v_on_horizontal(x):
        return shepard(np.column_stack([x, np.full_like(x, 0.5)]), position, velocity,
                       support)[:, 1]

    return {"y": y_ref, "u": u_on_vertical(y_ref), "u_ghia": u_ref, "x": x_ref,
            "v": v_on_horizontal(x_ref), "v_ghia": v_ref, "time": time,
            "u_on_vertical": u_on_vertical, "v_on_horizontal": v_on_horizontal}


def cavity_figures(runs, out, report):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    energy_fig, energy_axes = plt.subplots(1, 1, figsize=(7, 4.2))
    columns = {}
    for name in CAVITY:
        run = runs / name
        case = case_of(run)
        re = round(1.0 / case["material"]["kinematic_viscosity"])
        dr = case["discretisation"]["dr"]
        points = cavity_at_ghia_points(run)
        y_ref, u_ref, x_ref, v_ref = (points[k] for k in ("y", "u_ghia", "x", "v_ghia"))
        u, v, time = points["u"], points["v"], points["time"]
        u_on_vertical, v_on_horizontal = points["u_on_vertical"], points["v_on_horizontal"]
        line = np.linspace(0.0, 1.0, 101)
        label = f"Re {re}, dr = 1/{round(1 / dr)}, {run_variant(case)}"
        drawn = axes[0].plot(u_on_vertical(line), line, "-", lw=1.2, label=label)[0]
        axes[0].plot(u_ref, y_ref, "s", ms=4, mfc="none", color=drawn.get_color())
        axes[1].plot(line, v_on_horizontal(line), "-", lw=1.2, color=drawn.get_color(),
                     label=label)
        axes[1].plot(x_ref, v_ref, "s", ms=4, mfc="none", color=drawn.get_color())
        columns.update({f"{name}_y": y_ref, f"{name}_u": u, f"{name}_u_ghia": u_ref,
                        f"{name}_x": x_ref, f"{name}_v": v, f"{name}_v_ghia": v_ref})
        u_error, v_error = np.abs(u - u_ref), np.abs(v - v_ref)
        report.append((f"cavity {name} ({label}), t = {time:.2f}: L-inf error of u on x = 1/2, "
                       f"of v on y = 1/2 at the {len(y_ref)} Ghia points (walls included)",
                       f"{u_error.max():.4f}, {v_error.max():.4f}"))
        report.append((f"cavity {name}: the same at the {len(y_ref) - 2} interior points (the "
                       "first and last are the walls' values)",
                       f"{u_error[1:-1].max():.4f}, {v_error[1:-1].max():.4f}"))
        energy, _, _ = wall_work(run)
        total = physical_energy(energy)
        energy_axes.semilogy(energy["time"], energy["kinetic"] / total[-1],
                             label=f"kinetic, {label}")
        energy_axes.semilogy(energy["time"], np.maximum(energy["shear"] / total[-1], 1e-12),
                             ":", label=f"shear, {label}")
        report.append((f"cavity {name}: energy budget (E - E(0) - W) / W at the end (W the "
                       "walls' work)", budget_mismatch(run)))
    write_csv(out / "cavity_centrelines.csv", columns)
    axes[0].set_xlabel("u on x = 1/2")
    axes[0].set_ylabel("y")
    axes[0].set_title("Lid-driven cavity (paper 2, Fig. 14); squares: Ghia et al.")
    axes[0].legend(fontsize=7)
    axes[1].set_xlabel("x")
    axes[1].set_ylabel("v on y = 1/2")
    save_figure(fig, out / "cavity_centrelines.png", DPI)
    energy_axes.set_xlabel("t")
    energy_axes.set_ylabel("energy / final total")
    energy_axes.set_title("Lid-driven cavity energies (paper 2, Fig. 13 right)")
    energy_axes.legend(fontsize=6)
    save_figure(energy_fig, out / "cavity_energy.png", DPI)


def main():
    global REFDATA
    parser = figure_parser(__doc__)
    parser.add_argument("--refdata", default=str(REFDATA))
    args = parser.parse_args()
    REFDATA = Path(args.refdata)
    return figure_script_main(
        args, RUNS,
        [(COUETTE, couette_figures), (CAVITY, cavity_figures)],
        "shtc_fluids.md")


if __name__ == "__main__":
    sys.exit(main())
