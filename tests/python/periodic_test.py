#!/usr/bin/python3
"""Periodic boundaries (docs/periodic.md) against Galilean invariance: the doubly periodic shear
layer of docs/examples/periodic-shear-layer, run at rest and in a frame moving at W = (0.3, -0.2)
m/s, where its particles cross the faces at other times and places. The pair forces depend on
relative positions only, so the moving run must be the resting one carried along by W t (modulo
the period) with every velocity + W, up to the fixed-point rounding of the drifts, which differs
by a unit in the last place per step and is carried by the flow (measured: 1.7e-11 m and 9.5e-10
m/s after 400 steps). An image missing or misplaced across a face changes a particle's density by
up to half (the densities here vary by 5 %), its position by far more than the tolerances (1e-8 m
= 4e-7 dr; 1e-6 m/s = 1e-6 U). At t = 0 the lattice fills the period: every density is the rest
density, the faces included, which it is only with the images.

Usage: periodic_test.py REVSPH_BINARY [unittest options]
"""

import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import h5py
import numpy as np

REVSPH = os.path.abspath(os.environ.get("REVSPH") or (sys.argv.pop(1) if len(sys.argv) > 1 else "revsph"))
SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EXAMPLE = os.path.join(SOURCE, "docs", "examples", "periodic-shear-layer")
STEPS = 400
DT = 1.5e-3
FRAME = np.array([0.3, -0.2])


def run_case(work, name, frame):
    rows = []
    subprocess.run(["/usr/bin/python3", os.path.join(EXAMPLE, "make_points.py"), "--out",
                    "rest.csv"], cwd=work, check=True, capture_output=True)
    with open(os.path.join(work, "rest.csv")) as rest:
        lines = rest.read().splitlines()
    rows = lines[:2]
    for line in lines[2:]:
        x, y, u, v = (float(t) for t in line.split(","))
        rows.append(f"{x!r}, {y!r}, {u + frame[0]!r}, {v + frame[1]!r}")
    with open(os.path.join(work, name + ".csv"), "w") as points:
        points.write("\n".join(rows) + "\n")
    with open(os.path.join(EXAMPLE, "shear-layer.toml")) as case:
        text = case.read().replace('"shear_layer.csv"', f'"{name}.csv"')
    with open(os.path.join(work, name + ".toml"), "w") as case:
        case.write(text)
    result = subprocess.run([REVSPH, "run", name + ".toml", "--steps", str(STEPS), "--out", name],
                            cwd=work, capture_output=True, text=True)
    if result.returncode != 0:
        raise AssertionError(result.stdout + result.stderr)
    snapshots = os.path.join(work, name, "snapshots")
    first = h5py.File(os.path.join(snapshots, "step_000000000.h5"), "r")
    last = h5py.File(os.path.join(snapshots, f"step_{STEPS:09d}.h5"), "r")
    return first, last


class GalileanInvariance(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.mkdtemp(prefix="revsph-periodic-")
        cls.rest = run_case(cls.work, "rest_frame", np.zeros(2))
        cls.moving = run_case(cls.work, "moving_frame", FRAME)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.work, ignore_errors=True)

    def test_the_lattice_fills_the_period_at_the_start(self):
        density = self.rest[0]["particles/fluid/density"][:]
        self.assertEqual(density.min(), 1.0)
        self.assertEqual(density.max(), 1.0)

    def test_the_moving_run_is_the_resting_one_carried_along(self):
        rest, moving = self.rest[1]["particles/fluid"], self.moving[1]["particles/fluid"]
        carried = rest["position"][:] + FRAME * STEPS * DT
        offset = moving["position"][:] - carried
        offset -= np.round(offset)  # the period is 1 m on both axes
        self.assertLess(np.abs(offset).max(), 1e-8)
        velocity = moving["velocity"][:] - FRAME - rest["velocity"][:]
        self.assertLess(np.abs(velocity).max(), 1e-6)
        self.assertLess(np.abs(moving["density"][:] - rest["density"][:]).max(), 1e-8)
        # The flow did something and the particles did cross the faces.
        self.assertGreater(np.ptp(rest["density"][:]), 0.02)
        start = self.moving[0]["particles/fluid/position"][:]
        self.assertTrue((np.abs(moving["position"][:] - start) > 0.5).any())


if __name__ == "__main__":
    unittest.main()
