#!/usr/bin/python3
"""The elastic-solid benchmarks of paper 2 (SHTC-SPH, §4.1-4.2) from revsph runs: CSV + figures.

Usage: /usr/bin/python3 tools/plots/shtc_solids.py [--runs DIR] [--out DIR] [--make-runs]
           [--revsph PATH] [--threads N]

  --runs DIR   where the runs live, one subdirectory per run (default: out/shtc)
  --out DIR    where the CSV files and figures go (default: docs/figures/shtc)
  --make-runs  first make every missing run (present = its summary.json exists), printing each
               revsph command; about 20 min on 2 cores in all
  --revsph     the revsph binary (default: build/bin/revsph, else build-*/bin/revsph)
  --threads N  passed to revsph (default: revsph's own, all cores)

Runs: beryllium-plate (§4.1, 9 611 particles, 33 165 steps), beryllium-plate-no-penalty (the
same with cp = 0), twisting-column (§4.2, 5 424 + 339 particles, 58 068 steps).

Writes:
  plate_centre.csv/.png    Fig. 2: y of the centre particle against time, with the sinusoid fitted
                           to it and the linear (Euler-Bernoulli) prediction y = Y sin(omega t)
                           of eqs. (55)-(56); the fitted period against 2 pi / omega and against
                           a Timoshenko beam of the model's own moduli (plane strain), solved here
                           by finite elements; and the continuum model itself, large deflections
                           and all, solved by finite elements (plate_fe.py), as the paper's
                           Fig. 2 shows a finite-volume run
  plate_energy.csv/.png    Fig. 3: kinetic, volumetric, shear and penalty energy over E(0), and
                           the relative total-energy error
  plate_penalty.png        Fig. 4: the plate at the end of the run, coloured by pressure, with and
                           without the tensile penalty
  column_energy.csv/.png   Fig. 6: the energies of the twisting column, and the relative error
  column_top.csv/.png      Fig. 7: z / H of the particle that starts at the top centre, and the
                           angular momentum L_z of the column (its sign change is the rotation
                           reversing)
  shtc_solids.md           the numbers printed below, as a table
Exit status 0 only if every figure was made.
"""

import sys

import plate_fe
from revsph_runs import (case_of, figure_parser, figure_script_main, fit_sinusoid, read_csv,
                         save_figure, write_csv)

import matplotlib

matplotlib.use("Agg")
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

DPI = 110
RUNS = {
    "beryllium-plate": ["run", "beryllium-plate"],
    "beryllium-plate-no-penalty": ["run", "beryllium-plate", "--set", "penalty.speed=0"],
    "twisting-column": ["run", "twisting-column"],
}


def last_snapshot(run):
    path = sorted((run / "snapshots").glob("step_*.h5"))[-1]
    with h5py.File(path) as f:
        position = f["particles/material/position"][...]
        pressure = f["particles/material/pressure"][...]
        time = float(f.attrs["time"])
    return position, pressure, time


def timoshenko_free_free(length, thickness, density, young, shear_modulus, elements=400):
    """First elastic angular frequency of a free-free Timoshenko beam (per unit depth), linear
    finite elements with one-point (reduced) shear integration against shear locking."""
    area, inertia, kappa = thickness, thickness**3 / 12.0, 5.0 / 6.0
    h = length / elements
    n = 2 * (elements + 1)  # (w, theta) per node
    stiffness, mass = np.zeros((n, n)), np.zeros((n, n))
    bending = young * inertia / h * np.array([[0, 0, 0, 0], [0, 1, 0, -1], [0, 0, 0, 0],
                                              [0, -1, 0, 1]])
    # Shear strain gamma = w' - theta at the element centre: [-1/h, -1/2, 1/h, -1/2] . (w1 t1 w2 t2)
    g = np.array([-1.0 / h, -0.5, 1.0 / h, -0.5])
    shear = kappa * shear_modulus * area * h * np.outer(g, g)
    consistent = h / 6.0 * np.array([[2, 1], [1, 2]])
    element_mass = np.zeros((4, 4))
    element_mass[np.ix_([0, 2], [0, 2])] = density * area * consistent
    element_mass[np.ix_([1, 3], [1, 3])] = density * inertia * consistent
    for e in range(elements):
        index = np.arange(2 * e, 2 * e + 4)
        stiffness[np.ix_(index, index)] += bending + shear
        mass[np.ix_(index, index)] += element_mass
    cholesky = np.linalg.cholesky(mass)
    inverse = np.linalg.inv(cholesky)
    eigenvalues = np.linalg.eigvalsh(inverse @ stiffness @ inverse.T)  # ascending
    return np.sqrt(eigenvalues[2])  # after the two rigid modes (translation, rotation)


def plate_period(run):
    """The centre point's y(t) of a plate run and the sinusoid fitted to it: (t, y, fitted angular
    frequency, coefficients of c + a sin + b cos)."""
    case = case_of(run)
    diagnostics = read_csv(run / "diagnostics.csv")
    t, y = diagnostics["time"], diagnostics["probe_y"]
    omega = case["initial"]["omega"]
    fitted, coefficients, _ = fit_sinusoid(t, y, np.linspace(0.7 * omega, 1.3 * omega, 6001))
    return t, y, fitted, coefficients


def model_timoshenko(case):
    """First free-free angular frequency of a Timoshenko beam with the model's small-strain
    moduli: shear mu = rho0 cs^2, bulk K = rho0 c0^2 (eqs. 29, 31); plane strain (2D runs keep
    A33 = 1): E' = E / (1 - nu^2)."""
    material = case["material"]
    rho0 = material["rest_density"]
    mu = rho0 * material["shear_speed"] ** 2
    bulk = rho0 * material["sound_speed"] ** 2
    young = 9.0 * bulk * mu / (3.0 * bulk + mu)
    poisson = (3.0 * bulk - 2.0 * mu) / (2.0 * (3.0 * bulk + mu))
    plane_strain = young / (1.0 - poisson**2)
    # The plate of eqs. (54)-(55): L = 2 |x0|, W the lattice block's height (its length is the
    # lattice's, half a spacing longer than L; models/shtc/cases/beryllium-plate.toml).
    block = case["particles"][0]
    length, thickness = 2.0 * abs(case["initial"]["x0"]), block["max"][1] - block["min"][1]
    return timoshenko_free_free(length, thickness, rho0, plane_strain, mu)


def plate_figures(runs, out, report):
    run = runs / "beryllium-plate"
    case = case_of(run)
    initial = case["initial"]
    t, y, fitted, coefficients = plate_period(run)
    omega = initial["omega"]
    # Linear prediction at the probe particle: y = A (a1 (sinh s + sin s) - a2 (cosh s + cos s))
    # sin(omega t), s = alpha (x - x0), the displacement whose rate is eq. (55).
    x_probe = read_csv(run / "diagnostics.csv")["probe_x"][0]
    mode = plate_fe.mode_shape(x_probe, initial)
    linear = initial["amplitude"] * mode * np.sin(omega * t)
    timoshenko = model_timoshenko(case)
    period = 2.0 * np.pi / fitted
    report.append(("plate: fitted period of the centre point (s)", f"{period:.5e}"))
    report.append(("plate: linear theory 2 pi / omega, eq. (56) (s)",
                   f"{2 * np.pi / omega:.5e} ({period * omega / (2 * np.pi) - 1:+.2%})"))
    report.append(("plate: Timoshenko beam, model moduli, plane strain (s)",
                   f"{2 * np.pi / timoshenko:.5e} ({period * timoshenko / (2 * np.pi) - 1:+.2%})"))
    report.append(("plate: fitted amplitude / linear amplitude",
                   f"{np.hypot(*coefficients[1:]):.4e} m / {abs(initial['amplitude'] * mode):.4e} m"))
    # The paper's Fig. 2 compares with a finite-volume run [17]; here the reference is the same
    # continuum model solved by finite elements (plate_fe.py; Q2 24 x 4 is converged to 0.01 %).
    continuum_t, continuum_y, _, _ = plate_fe.solve(24, 4, initial["amplitude"])
    continuum_period = plate_fe.period_of(continuum_t, continuum_y)[0]
    continuum = np.interp(t, continuum_t, continuum_y)
    report.append(("plate: the continuum model (finite elements, plate_fe.py): period (s), "
                   "against eq. (56); SHTC-SPH against it",
                   f"{continuum_period:.5e}, {continuum_period * omega / (2 * np.pi) - 1:+.2%}; "
                   f"{period / continuum_period - 1:+.2%}"))
    report.append(("plate: largest |y_SPH - y_continuum| over the run / largest |y| (m)",
                   f"{np.max(np.abs(y - continuum)):.3e} / {np.max(np.abs(continuum)):.3e}"))
    write_csv(out / "plate_centre.csv", {"time": t, "y": y, "fitted": coefficients[0] +
                                         coefficients[1] * np.sin(fitted * t) +
                                         coefficients[2] * np.cos(fitted * t), "linear": linear,
                                         "continuum_model": continuum})
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(t * 1e6, y * 1e3, color="tab:orange", lw=2, label="revsph (SHTC-SPH)")
    ax.plot(t * 1e6, (coefficients[0] + coefficients[1] * np.sin(fitted * t) +
                      coefficients[2] * np.cos(fitted * t)) * 1e3, "k:",
            label=f"fitted sinusoid, period {period * 1e6:.3f} µs")
    ax.plot(t * 1e6, linear * 1e3, color="tab:blue", ls="--",
            label=f"linear theory eq. (56), period {2e6 * np.pi / omega:.3f} µs")
    every = max(1, len(continuum_t) // 60)
    ax.plot(continuum_t[::every] * 1e6, continuum_y[::every] * 1e3, "s", color="tab:blue",
            ms=4, mfc="none", label=f"the continuum model, finite elements (plate_fe.py), period "
            f"{continuum_period * 1e6:.3f} µs")
    ax.plot(t * 1e6, initial["amplitude"] * mode * omega / timoshenko * np.sin(timoshenko * t) * 1e3,
            color="tab:green", ls="-.",
            label=f"Timoshenko beam of the model's moduli, period {2e6 * np.pi / timoshenko:.3f} µs")
    ax.set_xlabel("t (µs)")
    ax.set_ylabel("y of the centre point (mm)")
    ax.set_title("Beryllium plate (paper 2, Fig. 2), dr = W/40")
    ax.legend(fontsize=7, loc="lower left")
    save_figure(fig, out / "plate_centre.png", DPI)

    energy = read_csv(run / "energy.csv")
    energy_figure(energy, out / "plate_energy", "Beryllium plate (paper 2, Fig. 3)", report,
                  "plate")

    fig, axes = plt.subplots(2, 1, figsize=(8, 5.5), sharex=True)
    for ax, name, title in zip(axes, ["beryllium-plate", "beryllium-plate-no-penalty"],
                               ["with the tensile penalty (cp = 10 c0)", "without (cp = 0)"]):
        position, pressure, time = last_snapshot(runs / name)
        limit = np.percentile(np.abs(pressure), 99)
        scatter = ax.scatter(position[:, 0] * 1e3, position[:, 1] * 1e3, c=pressure, s=0.6,
                             cmap="coolwarm", vmin=-limit, vmax=limit)
        ax.set_aspect("equal")
        ax.set_ylabel("y (mm)")
        ax.set_title(f"{title}, t = {time * 1e6:.1f} µs", fontsize=9)
        fig.colorbar(scatter, ax=ax, label="pressure (Pa)", shrink=0.8)
        spread = nearest_neighbour_spread(position)
        report.append((f"plate {title}: nearest-neighbour distance, 1st/50th percentile (m)",
                       f"{spread[0]:.3e} / {spread[1]:.3e}"))
    axes[-1].set_xlabel("x (mm)")
    fig.suptitle("Beryllium plate (paper 2, Fig. 4): tensile instability")
    save_figure(fig, out / "plate_penalty.png", DPI)


def nearest_neighbour_spread(position):
    """1st and 50th percentile of the distance to the nearest other particle: clumping pulls the
    1st percentile far below the lattice spacing."""
    points = position  # (particles, D)
    nearest = np.empty(len(points))
    for i in range(0, len(points), 512):
        block = points[i:i + 512]
        distance = np.sqrt(((block[:, None, :] - points[None, :, :]) ** 2).sum(axis=2))
        distance[np.arange(len(block)), np.arange(i, i + len(block))] = np.inf
        nearest[i:i + len(block)] = distance.min(axis=1)
    return np.percentile(nearest, 1), np.percentile(nearest, 50)


def energy_figure(energy, stem, title, report, what):
    total0 = energy["total"][0]
    columns = {"time": energy["time"]}
    for name in ("kinetic", "volumetric", "shear", "penalty", "total"):
        columns[name + "_over_E0"] = energy[name] / total0
    columns["relative_error"] = energy["relative_error"]
    write_csv(stem.with_suffix(".csv"), columns)
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 5.5), sharex=True)
    for name in ("kinetic", "volumetric", "shear", "penalty"):
        top.plot(energy["time"], energy[name] / total0, label=name)
    top.set_ylabel("energy / E(0)")
    top.legend(fontsize=8)
    top.set_title(title)
    bottom.plot(energy["time"], (energy["total"] - total0) / total0, color="k")
    bottom.set_ylabel("(E - E(0)) / E(0)")
    bottom.set_xlabel("t (s)")
    save_figure(fig, stem.with_suffix(".png"), DPI)
    report.append((f"{what}: max relative total-energy error",
                   f"{np.max(np.abs(energy['relative_error'])):.3e}"))


def column_figures(runs, out, report):
    run = runs / "twisting-column"
    case = case_of(run)
    height = case["initial"]["height"]
    energy = read_csv(run / "energy.csv")
    energy_figure(energy, out / "column_energy", "Twisting column (paper 2, Fig. 6)", report,
                  "column")
    diagnostics = read_csv(run / "diagnostics.csv")
    t, z, spin = diagnostics["time"], diagnostics["probe_z"], diagnostics["angular_momentum_z"]
    write_csv(out / "column_top.csv", {"time": t, "z_over_H": z / height,
                                       "angular_momentum_z": spin})
    reversal = t[np.argmax(np.sign(spin) != np.sign(spin[0]))] if np.any(
        np.sign(spin) != np.sign(spin[0])) else float("nan")
    lowest = int(np.argmin(z))
    report.append(("column: first sign change of L_z (rotation reverses) (s)", f"{reversal:.4f}"))
    report.append(("column: lowest z / H of the top point, and when (s)",
                   f"{z[lowest] / height:.4f} at t = {t[lowest]:.4f}"))
    report.append(("column: z / H at the end of the run",
                   f"{z[-1] / height:.4f} at t = {t[-1]:.4f}"))
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 5.5), sharex=True)
    top.plot(t, z / height, color="tab:orange")
    top.set_ylabel("z / H of the top point")
    top.set_title("Twisting column (paper 2, Fig. 7)")
    bottom.plot(t, spin, color="tab:green")
    bottom.axhline(0.0, color="k", lw=0.5)
    bottom.set_ylabel("L_z (kg m²/s)")
    bottom.set_xlabel("t (s)")
    save_figure(fig, out / "column_top.png", DPI)


def main():
    return figure_script_main(
        figure_parser(__doc__).parse_args(), RUNS,
        [(["beryllium-plate", "beryllium-plate-no-penalty"], plate_figures),
         (["twisting-column"], column_figures)],
        "shtc_solids.md")


if __name__ == "__main__":
    sys.exit(main())
