"""Spin-up of a viscous fluid at rest in a cylinder whose wall starts turning at Omega (the
impulsive start, axisymmetric Navier-Stokes): an independent reference for the rotating-cylinder
runs of paper 5 sec. V.3.

With w = v - Omega r, w_t = nu (w_rr + w_r / r - w / r^2), w(R) = 0 and w(r, 0) = -Omega r;
expanding in J1(j_k r / R), j_k the zeros of J1, with int_0^R r^2 J1(j r / R) dr = R^3 J2(j) / j
and int_0^R r J1(j r / R)^2 dr = R^2 J2(j)^2 / 2:

    v(r, t) = Omega r - sum_k 2 Omega R J1(j_k r / R) / (j_k J2(j_k)) exp(-nu j_k^2 t / R^2).
"""

import numpy as np
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
