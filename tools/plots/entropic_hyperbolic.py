#!/usr/bin/python3
"""Paper 4's hyperbolic heat conduction (Pavelka, Klika, Kincl 2024, §5.5, Figs. 13-14) and the
speed of its heat waves against the linear theory of the discrete model.

Usage: /usr/bin/python3 tools/plots/entropic_hyperbolic.py [--make-runs] [--runs DIR] [--out DIR]
           [--revsph PATH] [--threads N]

--make-runs runs models/entropic/cases/hyperbolic.toml into RUNS/hyperbolic (default RUNS =
out/entropic; about 2 minutes on 2 threads). Writes into --out (default docs/figures):
  entropic_hyperbolic.png        Fig. 13: the temperature at four times; Fig. 14: the relative
                                 total-energy error and the total entropy; the fundamental mode
                                 of the temperature profile with its fit.
  entropic_hyperbolic_mode.csv   t, the mode amplitude A1 and the fitted damped cosine.
  entropic_hyperbolic_energy.csv t, relative energy error, total entropy, entropy-flux energy.
  entropic_hyperbolic.md         the measured and predicted numbers (also printed).

Linear theory of the discrete model (models/entropic/README.md): on a square lattice of particles
at rest with volume V, mass m, temperature T0, put S_a = S0 + S^ e^(i k.x_a), w_a = w^ e^(i k.x_a)
into eq. (68). With g(k) = sum_b sin(k.r_b) (W'(r_b)/r_b) r_b over the neighbours b of a particle,
  d S^/dt = i 2 c_w V^2 g.w^,   d w^/dt = i V kappa g S^ - Gamma w^,   kappa = dT/dS = T0/(m c_V),
where Gamma = 2 c_w V / tau is the relaxation of eq. (69). So S^'' + Gamma S^' + omega^2 S^ = 0
with omega(k)^2 = 2 c_w V^3 kappa |g(k)|^2: heat waves of speed c(k) = omega(k)/|k|, which tends
to sqrt(2 c_w T0 / (rho c_V)) for long waves (g -> -k/V), damped at Gamma/2, oscillating at
Omega = sqrt(omega^2 - Gamma^2/4). The walls are adiabatic, so the initial linear profile along x
holds the cosine modes cos(n pi x / L), n odd; the fit follows the fundamental n = 1.
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
    REPO, case_of, figure_parser, figure_script_main, read_csv, save_figure, snapshots, write_csv)

RUNS = {"hyperbolic": ["run", str(REPO / "models/entropic/cases/hyperbolic.toml")]}


def kernel_slope_over_r(r, h):
    """W'(r)/r of the 2D Wendland quintic with support radius h (core/kernel_wendland.hpp)."""
    q = r / h
    return np.where(q < 1.0, -140.0 / (np.pi * h**4) * (1.0 - q) ** 3, 0.0)


def lattice_g(k, dr, h):
    """g(k) = sum_b sin(k.r_b) (W'(r_b)/r_b) r_b over a square lattice (vector, 2D)."""
    n = int(np.ceil(h / dr)) + 1
    i, j = np.meshgrid(np.arange(-n, n + 1), np.arange(-n, n + 1), indexing="ij")
    rx, ry = (i * dr).ravel(), (j * dr).ravel()
    r = np.hypot(rx, ry)
    keep = r > 0
    rx, ry, r = rx[keep], ry[keep], r[keep]
    weight = np.sin(k[0] * rx + k[1] * ry) * kernel_slope_over_r(r, h)
    return np.array([np.sum(weight * rx), np.sum(weight * ry)])


def row_frequency(k, dr, h, volumes, kappas, c_w):
    """omega(k) of the fundamental mode exp(i k x) in a body of rows y_j = (j + 1/2) dr between
    adiabatic walls (periodic along x; the walls along x change it by less than 1e-3, measured
    by doubling L): eq. (68) linearised with each row's own volume V_j and kappa_j,
      w_j' = sum V_j' (kappa_j S_j - kappa_j' S_j' e^(-i k r_x)) F(r) r,
      S_j' = -2 c_w sum V_j V_j' (w_j + w_j' e^(-i k r_x)) . F(r) r,
    F = W'(r)/r, r = x_a - x_b over the pairs of gas particles. The rows near the walls miss
    neighbours, which slows the waves there by O(h / height)."""
    rows = len(volumes)
    reach = int(np.ceil(h / dr))
    from_w = np.zeros((rows, 2 * rows), dtype=complex)  # S rates from (w_x, w_y) per row
    from_s = np.zeros((2 * rows, rows), dtype=complex)  # w rates from S per row
    for j in range(rows):
        for dj in range(-reach, reach + 1):
            jj = j + dj
            if jj < 0 or jj >= rows:
                continue
            for di in range(-reach, reach + 1):
                if di == 0 and dj == 0:
                    continue
                r = np.array([-di * dr, -dj * dr])  # x_a - x_b with b at (di, dj) from a
                distance = np.hypot(*r)
                if distance >= h:
                    continue
                f = kernel_slope_over_r(distance, h)
                phase = np.exp(-1j * k * r[0])
                for axis in range(2):
                    from_s[2 * j + axis, j] += volumes[jj] * kappas[j] * f * r[axis]
                    from_s[2 * j + axis, jj] -= volumes[jj] * kappas[jj] * phase * f * r[axis]
                    from_w[j, 2 * j + axis] -= 2 * c_w * volumes[j] * volumes[jj] * f * r[axis]
                    from_w[j, 2 * jj + axis] -= (2 * c_w * volumes[j] * volumes[jj] * phase
                                                 * f * r[axis])
    values, vectors = np.linalg.eig(from_w @ from_s)
    overlap = np.abs(vectors.sum(axis=0)) / np.linalg.norm(vectors, axis=0)
    fundamental = np.argmax(overlap)
    return float(np.sqrt(-values[fundamental].real))


def read_snapshot(path):
    with h5py.File(path) as f:
        gas = f["particles/gas"]
        return {
            "time": float(f.attrs["time"]),
            "x": gas["position"][:, 0],
            "y": gas["position"][:, 1],
            "temperature": gas["temperature"][:],
            "volume": gas["volume"][:],
        }


def fit_damped_cosine(t, y):
    """y = e^(-G t / 2) (a cos(W t) + b sin(W t)): best (W, G, a, b) by nested grid refinement
    with a, b by linear least squares."""

    def residual(w, g):
        envelope = np.exp(-0.5 * g * t)
        basis = np.c_[envelope * np.cos(w * t), envelope * np.sin(w * t)]
        coefficients = np.linalg.lstsq(basis, y, rcond=None)[0]
        return np.sum((basis @ coefficients - y) ** 2), coefficients

    w_range, g_range = (0.2, 20.0), (0.0, 10.0)
    best = None
    for _ in range(12):
        ws = np.linspace(*w_range, 41)
        gs = np.linspace(*g_range, 41)
        for w in ws:
            for g in gs:
                value, coefficients = residual(w, g)
                if best is None or value < best[0]:
                    best = (value, w, g, coefficients)
        dw, dg = (ws[1] - ws[0]) * 2, (gs[1] - gs[0]) * 2
        w_range = (max(best[1] - dw, 1e-6), best[1] + dw)
        g_range = (max(best[2] - dg, 0.0), best[2] + dg)
    value, w, g, (a, b) = best
    return w, g, a, b, np.sqrt(value / len(t))


def make_figures(runs, out, report):
    run = runs / "hyperbolic"
    case = case_of(run)
    paths = snapshots(run)
    frames = [read_snapshot(p) for p in paths]
    dr = case["discretisation"]["dr"]
    h = case["discretisation"]["support_radius_over_dr"] * dr
    c_w = case["hyperbolic_heat"]["energy_coefficient"]
    tau = case["hyperbolic_heat"].get("relaxation_time", np.inf)
    c_v = case["physics"]["heat_capacity"]
    rho = case["initial"]["density"]
    box_min = case["particles"][0]["min"]
    box_max = case["particles"][0]["max"]
    length = box_max[0] - box_min[0]

    first = frames[0]
    t0 = float(np.mean(first["temperature"]))
    # The particles' volume m / rho with rho the kernel sum (not rho0: on the lattice sum_b W_ab
    # is 0.5 % above 1 / dr^2 at h = 3 dr), in the interior, away from the walls.
    interior = ((first["x"] > box_min[0] + h) & (first["x"] < box_max[0] - h)
                & (first["y"] > box_min[1] + h) & (first["y"] < box_max[1] - h))
    volume = float(np.mean(first["volume"][interior]))
    mass = rho * dr * dr
    kappa = t0 / (mass * c_v)
    k1 = np.array([np.pi / length, 0.0])
    omega = np.sqrt(2.0 * c_w * volume**3 * kappa) * np.linalg.norm(lattice_g(k1, dr, h))
    gamma = 2.0 * c_w * volume / tau
    speed_continuum = np.sqrt(2.0 * c_w * t0 / (rho * c_v))
    speed_discrete = omega / k1[0]
    # The same with the rows of the body, their volumes and temperatures as they are.
    row = np.rint((first["y"] - box_min[1]) / dr - 0.5).astype(int)
    rows = row.max() + 1
    row_volume = np.array([np.mean(first["volume"][row == j]) for j in range(rows)])
    row_kappa = np.array([np.mean(first["temperature"][row == j]) for j in range(rows)]) / (
        mass * c_v)
    omega_rows = row_frequency(k1[0], dr, h, row_volume, row_kappa, c_w)
    speed_rows = omega_rows / k1[0]
    omega_damped = np.sqrt(omega_rows**2 - 0.25 * gamma**2)

    # The fundamental mode of the temperature profile: A1 = <T cos(pi x / L)> / <cos^2>.
    times, amplitudes = [], []
    for frame in frames:
        c = np.cos(np.pi * (frame["x"] - box_min[0]) / length)
        weights = frame["volume"]
        amplitudes.append(np.sum(weights * frame["temperature"] * c) / np.sum(weights * c * c))
        times.append(frame["time"])
    times, amplitudes = np.array(times), np.array(amplitudes)
    w_fit, g_fit, a, b, rms = fit_damped_cosine(times, amplitudes)
    fitted = np.exp(-0.5 * g_fit * times) * (a * np.cos(w_fit * times) + b * np.sin(w_fit * times))
    speed_measured = np.sqrt(w_fit**2 + 0.25 * g_fit**2) / k1[0]
    write_csv(out / "entropic_hyperbolic_mode.csv",
              {"time": times, "mode_amplitude": amplitudes, "fit": fitted})

    energy = read_csv(run / "energy.csv")
    diagnostics = read_csv(run / "diagnostics.csv")
    entropy = diagnostics["entropy"]
    write_csv(out / "entropic_hyperbolic_energy.csv",
              {"time": energy["time"], "relative_energy_error": energy["relative_error"],
               "entropy": entropy, "entropy_flux_energy": energy["entropy_flux"]})
    steps = np.diff(entropy)

    fig = plt.figure(figsize=(15, 8))
    picks = [0, len(frames) // 8, len(frames) // 4, len(frames) // 2]
    for panel, index in enumerate(picks):
        ax = fig.add_subplot(3, 4, panel + 1)
        frame = frames[index]
        scatter = ax.scatter(frame["x"], frame["y"], c=frame["temperature"], s=1.0,
                             cmap="inferno", vmin=t0 - 10.5, vmax=t0 + 10.5)
        ax.set_aspect("equal")
        ax.set_title(f"t = {frame['time']:.2f} s")
        ax.set_xticks([])
        ax.set_yticks([])
    fig.colorbar(scatter, ax=fig.axes[3], label="T (K)")
    ax = fig.add_subplot(3, 2, 3)
    ax.plot(energy["time"], energy["relative_error"], color="tab:blue")
    ax.set_ylabel("(E - E0) / E0")
    ax.set_title("Fig. 14: total energy error")
    ax = fig.add_subplot(3, 2, 4)
    ax.plot(diagnostics["time"], entropy - entropy[0], color="tab:red")
    ax.set_ylabel("S - S0 (J/(K m))")
    ax.set_title("Fig. 14: total entropy")
    ax = fig.add_subplot(3, 1, 3)
    ax.plot(times, amplitudes, "o", markersize=3, label="measured mode cos(pi x / L)")
    ax.plot(times, fitted, "-", label=f"fit: Omega = {w_fit:.4f} /s, Gamma = {g_fit:.4f} /s")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("A1 (K)")
    ax.legend()
    for ax in fig.axes[5:]:
        ax.grid(True, alpha=0.3)
    save_figure(fig, out / "entropic_hyperbolic.png")

    report += [
        ("particles, dr, h, dt", f"{len(first['x'])}, {dr}, {h:.4g}, {case_dt(run):.4g} s"),
        ("T0 (mean initial temperature)", f"{t0:.6g} K"),
        ("V (interior mean of m / rho) / dr^2", f"{volume / dr**2:.6g}"),
        ("wave speed, continuum sqrt(2 c_w T0/(rho c_V))", f"{speed_continuum:.6g} m/s"),
        ("wave speed, discrete model, unbounded lattice, k1 = pi/L", f"{speed_discrete:.6g} m/s"),
        ("wave speed, discrete model, the body's rows between walls", f"{speed_rows:.6g} m/s"),
        ("wave speed, measured sqrt(Omega^2 + Gamma^2/4)/k1", f"{speed_measured:.6g} m/s"),
        ("measured / discrete theory (rows)", f"{speed_measured / speed_rows:.5f}"),
        ("measured / discrete theory (unbounded)", f"{speed_measured / speed_discrete:.5f}"),
        ("Omega: measured, theory", f"{w_fit:.5g} /s, {omega_damped:.5g} /s"),
        ("Gamma: measured, theory 2 c_w V / tau", f"{g_fit:.5g} /s, {gamma:.5g} /s"),
        ("fit rms / initial amplitude", f"{rms / abs(amplitudes[0]):.3g}"),
        ("max |relative energy error|", f"{np.max(np.abs(energy['relative_error'])):.3g}"),
        ("entropy gain S(end) - S(0)", f"{entropy[-1] - entropy[0]:.6g} J/(K m)"),
        ("smallest entropy change between outputs", f"{steps.min():.3g} J/(K m)"),
    ]


def case_dt(run):
    import json

    return json.loads((run / "summary.json").read_text())["dt"]


def main():
    parser = figure_parser(__doc__, "out/entropic", REPO / "docs" / "figures")
    args = parser.parse_args()
    return figure_script_main(args, RUNS, [(["hyperbolic"], make_figures)],
                              "entropic_hyperbolic.md")


if __name__ == "__main__":
    sys.exit(main())
