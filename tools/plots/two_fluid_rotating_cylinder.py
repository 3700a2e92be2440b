"""The rotating cylinder with Tsuzuki's two-fluid model (paper 5 sec. V.3, Figs. 10-12): helium II
at 1.6 K in the paper's vessel (diameter 2 mm) spun up by its wall turning at 5 rad/s; |v| against
the radius at 0.5 s and 5 s, the least-squares slope against time and against the analytic
Navier-Stokes spin-up (tools/plots/cylinder_spin_up.py), and the C_omega scan.

Usage: /usr/bin/python3 tools/plots/two_fluid_rotating_cylinder.py [--make-runs] [--runs DIR]
           [--out DIR] [--revsph PATH] [--threads N] [--only NAME ...]

--make-runs runs, into RUNS/NAME (default RUNS = out/two_fluid), 160 particles across the vessel
(about 20 000 fluid particles, 8 minutes per run to 5 s on one thread; 90 minutes in all):
  spin-up-normal            models/two_fluid/cases/spin-up-normal.toml: normal fluid alone, spin
                            term off, to 2 s: the check against Navier-Stokes
  cylinder-paper            models/two_fluid/cases/rotating-cylinder.toml: C_omega = 0.01,
                            Vinen's decay beta_v = 4.76e-9 m^2/s
  cylinder-paper-steady-l   beta_v = 0: the line density stays at L0, the two fluids locked
  cylinder-paper-cSCAN      C_omega = 0, 0.005, 0.015, 0.02, 0.03, 0.05, 0.1, 0.2
  cylinder-interp           physics.phases = interpenetrating (README): the mixture as the
                            two-fluid continuum, C_omega = 0.01
  cylinder-interp-nospin    the same, spin term off: against the linear two-fluid spin-up
  cylinder-interp-nofriction  the same, friction off too (alpha = 0), to 2 s: the continuum
                            leaves the superfluid at rest; what moves it is the particles' own
                            coupling (README)
  cylinder-grip-wall-l      as cylinder-paper, the friction against the wall particles held at
                            L0 (mutual_friction.wall_line_density = "initial"; README, "Wall grip")
  cylinder-grip-undiluted   as cylinder-paper, the normal pairs' viscosity undiluted
                            (physics.separate_phase_viscosity = "undiluted")
  cylinder-grip-rigid       as cylinder-paper, the wall turning rigidly (particles[1].wall_motion =
                            "rigid")
  cylinder-grip-all         the three together
  cylinder-grip-all-central the three with physics.viscosity_form = "central" (undiluted, eq. 34's
                            non-central pair force brakes rigid rotation N / N_n times harder), the
                            spin term off (it repairs eq. 34's torque; beside the central form its
                            fixed spin drives the fluid past the wall) and viscous_number 0.02
                            (0.125 blew the small vessel up at step 11): six times the steps
  cylinder-interp-grip      cylinder-interp with the wall's friction at L0 and the wall turning
                            rigidly (interpenetrating phases are undiluted already)
  cylinder-interp-grip-320  the same at 320 particles across (about 80 000 fluid particles)
  cylinder-paper-320        cylinder-paper at 320 particles across (dr halved), to 5 s
Writes into --out (default docs/figures):
  two_fluid_rotating_cylinder.png  the normal fluid alone against Navier-Stokes; |v| against r at
                                   0.5 s and 5 s; the slope against t; the scan: vortex strength
                                   and slope at 5 s against C_omega; the normal fluid's velocity
                                   about its mean rotation at 5 s
  two_fluid_rotating_cylinder.csv  run, C_omega, beta_v, t, kind, slope of |v| against r, vortex
                                   strength, analytic slopes (normal fluid alone, fluids locked)
  two_fluid_rotating_cylinder.md   the numbers (also printed)
  two_fluid_cylinder_grip.png      the cylinder-grip runs' slopes against t and the two-fluid
                                   continuum (their numbers in the .md too)

The slope is the least-squares fit |v| = k r through the origin over every particle of a kind.
The vortex strength is the rms of v minus the kind's mean azimuthal velocity at that radius
(10 rings), over (5 rad/s R): the flow that is not a rotation about the axis.
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
from cylinder_spin_up import spin_up_slope, spin_up_velocity, two_fluid_spin_up  # noqa: E402
from revsph_runs import REPO, chosen_runs, figure_parser, figure_script_main, save_figure, snapshots  # noqa: E402,E501

CASES = REPO / "models" / "two_fluid" / "cases"
OMEGA = 5.0
RADIUS = 1.0e-3
ETA_N = 1.306e-6  # the cases' eta_bar = eta_r = eta_n (Donnelly & Barenghi 1998, 1.6 K)
RHO_N, RHO = 24.105, 145.207
NU_NORMAL = 2 * ETA_N / RHO_N  # the normal fluid alone: (eta_bar + eta_r) / rho_n
NU_LOCKED = 2 * ETA_N / RHO  # both fluids locked together by the friction
SCAN = (0.0, 0.005, 0.01, 0.015, 0.02, 0.03, 0.05, 0.1, 0.2)
RUNS = {"spin-up-normal": (0.0, 0.0), "cylinder-paper": (0.01, 4.76e-9),
        "cylinder-paper-steady-l": (0.01, 0.0)}
RUNS.update({f"cylinder-paper-c{c}": (c, 4.76e-9) for c in SCAN if c != 0.01})
# physics.phases = "interpenetrating" (README): the random mixture as the two-fluid continuum.
INTERPENETRATING = {"cylinder-interp": (0.01, 4.76e-9), "cylinder-interp-nospin": (0.0, 4.76e-9)}
RUNS.update(INTERPENETRATING)
FRICTIONLESS = "cylinder-interp-nofriction"  # interpenetrating, spin and friction off, to 2 s
RUNS[FRICTIONLESS] = (0.0, 4.76e-9)
# The wall-grip options (README, "Wall grip"), each alone and all together, on cylinder-paper.
GRIP_OPTIONS = {"wall-l": "mutual_friction.wall_line_density=initial",
                "undiluted": "physics.separate_phase_viscosity=undiluted",
                "rigid": "particles[1].wall_motion=rigid"}
GRIP = {f"cylinder-grip-{k}": [v] for k, v in GRIP_OPTIONS.items()}
GRIP["cylinder-grip-all"] = list(GRIP_OPTIONS.values())
GRIP["cylinder-grip-all-central"] = [*GRIP_OPTIONS.values(), "physics.viscosity_form=central",
                                     "spin.coefficient=0", "discretisation.viscous_number=0.02"]
# The next experiment the wall-grip runs point to (README): the interpenetrating mixture, whose
# normal fluid is not locked to superfluid particles, with the wall's grip (undiluted already).
GRIP["cylinder-interp-grip"] = [GRIP_OPTIONS["wall-l"], GRIP_OPTIONS["rigid"]]
INTERPENETRATING["cylinder-interp-grip"] = (0.01, 4.76e-9)
# The same at 320 particles across (dr halved: four times the particles).
GRIP["cylinder-interp-grip-320"] = [*GRIP["cylinder-interp-grip"], "discretisation.dr=6.25e-6"]
INTERPENETRATING["cylinder-interp-grip-320"] = (0.01, 4.76e-9)
# The kernel's support, which the paper does not give (issue 30): 2 and 4 dr beside the case's 3,
# the wall as thick as the support.
GRIP["cylinder-paper-s2"] = ["discretisation.support_radius_over_dr=2.0"]
GRIP["cylinder-paper-s4"] = ["discretisation.support_radius_over_dr=4.0",
                             "particles[1].outer_radius=1.05e-3"]
GRIP["cylinder-paper-s2-320"] = [*GRIP["cylinder-paper-s2"], "discretisation.dr=6.25e-6", "run.t_end=2.0"]
# The case itself (3 dr) at 320 across to 5 s: does the separate phases' rate move with dr?
GRIP["cylinder-paper-320"] = ["discretisation.dr=6.25e-6"]
RUNS.update({name: (0.01, 4.76e-9) for name in GRIP})
RHO_S = RHO - RHO_N
ALPHA, KAPPA, L0, BETA_V = 0.0968, 9.9693e-8, 1.0e10, 4.76e-9  # the case's mutual friction


def friction_coefficient(t, beta=BETA_V):
    """C_L(t) = (2/3) rho_s alpha kappa L(t), 1/L = 1/L0 + beta_v t (paper 5 eqs. 8-9, 29)."""
    return 2.0 / 3.0 * RHO_S * ALPHA * KAPPA / (1.0 / L0 + beta * t)


def command(name):
    if name == "spin-up-normal":
        return ["run", str(CASES / "spin-up-normal.toml")]
    c_omega, beta = RUNS[name]
    arguments = ["run", str(CASES / "rotating-cylinder.toml")]
    if name in INTERPENETRATING or name == FRICTIONLESS:
        arguments += ["--set", "physics.phases=interpenetrating"]
    if name == FRICTIONLESS:
        arguments += ["--set", "mutual_friction.alpha=0", "--t-end", "2"]
    for setting in GRIP.get(name, []):
        arguments += ["--set", setting]
    if beta != 4.76e-9:
        arguments += ["--set", f"mutual_friction.vinen_beta={beta!r}"]
    if c_omega != 0.01:
        arguments += ["--set", f"spin.coefficient={c_omega!r}"]
    return arguments


def read_state(path):
    """Time and, per kind present, positions and velocities."""
    with h5py.File(path) as f:
        kinds = {}
        for kind in ("superfluid", "normal"):
            g = f[f"particles/{kind}"]
            if len(g["mass"]):
                kinds[kind] = (g["position"][...],
                               g["momentum"][...] / g["mass"][...].reshape(-1, 1))
        return float(f.attrs["time"]), kinds


def state_at(run, time):
    best = min(snapshots(run), key=lambda p: abs(read_state(p)[0] - time))
    return read_state(best)


def azimuthal_velocity(x, v):
    """r and v_theta of each particle."""
    r = np.hypot(x[:, 0], x[:, 1])
    return r, (x[:, 0] * v[:, 1] - x[:, 1] * v[:, 0]) / np.maximum(r, 1e-300)


def ring_means(x, v, rings=10):
    """Each particle's ring (of `rings` equal widths across R) and each ring's mean v_theta (0 for
    an empty ring)."""
    r, azimuthal = azimuthal_velocity(x, v)
    ring = np.minimum((r / RADIUS * rings).astype(int), rings - 1)
    return ring, np.array([azimuthal[ring == k].mean() if np.any(ring == k) else 0.0
                           for k in range(rings)])


def rotation_measures(x, v):
    """r, |v|, the slope of |v| = k r, and the vortex strength (module docstring)."""
    r = np.hypot(x[:, 0], x[:, 1])
    speed = np.hypot(v[:, 0], v[:, 1])
    slope = np.sum(r * speed) / np.sum(r * r)
    ring, mean = ring_means(x, v)
    about = v - mean[ring][:, None] * np.column_stack([-x[:, 1], x[:, 0]]) / np.maximum(r, 1e-300)[:, None]
    strength = np.sqrt(np.mean(np.sum(about**2, axis=1))) / (OMEGA * RADIUS)
    return r, speed, slope, strength, about


def history(run):
    """[(t, kind, slope, strength)] over every snapshot of a run."""
    rows = []
    for path in snapshots(run):
        t, kinds = read_state(path)
        for kind, (x, v) in kinds.items():
            _, _, slope, strength, _ = rotation_measures(x, v)
            rows.append((t, kind, slope, strength))
    return rows


def plot_normal_alone(axis, runs, rows, report):
    t_all = np.linspace(0, 2.0, 81)
    axis.plot(t_all, [spin_up_slope(t, NU_NORMAL, RADIUS, OMEGA) for t in t_all], "k-",
              label=f"Navier-Stokes, nu = 2 eta_n / rho_n = {NU_NORMAL:.3g} m^2/s")
    h = history(runs / "spin-up-normal")
    axis.plot([r[0] for r in h], [r[2] for r in h], "o", label="SPH, normal fluid alone")
    worst = 0.0
    for t, kind, slope, strength in h:
        exact = spin_up_slope(t, NU_NORMAL, RADIUS, OMEGA)
        rows.append(("spin-up-normal", 0.0, 0.0, t, kind, slope, strength, exact, np.nan))
        if t > 0:
            worst = max(worst, abs(slope / exact - 1))
    t, kinds = state_at(runs / "spin-up-normal", 0.5)
    r, azimuthal = azimuthal_velocity(*kinds["normal"])
    rms = np.sqrt(np.mean((azimuthal - spin_up_velocity(r, t, NU_NORMAL, RADIUS, OMEGA))**2))
    report.append(("spin-up-normal: largest |slope / Navier-Stokes - 1| over the snapshots",
                   f"{worst:.4f}"))
    report.append((f"spin-up-normal: rms of v_theta - Navier-Stokes at t = {t:.3g} s / (5 rad/s R)",
                   f"{rms / (OMEGA * RADIUS):.4f}"))
    axis.set(xlabel="t (s)", ylabel="slope of |v| against r (rad/s)",
             title="normal fluid alone in the 2 mm vessel")
    axis.legend(fontsize=7)


def plot_profiles(axes, runs, report):
    for axis, time in zip(axes, (0.5, 5.0)):
        for name in ("cylinder-paper", "cylinder-paper-steady-l"):
            t, kinds = state_at(runs / name, time)
            for kind, (x, v) in kinds.items():
                r, speed, slope, _, _ = rotation_measures(x, v)
                axis.plot(r / RADIUS, speed / (OMEGA * RADIUS), ".", ms=1,
                          label=f"{name}, {kind}: slope {slope:.2f} rad/s")
        grid = np.linspace(0, RADIUS, 200)
        for nu, label in ((NU_LOCKED, "fluids locked"), (NU_NORMAL, "normal fluid alone")):
            axis.plot(grid / RADIUS, spin_up_velocity(grid, time, nu, RADIUS, OMEGA) / (OMEGA * RADIUS),
                      "-", lw=1.5, label=f"Navier-Stokes, {label}: slope "
                      f"{spin_up_slope(time, nu, RADIUS, OMEGA):.2f}")
        axis.plot([0, 1], [0, 1], "k--", lw=1, label="rigid rotation at 5 rad/s")
        axis.set(xlabel="r / R", ylabel="|v| / (5 rad/s R)", title=f"C_omega = 0.01, t = {time} s")
        axis.legend(fontsize=6)
    for nu, label in ((NU_LOCKED, "fluids locked"), (NU_NORMAL, "normal fluid alone")):
        report.append((f"Navier-Stokes slope at 5 s, {label} (nu = {nu:.3g} m^2/s)",
                       f"{spin_up_slope(5.0, nu, RADIUS, OMEGA):.3f}"))


def plot_navier_stokes_slopes(axis, t_end, samples):
    """The analytic spin-up's slope against t for the normal fluid alone and the locked fluids."""
    t_all = np.linspace(0, t_end, samples)
    for nu, label in ((NU_NORMAL, "normal fluid alone"), (NU_LOCKED, "fluids locked")):
        axis.plot(t_all, [spin_up_slope(t, nu, RADIUS, OMEGA) for t in t_all], "-",
                  label=f"Navier-Stokes, {label}")
    return t_all


def plot_slope_history(axis, runs, rows, report):
    t_all = plot_navier_stokes_slopes(axis, 5.0, 101)
    # The linear two-fluid continuum with the case's C_L(t): the reference of the
    # interpenetrating runs (the spin term, absent from it, is off in cylinder-interp-nospin).
    continuum = two_fluid_spin_up(t_all[1:], RHO_N, RHO_S, 2 * ETA_N, friction_coefficient,
                                  RADIUS, OMEGA)
    for k, kind in enumerate(("normal", "superfluid")):
        axis.plot(t_all[1:], [c[k] for c in continuum], "k" + ("-." if k else ":"),
                  label=f"two-fluid continuum, {kind}")
        report.append((f"two-fluid continuum (C_L(t) of the case): {kind}'s slope at 5 s",
                       f"{continuum[-1][k]:.3f}"))
    for name in ("cylinder-paper", "cylinder-paper-steady-l", *INTERPENETRATING):
        c_omega, beta = RUNS[name]
        whole = history(runs / name)
        for kind, marker in (("superfluid", "o"), ("normal", "s")):
            h = [r for r in whole if r[1] == kind]
            axis.plot([r[0] for r in h], [r[2] for r in h], marker, ms=3, mfc="none",
                      label=f"{name}, {kind}")
            if name in INTERPENETRATING:
                report.append((f"{name}: {kind}'s slope at {h[-1][0]:.3g} s", f"{h[-1][2]:.3f}"))
        if name in INTERPENETRATING:
            rows += [(name, c_omega, beta, t, kind, slope, strength,
                      spin_up_slope(t, NU_NORMAL, RADIUS, OMEGA),
                      spin_up_slope(t, NU_LOCKED, RADIUS, OMEGA))
                     for t, kind, slope, strength in whole]
    axis.axhline(OMEGA, color="k", ls="--", lw=1)
    axis.axhline(0.9 * OMEGA, color="k", ls=":", lw=1)
    axis.set(xlabel="t (s)", ylabel="slope of |v| against r (rad/s)",
             title="spin-up of the mixture (C_omega = 0.01 unless 'nospin')")
    axis.legend(fontsize=6)


def plot_scan(axes, runs, names, rows, report):
    points = []
    for name in names:
        c_omega, beta = RUNS[name]
        for t, kind, slope, strength in history(runs / name):
            rows.append((name, c_omega, beta, t, kind, slope, strength,
                         spin_up_slope(t, NU_NORMAL, RADIUS, OMEGA),
                         spin_up_slope(t, NU_LOCKED, RADIUS, OMEGA)))
        if beta == 4.76e-9:
            for time in (0.5, 5.0):
                t, kinds = state_at(runs / name, time)
                for kind, (x, v) in kinds.items():
                    _, _, slope, strength, _ = rotation_measures(x, v)
                    points.append((c_omega, time, kind, slope, strength))
        report.append((f"{name}: slope at 5 s, superfluid / normal (rad/s)",
                       " / ".join(f"{r[5]:.3f}" for r in rows[-2:])))
    for time, style in ((0.5, "--"), (5.0, "-")):
        for kind, marker in (("superfluid", "o"), ("normal", "s")):
            chosen = sorted(p for p in points if p[1] == time and p[2] == kind)
            axes[0].plot([p[0] for p in chosen], [p[4] for p in chosen], marker + style,
                         label=f"{kind}, t = {time} s")
            if time == 5.0:
                axes[1].plot([p[0] for p in chosen], [p[3] for p in chosen], marker + style,
                             label=kind)
                for p in chosen:
                    report.append((f"C_omega = {p[0]}: {kind}'s vortex strength at 5 s",
                                   f"{p[4]:.4f}"))
    axes[0].set(xlabel="C_omega", ylabel="rms |v - mean rotation| / (5 rad/s R)",
                title="vortex strength (beta_v = 4.76e-9)")
    axes[0].legend(fontsize=7)
    axes[1].axhline(OMEGA, color="k", ls="--", lw=1)
    axes[1].set(xlabel="C_omega", ylabel="slope at 5 s (rad/s)", title="spin-up against C_omega")
    axes[1].legend(fontsize=7)


def plot_field(axis, runs, name):
    t, kinds = state_at(runs / name, 5.0)
    x, v = kinds["normal"]
    _, _, _, _, about = rotation_measures(x, v)
    axis.quiver(x[:, 0] * 1e3, x[:, 1] * 1e3, about[:, 0], about[:, 1])
    axis.set(aspect="equal", xlabel="x (mm)", ylabel="y (mm)",
             title=f"{name}:\nnormal fluid about its mean rotation, t = {t:.2f} s")


def plot_frictionless(axis_slope, axis_profile, runs, report):
    """Interpenetrating phases with friction and spin off: the continuum's superfluid stays at rest
    and its normal fluid spins up alone (nu = 2 eta_n / rho_n); the particles say otherwise."""
    whole = history(runs / FRICTIONLESS)
    t_all = plot_navier_stokes_slopes(axis_slope, 2.0, 81)
    axis_slope.plot(t_all, 0 * t_all, "k-.", label="continuum superfluid (no friction): 0")
    for kind, marker in (("superfluid", "o"), ("normal", "s")):
        h = [r for r in whole if r[1] == kind]
        axis_slope.plot([r[0] for r in h], [r[2] for r in h], marker, mfc="none", label=kind)
        report.append((f"{FRICTIONLESS}: {kind}'s slope at {h[-1][0]:.3g} s", f"{h[-1][2]:.3f}"))
    axis_slope.set(xlabel="t (s)", ylabel="slope of |v| against r (rad/s)",
                   title=f"{FRICTIONLESS}: friction and spin off")
    axis_slope.legend(fontsize=6)
    t, kinds = state_at(runs / FRICTIONLESS, 2.0)
    r_fine = np.linspace(0, RADIUS, 101)
    for nu, label in ((NU_NORMAL, "normal fluid alone"), (NU_LOCKED, "fluids locked")):
        axis_profile.plot(r_fine / RADIUS,
                          spin_up_velocity(r_fine, t, nu, RADIUS, OMEGA) / (OMEGA * RADIUS), "-",
                          label=f"Navier-Stokes, {label}")
    for kind, (x, v) in kinds.items():
        _, means = ring_means(x, v)
        centres, profile = (np.arange(len(means)) + 0.5) / len(means), means / (OMEGA * RADIUS)
        axis_profile.plot(centres, profile, "o-" if kind == "superfluid" else "s-", mfc="none",
                          label=f"{kind}, t = {t:.2f} s")
        report.append((f"{FRICTIONLESS}: {kind}'s ring means of v_theta / (Omega R) at {t:.3g} s",
                       " ".join(f"{p:.3f}" for p in profile)))
    locked = spin_up_velocity(np.array([0.95 * RADIUS]), t, NU_LOCKED, RADIUS, OMEGA)[0]
    report.append((f"Navier-Stokes, fluids locked: v_theta / (Omega R) at 0.95 R, {t:.3g} s",
                   f"{locked / (OMEGA * RADIUS):.3f}"))
    axis_profile.set(xlabel="r / R", ylabel="ring mean of v_theta / (Omega R)",
                     title=f"{FRICTIONLESS}: the outer ring slips at the wall")
    axis_profile.legend(fontsize=6)


def make_figures(runs, out, report, names):
    fig, axes = plt.subplots(3, 4, figsize=(21, 14))
    rows = []
    plot_normal_alone(axes[0, 0], runs, rows, report)
    plot_profiles(axes[0, 1:], runs, report)
    plot_slope_history(axes[1, 0], runs, rows, report)
    scan = [n for n in names if n.startswith("cylinder-paper")]
    plot_scan(axes[1, 1:], runs, scan, rows, report)
    plot_field(axes[2, 0], runs, "cylinder-paper")
    plot_field(axes[2, 1], runs, "cylinder-paper-c0.05")
    plot_field(axes[2, 2], runs, "cylinder-paper-c0.0")
    plot_frictionless(axes[0, 3], axes[1, 3], runs, report)
    axes[2, 3].axis("off")
    save_figure(fig, out / "two_fluid_rotating_cylinder.png")
    with open(out / "two_fluid_rotating_cylinder.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["run", "c_omega", "vinen_beta", "time", "kind", "slope",
                         "vortex_strength", "slope_ns_normal_alone", "slope_ns_locked"])
        writer.writerows([r[0], r[1], r[2], f"{r[3]:.6g}", r[4]] + [f"{x:.6g}" for x in r[5:]]
                         for r in rows)


def make_grip_figure(runs, out, report):
    """The cylinder-grip runs' slopes against t, with the two-fluid continuum of the case's
    C_L(t) (4.41 / 3.72 rad/s at 5 s) and its +-10 % band at 5 s."""
    fig, axis = plt.subplots(figsize=(8, 6))
    t_all = np.linspace(0.0, 5.0, 101)
    continuum = two_fluid_spin_up(t_all[1:], RHO_N, RHO_S, 2 * ETA_N, friction_coefficient,
                                  RADIUS, OMEGA)
    for k, kind in enumerate(("normal", "superfluid")):
        final = continuum[-1][k]
        axis.plot(t_all[1:], [c[k] for c in continuum], "k" + ("-." if k else ":"),
                  label=f"two-fluid continuum, {kind}")
        axis.errorbar([5.0], [final], yerr=[0.1 * final], color="k", capsize=4)
        for name in GRIP:
            h = [r for r in history(runs / name) if r[1] == kind]
            axis.plot([r[0] for r in h], [r[2] for r in h], "os"[k], ms=3, mfc="none",
                      label=f"{name}, {kind}")
            report.append((f"{name}: {kind}'s slope at {h[-1][0]:.3g} s (continuum {final:.2f})",
                           f"{h[-1][2]:.3f} ({h[-1][2] / final - 1:+.1%})"))
    axis.set(xlabel="t (s)", ylabel="slope of |v| against r (rad/s)",
             title="wall-grip options against the two-fluid continuum")
    axis.legend(fontsize=6)
    save_figure(fig, out / "two_fluid_cylinder_grip.png")


def main():
    parser = figure_parser(__doc__, "out/two_fluid", REPO / "docs" / "figures", RUNS)
    args = parser.parse_args()
    names = chosen_runs(parser, args, RUNS)
    main_runs = [n for n in RUNS if n not in GRIP]
    return figure_script_main(
        args, {n: command(n) for n in names},
        [(main_runs, lambda runs, out, report: make_figures(runs, out, report, main_runs)),
         (list(GRIP), make_grip_figure)],
        "two_fluid_rotating_cylinder.md")


if __name__ == "__main__":
    sys.exit(main())
