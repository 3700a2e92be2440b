"""Spin-up of a viscous fluid at rest in a cylinder whose wall starts turning at Omega (the
impulsive start, axisymmetric Navier-Stokes): an independent reference for the rotating-cylinder
runs of paper 5 sec. V.3.

With w = v - Omega r, w_t = nu (w_rr + w_r / r - w / r^2), w(R) = 0 and w(r, 0) = -Omega r;
expanding in J1(j_k r / R), j_k the zeros of J1, with int_0^R r^2 J1(j r / R) dr = R^3 J2(j) / j
and int_0^R r J1(j r / R)^2 dr = R^2 J2(j)^2 / 2:

    v(r, t) = Omega r - sum_k 2 Omega R J1(j_k r / R) / (j_k J2(j_k)) exp(-nu j_k^2 t / R^2).
"""

import numpy as np
from scipy.sparse import bmat, diags, identity
from scipy.sparse.linalg import splu
from scipy.special import jn_zeros, jv

TERMS = 400  # the series' tail at t = 0 is 1/k^2 small; at t > 0 it dies exponentially


def spin_up_velocity(r, t, nu, radius, omega):
    """Azimuthal velocity at radii r (array) and time t."""
    r = np.asarray(r, dtype=float)
    v = omega * r
    for j in jn_zeros(1, TERMS):
        decay = np.exp(-nu * j * j * t / radius**2)
        if decay < 1e-16:
            break
        v = v - 2 * omega * radius * jv(1, j * r / radius) / (j * jv(2, j)) * decay
    return v


def spin_up_slope(t, nu, radius, omega, samples=4001):
    """Least-squares slope k of v = k r through the origin over a disc filled uniformly (weight
    r dr), as the runs' slope over evenly spread particles."""
    r = np.linspace(0.0, radius, samples)
    v = spin_up_velocity(r, t, nu, radius, omega)
    return np.trapz(v * r * r, r) / np.trapz(r**3, r)


def two_fluid_spin_up(times, rho_n, rho_s, eta, friction, radius, omega, cells=400, dt=1.0e-3):
    """The same spin-up for the linear, axisymmetric two-fluid model: the normal fluid viscous
    and held by the wall, the superfluid inviscid and dragged only by the mutual friction,

        rho_n dv_n/dt = eta (v_n'' + v_n' / r - v_n / r^2) - C(t) (v_n - v_s),
        rho_s dv_s/dt = C(t) (v_n - v_s),      v_n(R) = Omega R,  v_n = v_s = 0 at t = 0,

    C(t) = friction(t) the friction coefficient per unit volume (paper 5 eq. 29: C_L). Central
    differences on `cells` rings, Crank-Nicolson in time (second order in both). Returns the
    least-squares slopes (as spin_up_slope) of v_n and v_s at each of `times` (ascending)."""
    h = radius / cells
    r = h * np.arange(1, cells)  # interior nodes; v = 0 at r = 0, v_n = Omega R at r = R
    lower = eta * (1.0 / h**2 - 1.0 / (2.0 * h * r[1:]))
    upper = eta * (1.0 / h**2 + 1.0 / (2.0 * h * r[:-1]))
    main = eta * (-2.0 / h**2 - 1.0 / r**2)
    laplacian = diags([lower, main, upper], [-1, 0, 1], format="csc")
    wall = np.zeros_like(r)
    wall[-1] = eta * (1.0 / h**2 + 1.0 / (2.0 * h * r[-1])) * omega * radius
    n = len(r)
    v_n, v_s = np.zeros(n), np.zeros(n)
    grid = np.concatenate([[0.0], r, [radius]])
    weight = np.trapz(grid**3, grid)
    eye = identity(n, format="csc")
    slopes, t, solvers = [], 0.0, {}
    for target in times:
        while t < target - 1e-12:
            step = min(dt, target - t)
            c = friction(t + step / 2)
            if (c, step) not in solvers:  # a constant C reuses one factorisation
                solvers = {(c, step): splu(bmat(
                    [[rho_n * eye - step / 2 * (laplacian - c * eye), -step / 2 * c * eye],
                     [-step / 2 * c * eye, (rho_s + step / 2 * c) * eye]], format="csc"))}
            rhs_n = rho_n * v_n + step / 2 * (laplacian @ v_n - c * (v_n - v_s)) + step * wall
            rhs_s = rho_s * v_s + step / 2 * c * (v_n - v_s)
            solution = solvers[(c, step)].solve(np.concatenate([rhs_n, rhs_s]))
            v_n, v_s = solution[:n], solution[n:]
            t += step
        full_n = np.concatenate([[0.0], v_n, [omega * radius]])
        full_s = np.concatenate([[0.0], v_s, [v_s[-1]]])
        slopes.append((np.trapz(full_n * grid**2, grid) / weight,
                       np.trapz(full_s * grid**2, grid) / weight))
    return slopes
