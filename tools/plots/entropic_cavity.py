#!/usr/bin/python3
"""Natural convection with entropic SPH: the side-heated square cavity against the benchmark of
de Vahl Davis (1983), and Rayleigh-Benard convection (paper 4 §5.4, Fig. 12): the Nusselt
numbers over time, and the flow at the end.

Usage: /usr/bin/python3 tools/plots/entropic_cavity.py [--make-runs] [--runs DIR] [--out DIR]
           [--revsph PATH] [--threads N] [--only NAME ...]

--make-runs runs the cases models/entropic/cases/cavity-*.toml into RUNS/NAME (default RUNS =
out/entropic; Ra = 1e4 takes about 3 minutes on 2 threads, Ra = 1e5 about 20, their Boussinesq
variants 1 and 3, the conduction check 1, Rayleigh-Benard about 40; cavity-ra1e{4,5}-s{4.5,6.5}:
the kernel's support at 4.5 and 6.5 dr, walls as thick, about 2.5 and 5 times the cost;
cavity-ra1e4-s{3.0,4.5}-thick: walls twice the support thick; cavity-ra1e4-s{4.5,6.5}-hydro:
those walls with the authors' hydrostatic start and background pressure (1 at the top), -n40,
-n80, -n160 at 40 x 40, 80 x 80, 160 x 160; cavity-ra1e4-boussinesq-n80 at 80 x 80;
rayleigh-benard-s6.5 and -s6.5-conduction: the authors' RaBe.jl support, seeded or from the
conduction profile; rayleigh-benard-hydrostatic: the authors' start (initial.hydrostatic, the
conduction profile) at their low background pressure (about 1 at the top) with walls twice
the support thick, 3 dr, to t = 30 (about 45 minutes on one thread);
rayleigh-benard-hydrostatic-s6.5: the same at the authors' 6.5 dr (2.5 hours on one thread;
a longer run continues with revsph run --from as RUN-2, RUN-3, ...)).
Writes into --out (default docs/figures):
  entropic_cavity.png  the Nusselt numbers of the hot and the cold wall over time against the
                       benchmark, and the temperature field with the velocities at the end.
  entropic_cavity.csv  run, time, Nu of the hot wall, Nu of the cold wall.
  entropic_cavity.md   the measured and reference numbers (also printed).

The Nusselt number of a wall is the heat it passes per unit time over that of pure conduction
across the cavity, lambda dT H / L (2D, per unit depth): Nu = Qdot L / (lambda dT H). The model
reports the heat the hot walls gave out and the cold walls took in since the start
(diagnostics.csv); Qdot is its slope over windows of 1/30 of the run. The mean Nu is the mean
of the two walls over the last quarter of the run. The conduction check (gravity off) must give
Nu = 1 at its end: what it gives instead is the discretisation's own bias at the walls.
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
    REPO, case_of, chosen_runs_main, read_csv, save_figure, snapshots)

CASES = REPO / "models" / "entropic" / "cases"
RUNS = {
    "cavity-conduction": ["run", str(CASES / "cavity-ra1e4.toml"), "--set", "physics.gravity=0",
                          "--set", "physics.heat_conductivity=474.7120999711",
                          "--set", "run.t_end=6"],
    "cavity-ra1e4": ["run", str(CASES / "cavity-ra1e4.toml")],
    "cavity-ra1e5": ["run", str(CASES / "cavity-ra1e5.toml")],
    "cavity-ra1e4-boussinesq": ["run", str(CASES / "cavity-ra1e4-boussinesq.toml")],
    "cavity-ra1e5-boussinesq": ["run", str(CASES / "cavity-ra1e5-boussinesq.toml")],
    "rayleigh-benard": ["run", str(CASES / "rayleigh-benard.toml")],
    "rayleigh-benard-boussinesq": ["run", str(CASES / "rayleigh-benard-boussinesq.toml")],
}


def walls_around_unit_square(support, thickness, dr):
    """The outer edges (lo, hi) of walls ceil(thickness * support) layers of dr thick around the
    unit square: thick enough (thickness 1) that no gas particle sees past them, or (2) that
    no wall particle a gas particle sees has its kernel sum cut by the wall's outer edge."""
    t = np.ceil(thickness * support - 1e-9) * dr
    return -t, 1.0 + t


def domain_around(lo, hi):
    """The --set arguments of a domain 0.02 beyond walls reaching from lo to hi: the cases' own
    domain is too small for walls thicker than theirs."""
    return ["--set", f"domain.min=[{lo - 0.02!r}, {lo - 0.02!r}]",
            "--set", f"domain.max=[{hi + 0.02!r}, {hi + 0.02!r}]"]


def wider_kernel(case, dr, support, thickness=1, hydrostatic_pressure=None, refine=False):
    """The side-heated cavity with the kernel's support at `support` dr (issue 30: paper 4's
    cases use 3 dr, the authors' RaBe.jl 6.5 dr): the walls ceil(thickness * support) layers
    thick (1: no gas particle sees past them; 2: no wall particle that a gas particle sees has a
    kernel sum cut by the wall's outer edge, whose deficit gives it a strongly negative pressure
    in the stiffened gas), and dt = 0.65 dr / c0 whatever the support (the authors' dt = 0.1 h / c
    with h = 6.5 dr; the committed cases have 0.75 dr / c0). hydrostatic_pressure: the
    authors' start and background pressure instead (as hydrostatic_rayleigh_benard), the
    pressure at mid-height and the stiffened gas's reference pressure. refine: dr is not the
    case's own spacing; set it."""
    lo, hi = walls_around_unit_square(support, thickness, dr)
    extra = [] if hydrostatic_pressure is None else [
        "--set", "initial.hydrostatic=true",
        "--set", f"initial.pressure={hydrostatic_pressure!r}",
        "--set", f"physics.reference_pressure={hydrostatic_pressure!r}"]
    if refine:
        extra += ["--set", f"discretisation.dr={dr!r}"]
    if lo < -0.2:
        extra += domain_around(lo, hi)
    return ["run", str(CASES / case), *extra,
            "--set", f"discretisation.support_radius_over_dr={support!r}",
            "--set", f"discretisation.courant_number={0.65 / support!r}",
            "--set", f"particles[1].min=[{lo!r}, 0.0]",
            "--set", f"particles[2].max=[{hi!r}, 1.0]",
            "--set", f"particles[3].min=[{lo!r}, {lo!r}]", "--set", f"particles[3].max=[{hi!r}, 0.0]",
            "--set", f"particles[4].min=[{lo!r}, 1.0]", "--set", f"particles[4].max=[{hi!r}, {hi!r}]"]


for _support in (4.5, 6.5):
    RUNS[f"cavity-ra1e4-s{_support}"] = wider_kernel("cavity-ra1e4.toml", 0.025, _support)
    RUNS[f"cavity-ra1e5-s{_support}"] = wider_kernel("cavity-ra1e5.toml", 0.0125, _support)
for _support in (3.0, 4.5):
    RUNS[f"cavity-ra1e4-s{_support}-thick"] = wider_kernel("cavity-ra1e4.toml", 0.025, _support, 2)
# The authors' background pressure: about 1 at the top. p(mid) = 1 + rho g L / 2 less the
# lattice's kernel-sum excess times c0^2 (4.5 dr: 0.074 %, 1.2; 6.5 dr: 0.012 %, 0.19).
RUNS["cavity-ra1e4-s4.5-hydro"] = wider_kernel("cavity-ra1e4.toml", 0.025, 4.5, 2, 4.8)
RUNS["cavity-ra1e4-s6.5-hydro"] = wider_kernel("cavity-ra1e4.toml", 0.025, 6.5, 2, 5.8)
# The same at Ra 1e5 (80 x 80), and Ra 1e4 at 80 x 80: does the gap at Ra 1e4 close with dr?
RUNS["cavity-ra1e5-s4.5-hydro"] = wider_kernel("cavity-ra1e5.toml", 0.0125, 4.5, 2, 4.8)
RUNS["cavity-ra1e5-s6.5-hydro"] = wider_kernel("cavity-ra1e5.toml", 0.0125, 6.5, 2, 5.8)
RUNS["cavity-ra1e4-s4.5-hydro-n80"] = wider_kernel("cavity-ra1e4.toml", 0.0125, 4.5, 2, 4.8,
                                                     refine=True)
# Convergence in dr: Ra 1e4 at 160 x 160 (about 10 hours on one thread), Ra 1e5 at 40 x 40
# (about 10 minutes), and the Boussinesq Ra 1e4 cavity at 80 x 80 (Ra 1e5's case with Ra 1e4's
# viscosity and conductivity).
RUNS["cavity-ra1e4-s4.5-hydro-n160"] = wider_kernel("cavity-ra1e4.toml", 0.00625, 4.5, 2, 4.8,
                                                      refine=True)
RUNS["cavity-ra1e5-s4.5-hydro-n40"] = wider_kernel("cavity-ra1e5.toml", 0.025, 4.5, 2, 4.8,
                                                     refine=True)
RUNS["cavity-ra1e4-boussinesq-n80"] = [
    "run", str(CASES / "cavity-ra1e5-boussinesq.toml"),
    "--set", "physics.viscosity=8.4261497731763586e-3",
    "--set", "physics.heat_conductivity=2.966950624819375"]


def rayleigh_benard_walls(support, thickness, courant):
    """rayleigh-benard (dr = 1/105) with the kernel's support at `support` dr: the heater and
    cooler rows and the side walls as walls_around_unit_square makes them, the domain around
    them, and dt = courant dr / c0 whatever the support."""
    lo, hi = walls_around_unit_square(support, thickness, 1.0 / 105.0)
    return ["run", str(CASES / "rayleigh-benard.toml"),
            "--set", f"discretisation.support_radius_over_dr={support!r}",
            "--set", f"discretisation.courant_number={courant / support!r}",
            *domain_around(lo, hi),
            "--set", f"particles[1].min=[{lo!r}, {lo!r}]", "--set", f"particles[1].max=[{hi!r}, 0.0]",
            "--set", f"particles[2].min=[{lo!r}, 1.0]", "--set", f"particles[2].max=[{hi!r}, {hi!r}]",
            "--set", f"particles[3].min=[{lo!r}, 0.0]", "--set", f"particles[4].max=[{hi!r}, 1.0]"]


def wider_kernel_rayleigh_benard(support, conduction_start=False, t_end=30.0):
    """rayleigh-benard with the authors' RaBe.jl kernel (support 6.5 dr): heater and cooler rows
    and the side walls ceil(support) layers thick, dt = 0.65 dr / c0; conduction_start: the
    authors' start from the conduction profile (T from 1.05 at the bottom to 0.95 at the top)
    instead of uniform T with a seeded roll. Run to t_end (30, as the hydrostatic start: about
    2 hours on one thread at 6.5 dr; the case's 100 would take 6)."""
    command = rayleigh_benard_walls(support, 1, 0.65) + ["--set", f"run.t_end={t_end!r}",
                                                         "--set", "output.snapshot_every=4000"]
    if conduction_start:
        command += ["--set", "initial.temperature_gradient=[0.0, -0.1]"]
    return command


def hydrostatic_rayleigh_benard(support=3.0, pressure=4.0, t_end=30.0):
    """rayleigh-benard as the authors' RaBe.jl starts it: in hydrostatic equilibrium on the
    conduction profile (T from 1.05 at the bottom to 0.95 at the top), the seeded roll on top,
    at their background pressure: the stiffened gas's p about 1 at the top (RaBe.jl's P_inf =
    T_top - h T_dif). `pressure` is initial.pressure at mid-height, set to the reference
    pressure too (T0 = 1 there); at 3 dr the lattice's kernel sum is 0.51 % above rho, which
    adds c0^2 * 0.0051 = 2.1 to every pressure, so 4 gives about 1 at the top. Heater, cooler
    and side walls twice the support thick (a wall particle's kernel sum cut by the wall's outer
    edge gives it a strongly negative pressure; with 3 layers the gas was drawn into the top
    corners by t = 3)."""
    return [*rayleigh_benard_walls(support, 2, 0.75),
            "--set", "initial.hydrostatic=true", "--set", "initial.temperature_gradient=[0.0, -0.1]",
            "--set", f"initial.pressure={pressure!r}", "--set", f"physics.reference_pressure={pressure!r}",
            "--set", f"run.t_end={t_end!r}", "--set", "output.snapshot_every=4000"]


RUNS["rayleigh-benard-hydrostatic"] = hydrostatic_rayleigh_benard()
RUNS["rayleigh-benard-s6.5"] = wider_kernel_rayleigh_benard(6.5)
RUNS["rayleigh-benard-s6.5-conduction"] = wider_kernel_rayleigh_benard(6.5, True)
# The authors' start at their support: at 6.5 dr the lattice's kernel sum is only 0.012 % above
# rho (3 dr: 0.51 %), so the pressure offset that gave about 1 at the top at 3 dr shrinks from 2.1
# to 0.05: 2.0 at mid-height gives about 1 at the top again.
RUNS["rayleigh-benard-hydrostatic-s6.5"] = hydrostatic_rayleigh_benard(6.5, 2.0)

# de Vahl Davis (1983), Int. J. Numer. Methods Fluids 3, 249-264: mean Nusselt numbers of the
# benchmark solution (Pr = 0.71).
REFERENCE = {"cavity-ra1e4": 2.243, "cavity-ra1e5": 4.519, "cavity-conduction": 1.0,
             "cavity-ra1e4-boussinesq": 2.243, "cavity-ra1e5-boussinesq": 4.519}
REFERENCE.update({f"cavity-ra1e{k}-s{s}": REFERENCE[f"cavity-ra1e{k}"]
                  for k in (4, 5) for s in (4.5, 6.5)})
REFERENCE.update({f"cavity-ra1e4-s{s}-thick": REFERENCE["cavity-ra1e4"] for s in (3.0, 4.5)})
REFERENCE.update({f"cavity-ra1e4-s{s}-hydro": REFERENCE["cavity-ra1e4"] for s in (4.5, 6.5)})
REFERENCE.update({f"cavity-ra1e5-s{s}-hydro": REFERENCE["cavity-ra1e5"] for s in (4.5, 6.5)})
REFERENCE.update({n: REFERENCE["cavity-ra1e4"] for n in (
    "cavity-ra1e4-s4.5-hydro-n80", "cavity-ra1e4-s4.5-hydro-n160", "cavity-ra1e4-boussinesq-n80")})
REFERENCE["cavity-ra1e5-s4.5-hydro-n40"] = REFERENCE["cavity-ra1e5"]
# The Rayleigh-Benard case (paper 4 Fig. 12) has no reference number: its Nu is reported only.


def segments(run):
    """The run's directories in order: RUN, RUN-2, RUN-3, ... (continued with revsph run --from)."""
    found = [run]
    k = 2
    while (run.parent / f"{run.name}-{k}").is_dir():
        found.append(run.parent / f"{run.name}-{k}")
        k += 1
    return found


CUMULATIVE = ("heat_out_of_hot_walls", "heat_into_cold_walls")


def stitched_diagnostics(run):
    """diagnostics.csv over the run's segments: a continued run counts its walls' heat from
    zero again, so each segment's cumulative heats are offset by where the last one ended."""
    joined = None
    for segment in segments(run):
        part = read_csv(segment / "diagnostics.csv")
        if joined is None:
            joined = part
            continue
        keep = part["time"] > joined["time"][-1]
        for name in joined:
            values = part[name]
            if name in CUMULATIVE:
                values = values + joined[name][-1] - part[name][0]
            joined[name] = np.concatenate([joined[name], values[keep]])
    return joined


def nusselt_series(run):
    case = case_of(run)
    diagnostics = stitched_diagnostics(run)
    thermal = [block for block in case["particles"] if block["kind"] == "thermal"]
    held = [block["temperature"] for block in thermal]
    gas = next(block for block in case["particles"] if block["kind"] == "gas")
    # The axis the heat crosses: the one along which the hottest and coldest walls lie apart.
    centre = [[0.5 * (b["min"][k] + b["max"][k]) for k in range(2)] for b in thermal]
    hot, cold = centre[held.index(max(held))], centre[held.index(min(held))]
    axis = 0 if abs(hot[0] - cold[0]) > abs(hot[1] - cold[1]) else 1
    across = gas["max"][axis] - gas["min"][axis]
    along = gas["max"][1 - axis] - gas["min"][1 - axis]
    conduction = case["physics"]["heat_conductivity"] * (max(held) - min(held)) * along / across
    t = diagnostics["time"]
    window = max(1, len(t) // 30)
    mid = 0.5 * (t[window:] + t[:-window])
    dt = t[window:] - t[:-window]
    hot = (diagnostics["heat_out_of_hot_walls"][window:]
           - diagnostics["heat_out_of_hot_walls"][:-window]) / dt / conduction
    cold = (diagnostics["heat_into_cold_walls"][window:]
            - diagnostics["heat_into_cold_walls"][:-window]) / dt / conduction
    last = t >= 0.75 * t[-1]
    mean_hot = (np.interp(t[-1], t, diagnostics["heat_out_of_hot_walls"])
                - np.interp(t[last][0], t, diagnostics["heat_out_of_hot_walls"]))
    mean_cold = (np.interp(t[-1], t, diagnostics["heat_into_cold_walls"])
                 - np.interp(t[last][0], t, diagnostics["heat_into_cold_walls"]))
    span = t[-1] - t[last][0]
    return mid, hot, cold, mean_hot / span / conduction, mean_cold / span / conduction


def make_figures(runs, out, report, names):
    fig, axes = plt.subplots(1, 1 + len(names), figsize=(5.2 * (1 + len(names)), 4.6),
                             squeeze=False)
    axes = axes[0]
    rows = []
    for index, name in enumerate(names):
        run = runs / name
        mid, hot, cold, mean_hot, mean_cold = nusselt_series(run)
        colour = f"C{index}"
        axes[0].plot(mid, hot, "-", color=colour, label=f"{name}: hot wall")
        axes[0].plot(mid, cold, "--", color=colour, label=f"{name}: cold wall")
        if name in REFERENCE:
            axes[0].axhline(REFERENCE[name], color=colour, linestyle=":", linewidth=1)
        rows += [(name, t, h, c) for t, h, c in zip(mid, hot, cold)]
        mean = 0.5 * (mean_hot + mean_cold)
        report.append((f"{name}: mean Nu over the last quarter (hot, cold)",
                       f"{mean:.4f} ({mean_hot:.4f}, {mean_cold:.4f})"))
        if name in REFERENCE:
            report += [
                (f"{name}: reference (de Vahl Davis 1983; conduction: 1)", f"{REFERENCE[name]}"),
                (f"{name}: relative difference", f"{mean / REFERENCE[name] - 1:+.2%}"),
            ]
        with h5py.File(snapshots(segments(run)[-1])[-1]) as f:
            gas = f["particles/gas"]
            x, v, temperature = gas["position"][:], gas["velocity"][:], gas["temperature"][:]
            time = float(f.attrs["time"])
        ax = axes[1 + index]
        picture = ax.scatter(x[:, 0], x[:, 1], c=temperature, s=6, cmap="coolwarm")
        every = max(1, len(x) // 400)
        ax.quiver(x[::every, 0], x[::every, 1], v[::every, 0], v[::every, 1], width=0.003)
        ax.set_aspect("equal")
        ax.set_title(f"{name}, t = {time:.1f} s")
        fig.colorbar(picture, ax=ax, label="T (K)", shrink=0.8)
    axes[0].set_xlabel("t (s)")
    axes[0].set_ylabel("Nu")
    axes[0].set_ylim(0, None)
    axes[0].grid(True, alpha=0.3)
    axes[0].legend(fontsize=7)
    axes[0].set_title("Nusselt numbers (dotted: de Vahl Davis)")
    save_figure(fig, out / "entropic_cavity.png")
    with open(out / "entropic_cavity.csv", "w") as f:
        f.write("run,time,nusselt_hot,nusselt_cold\n")
        for name, t, h, c in rows:
            f.write(f"{name},{t:.6g},{h:.6g},{c:.6g}\n")


def main():
    return chosen_runs_main(__doc__, "out/entropic", RUNS, lambda name: RUNS[name], make_figures,
                            "entropic_cavity.md")


if __name__ == "__main__":
    sys.exit(main())
