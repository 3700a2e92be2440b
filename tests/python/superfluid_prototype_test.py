#!/usr/bin/python3
"""The superfluid model against its independent float64 prototype
(models/superfluid/scheme_check.py: eq. 19 in numpy, the doubled stepper in a dozen lines): the
second-sound square (N = 12, A = 0.1, square lattice, dt = h / (25 u1)) and the same square with
a uniform coflow and counterflow, 40 steps, in the engine's fixed point and float arithmetic.
The engine's mean fields must equal the prototype's to 1e-9 relative (measured: fixed point
1e-12 of the velocities and 5e-14 of s0, float 2e-14): the C++ pair terms are the equations the
prototype checks for energy conservation and order.

Usage: superfluid_prototype_test.py REVSPH_BINARY [unittest options]
"""

import os
import subprocess
import sys
import unittest

import h5py
import numpy as np

from revsph_testing import environment, run_unittests

REPO = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(REPO, "models", "superfluid"))
import scheme_check as proto  # noqa: E402

REVSPH = None
WORK = None
N, A, M, STEPS = 12, 0.1, 25, 40
L = 0.01


def engine_run(name, arithmetic, extra):
    out = os.path.join(WORK, name)
    command = [REVSPH, "run", "second-sound-small", "--steps", str(STEPS), "--threads", "1",
               "--arithmetic", arithmetic, "--out", out, "--force",
               "--set", f"discretisation.dr={L / N!r}",
               # The prototype's kernel is eq. (17) as printed, h = 3 dr with support 2h.
               "--set", "discretisation.support_radius_over_dr=6.0",
               "--set", f"discretisation.courant_number={1 / (2 * M)!r}",
               "--set", "particles[0].lattice=square",
               "--set", f"output.snapshot_every={STEPS}"] + extra
    result = subprocess.run(command, capture_output=True, text=True, env=environment())
    if result.returncode != 0:
        raise AssertionError(f"{command} failed:\n{result.stderr}")
    last = sorted(os.listdir(os.path.join(out, "snapshots")))[-1]
    with h5py.File(os.path.join(out, "snapshots", last)) as f:
        fluid = f["particles/fluid"]
        return {k: fluid[k][...] for k in ("position", "mean_velocity",
                                           "mean_superflow_velocity", "mean_entropy")}


def by_position(fields):
    # The lattice cell of each particle (they move far less than dr in 40 steps).
    cell = np.round(fields["position"] / (L / N) - 0.5).astype(int)
    order = np.lexsort((cell[:, 1], cell[:, 0]))
    return {k: v[order] for k, v in fields.items()}


class SuperfluidPrototype(unittest.TestCase):
    def compare(self, name, extra, perturb):
        part, state = proto.second_sound(N, A)
        perturb(state)
        h = 3 * L / N
        dt = h / (M * proto.U1)
        d = proto.to_full(state)
        for _ in range(STEPS):
            d = proto.full_step(part, d, dt)
        x, v, vs, s = proto.from_full(d)
        reference = by_position({"position": x, "mean_velocity": v,
                                 "mean_superflow_velocity": vs, "mean_entropy": s})
        fixed = by_position(engine_run(name + "-fixed", "fixed", extra))
        floating = by_position(engine_run(name + "-float", "float", extra))
        for key, scale in (("position", L), ("mean_velocity", 1.0),
                           ("mean_superflow_velocity", 1.0), ("mean_entropy", proto.S0)):
            for engine, label in ((fixed, "fixed"), (floating, "float")):
                difference = np.max(np.abs(engine[key] - reference[key])) / scale
                self.assertLess(difference, 1e-9, f"{name}, {label}, {key}")
        moved = np.max(np.abs(reference["mean_entropy"] - s.mean()))
        self.assertGreater(moved, 1.0, "the wave is there")

    def test_second_sound(self):
        self.compare("wave", [], lambda state: None)

    def test_second_sound_with_uniform_counterflow(self):
        # A uniform v and v - v_s add the nonlinear terms (Pi's u (x) u, grad v_n, T's flow
        # part) without a random field the engine cannot be given particle by particle.
        def perturb(state):
            state[1][:] = [0.2, -0.1]
            state[2][:] = state[1] - np.array([0.3, 0.25])
        self.compare("counterflow", ["--set", "initial.uniform_velocity=[0.2, -0.1]",
                                     "--set", "initial.uniform_counterflow=[0.3, 0.25]"], perturb)


if __name__ == "__main__":
    run_unittests(globals(), "revsph-superfluid-prototype-")
