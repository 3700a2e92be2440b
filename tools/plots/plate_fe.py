#!/usr/bin/python3
"""An independent reference for the beryllium plate (paper 2, §4.1): the same continuum model,
solved by finite elements instead of SPH.

The plate of SHTC-SPH is elastic (tau = infinity), so its distortion is the inverse deformation
gradient, A = F^-1 (dA/dt = -A L and d(F^-1)/dt = -F^-1 L, A = I at t = 0). The model is then a
hyperelastic solid with the stored energy per unit reference volume
    W(F) = rho0 [ c0^2 / 2 (J - 1)^2 + cs^2 / 4 |dev(A^T A)|_F^2 ],   J = det F,
eqs. (29) (with rho0 / rho = J) and (31), in plane strain (F33 = 1, as the SPH code's A33 = 1).
This script solves that solid in the total Lagrangian form with 9-node quadrilaterals (Q2,
3 x 3 Gauss points), a row-sum lumped mass matrix and the leapfrog (velocity Verlet) scheme,
starting from the velocity of eq. (55). Large deflections and the energy's nonlinearity are
kept in full: nothing is linearised. Nothing of the SPH code is used, so where the SHTC-SPH run
and this one agree, the plate's motion is the model's, not the particles'.

Run: /usr/bin/python3 tools/plots/plate_fe.py [--out docs/figures/shtc] [--runs out/shtc]  (~1 h)
  Mesh and time-step study at eq. (56)'s amplitude A and at A/10 and A/2; the centre point's
  period (sinusoid fitted over t <= 3e-5 s, as for the SPH runs: shtc_solids.plate_period);
  energy conservation; figure plate_fe.png (with the SPH centre point if --runs holds the
  beryllium-plate run), plate_fe.csv and plate_fe.md in --out.
"""

import argparse
import math
import sys
import tomllib
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from revsph_runs import fit_sinusoid, read_csv, save_figure, write_csv  # noqa: E402

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# The plate of the beryllium-plate case (Table 1, eqs. 54-57): L = 2 |x0| (s = alpha (x - x0)
# starts at the left end), W the height of its particle block.
CASE_FILE = Path(__file__).resolve().parents[2] / "models" / "shtc" / "cases" / "beryllium-plate.toml"
with CASE_FILE.open("rb") as case_file:
    CASE = tomllib.load(case_file)
X0 = CASE["initial"]["x0"]
LENGTH = 2.0 * abs(X0)
THICKNESS = CASE["particles"][0]["max"][1] - CASE["particles"][0]["min"][1]
DENSITY = CASE["material"]["rest_density"]
C0, CS = CASE["material"]["sound_speed"], CASE["material"]["shear_speed"]
AMPLITUDE, OMEGA = CASE["initial"]["amplitude"], CASE["initial"]["omega"]
T_END = CASE["run"]["t_end"]


def embed(f):
    """In-plane deformation gradients (..., 2, 2) as 3 x 3 with F33 = 1 (plane strain)."""
    full = np.zeros(f.shape[:-2] + (3, 3))
    full[..., :2, :2] = f
    full[..., 2, 2] = 1.0
    return full


def stored_energy(f):
    """W(F) per unit reference volume, eqs. (29), (31) with A = F^-1."""
    full = embed(f)
    a = np.linalg.inv(full)
    g = np.swapaxes(a, -1, -2) @ a
    dev = g - np.trace(g, axis1=-2, axis2=-1)[..., None, None] / 3.0 * np.eye(3)
    j = np.linalg.det(full)
    return DENSITY * (0.5 * C0**2 * (j - 1.0) ** 2 + 0.25 * CS**2 * np.sum(dev * dev, axis=(-2, -1)))


def first_piola(f):
    """P = dW/dF (in-plane block). With G = A^T A, D = dev G and dG = -A^T dF^T G - G dF A:
    d(cs^2/4 D:D) = cs^2/2 D:dG = -cs^2 (G D A^T):dF; d(c0^2/2 (J-1)^2) = c0^2 (J-1) J A^T:dF."""
    full = embed(f)
    a = np.linalg.inv(full)
    a_t = np.swapaxes(a, -1, -2)
    g = a_t @ a
    dev = g - np.trace(g, axis1=-2, axis2=-1)[..., None, None] / 3.0 * np.eye(3)
    j = np.linalg.det(full)
    p = DENSITY * (C0**2 * ((j - 1.0) * j)[..., None, None] * a_t - CS**2 * g @ dev @ a_t)
    return p[..., :2, :2]


def check_stress(samples=20, seed=1):
    """P against central differences of W at random large deformations: the stress the solver
    uses is the derivative of the energy it reports, or the script stops."""
    rng = np.random.default_rng(seed)
    f = np.eye(2) + 0.3 * rng.standard_normal((samples, 2, 2))
    f[np.linalg.det(f) < 0.3] = np.eye(2)
    step = 1e-6
    numeric = np.zeros_like(f)
    for i in range(2):
        for k in range(2):
            e = np.zeros((2, 2))
            e[i, k] = step
            numeric[:, i, k] = (stored_energy(f + e) - stored_energy(f - e)) / (2.0 * step)
    scale = DENSITY * C0**2
    error = np.max(np.abs(numeric - first_piola(f))) / scale
    if error > 1e-7:
        raise SystemExit(f"plate_fe: dW/dF does not match the energy (relative error {error:.2e})")
    return error


def quadratic_shape(xi):
    """1D quadratic Lagrange functions on nodes -1, 0, 1 and their derivatives."""
    return (np.array([0.5 * xi * (xi - 1.0), 1.0 - xi * xi, 0.5 * xi * (xi + 1.0)]),
            np.array([xi - 0.5, -2.0 * xi, xi + 0.5]))


class PlateMesh:
    """Q2 mesh of (-L/2, L/2) x (-W/2, W/2): nx x ny elements, (2 nx + 1) x (2 ny + 1) nodes."""

    def __init__(self, nx, ny):
        self.nx, self.ny = nx, ny
        self.columns, self.rows = 2 * nx + 1, 2 * ny + 1
        x = np.linspace(-0.5 * LENGTH, 0.5 * LENGTH, self.columns)
        y = np.linspace(-0.5 * THICKNESS, 0.5 * THICKNESS, self.rows)
        self.reference = np.stack(np.meshgrid(x, y, indexing="xy"), axis=-1).reshape(-1, 2)
        ex, ey = np.meshgrid(np.arange(nx), np.arange(ny), indexing="xy")
        local = [(i, j) for j in range(3) for i in range(3)]  # node (i, j) of an element
        self.connectivity = np.stack(
            [(2 * ey.ravel() + j) * self.columns + 2 * ex.ravel() + i for i, j in local], axis=1)
        # All elements are the same rectangle: one table of shape-function gradients.
        hx, hy = LENGTH / nx, THICKNESS / ny
        points, weights = np.polynomial.legendre.leggauss(3)
        gradients, volumes, values = [], [], []
        for qy, wy in zip(points, weights):
            for qx, wx in zip(points, weights):
                nxv, dnx = quadratic_shape(qx)
                nyv, dny = quadratic_shape(qy)
                gradients.append([[dnx[i] * nyv[j] * 2.0 / hx, nxv[i] * dny[j] * 2.0 / hy]
                                  for i, j in local])
                values.append([nxv[i] * nyv[j] for i, j in local])
                volumes.append(wx * wy * hx * hy / 4.0)
        self.gradients = np.array(gradients)  # (gauss point, node, 2)
        self.volumes = np.array(volumes)
        element_mass = DENSITY * np.einsum("q,qa,qb->ab", self.volumes, np.array(values),
                                           np.array(values))
        lumped = element_mass.sum(axis=1)  # row sums: 1/36, 1/9, 4/9 of the element: positive
        self.mass = np.bincount(self.connectivity.ravel(), np.tile(lumped, nx * ny),
                                minlength=len(self.reference))
        self.node_spacing = min(hx, hy) / 2.0
        self.centre = (self.rows // 2) * self.columns + self.columns // 2

    def deformation_gradients(self, position):
        return np.einsum("eni,qnj->eqij", position[self.connectivity], self.gradients)

    def forces(self, position):
        """Nodal forces -dE/dx and the stored energy."""
        f = self.deformation_gradients(position)
        stress = first_piola(f)
        element = -np.einsum("q,eqij,qnj->eni", self.volumes, stress, self.gradients)
        force = np.zeros_like(position)
        for i in range(2):
            force[:, i] = np.bincount(self.connectivity.ravel(), element[..., i].ravel(),
                                      minlength=len(position))
        energy = np.einsum("q,eq->", self.volumes, stored_energy(f))
        return force, energy


def mode_shape(x, initial=CASE["initial"]):
    """The first free-free mode of eqs. (55)-(56): a1 (sinh s + sin s) - a2 (cosh s + cos s),
    s = alpha (x - x0); the linear displacement is A mode_shape(x) sin(omega t)."""
    s = initial["alpha"] * (np.asarray(x) - initial["x0"])
    return initial["a1"] * (np.sinh(s) + np.sin(s)) - initial["a2"] * (np.cosh(s) + np.cos(s))


def initial_velocity(reference, amplitude):
    """Eq. (55): v_y = A omega mode_shape(x)."""
    velocity = np.zeros_like(reference)
    velocity[:, 1] = amplitude * OMEGA * mode_shape(reference[:, 0])
    return velocity


def solve(nx, ny, amplitude, courant=0.2):
    """Leapfrog from eq. (55) until T_END. dt = courant x node spacing / longitudinal speed.
    Returns t, the centre point's y and the total energy at every step."""
    mesh = PlateMesh(nx, ny)
    dt_limit = courant * mesh.node_spacing / math.sqrt(C0**2 + 4.0 / 3.0 * CS**2)
    steps = math.ceil(T_END / dt_limit)
    dt = T_END / steps
    position = mesh.reference.copy()
    velocity = initial_velocity(mesh.reference, amplitude)
    force, stored = mesh.forces(position)
    t, centre, energy = [0.0], [position[mesh.centre, 1]], []
    energy.append(stored + 0.5 * np.sum(mesh.mass[:, None] * velocity**2))
    inverse_mass = 1.0 / mesh.mass[:, None]
    for step in range(1, steps + 1):
        velocity += 0.5 * dt * force * inverse_mass
        position += dt * velocity
        force, stored = mesh.forces(position)
        velocity += 0.5 * dt * force * inverse_mass
        t.append(step * dt)
        centre.append(position[mesh.centre, 1])
        energy.append(stored + 0.5 * np.sum(mesh.mass[:, None] * velocity**2))
    return np.array(t), np.array(centre), np.array(energy), dt


def period_of(t, y):
    fitted, coefficients, _ = fit_sinusoid(t, y, np.linspace(0.7 * OMEGA, 1.3 * OMEGA, 6001))
    return 2.0 * math.pi / fitted, coefficients


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default="docs/figures/shtc", help="output directory")
    parser.add_argument("--runs", default="out/shtc",
                        help="SHTC-SPH runs to compare with (beryllium-plate, if present)")
    parser.add_argument("--quick", action="store_true", help="coarse meshes only (a smoke run)")
    args = parser.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    stress_error = check_stress()
    linear_period = 2.0 * math.pi / OMEGA
    meshes = [(12, 2), (24, 4)] if args.quick else [(12, 2), (24, 4), (48, 8), (96, 16)]
    finest = meshes[-1]
    studies = [(nx, ny, AMPLITUDE, 0.2) for nx, ny in meshes]
    studies.append((finest[0] // 2, finest[1] // 2, AMPLITUDE, 0.1))  # time-step check
    for fraction in (0.5, 0.1):
        studies += [(nx, ny, fraction * AMPLITUDE, 0.2) for nx, ny in meshes[-2:]]
    rows, curves = [], {}
    for nx, ny, amplitude, courant in studies:
        t, y, energy, dt = solve(nx, ny, amplitude, courant)
        period, _ = period_of(t, y)
        drift = np.max(np.abs(energy / energy[0] - 1.0))
        rows.append({"elements_x": nx, "elements_y": ny, "amplitude": amplitude, "dt": dt,
                     "period": period, "period_vs_linear": period / linear_period - 1.0,
                     "max_relative_energy_error": drift})
        print(f"Q2 {nx} x {ny}, A = {amplitude:.4e} m, dt = {dt:.3e} s: period {period:.5e} s "
              f"({period / linear_period - 1.0:+.2%} vs 2 pi / omega), energy error {drift:.1e}",
              flush=True)
        if courant == 0.2 and (nx, ny) == finest:
            curves[amplitude] = (t, y)
    write_csv(out / "plate_fe.csv", {key: np.array([row[key] for row in rows])
                                     for key in rows[0]})
    lines = ["# Beryllium plate: finite-element reference of the same continuum model",
             "", "Command: `/usr/bin/python3 tools/plots/plate_fe.py`"
             + (" --quick" if args.quick else "") + ". Plane strain, Q2 elements, lumped mass, "
             "leapfrog; W(F) of eqs. (29), (31) with A = F^-1. "
             f"dW/dF checked against central differences: {stress_error:.1e} (relative).", "",
             f"Linear theory 2 pi / omega (eq. 56): {linear_period:.5e} s.", "",
             "| mesh (Q2) | amplitude (m) | dt (s) | period (s) | vs 2 pi / omega | "
             "max relative energy error |", "|---|---|---|---|---|---|"]
    for row in rows:
        lines.append(f"| {row['elements_x']} x {row['elements_y']} | {row['amplitude']:.4e} | "
                     f"{row['dt']:.3e} | {row['period']:.5e} | {row['period_vs_linear']:+.2%} | "
                     f"{row['max_relative_energy_error']:.1e} |")
    fig, ax = plt.subplots(figsize=(7, 4))
    t, y = curves[AMPLITUDE]
    ax.plot(t * 1e6, y * 1e3, "k-", lw=1.5, label=f"finite elements, Q2 {finest[0]} x {finest[1]}")
    sph = Path(args.runs) / "beryllium-plate" / "diagnostics.csv"
    if sph.exists():
        diagnostics = read_csv(sph)
        ts, ys = diagnostics["time"], diagnostics["probe_y"]
        ax.plot(ts * 1e6, ys * 1e3, color="tab:orange", lw=1.5, ls="--",
                label="revsph SHTC-SPH, dr = W/40")
        sph_period, _ = period_of(ts, ys)
        fe_period, _ = period_of(t, y)
        lines += ["", f"SHTC-SPH beryllium-plate run ({sph.parent}): period {sph_period:.5e} s, "
                  f"{sph_period / fe_period - 1.0:+.2%} against the finest finite-element run; "
                  "largest difference of the centre point's y over the run: "
                  f"{np.max(np.abs(np.interp(ts, t, y) - ys)):.3e} m "
                  f"(amplitude {np.max(np.abs(y)):.3e} m)."]
    ax.plot(t * 1e6, AMPLITUDE * mode_shape(0.0) * np.sin(OMEGA * t) * 1e3, "b:", lw=1,
            label="linear theory, eq. (56)")
    ax.set_xlabel("t (µs)")
    ax.set_ylabel("centre point y (mm)")
    ax.set_title("Beryllium plate at eq. (56)'s amplitude")
    ax.legend(fontsize=8)
    save_figure(fig, out / "plate_fe.png")
    (out / "plate_fe.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
