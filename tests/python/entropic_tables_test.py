#!/usr/bin/python3
"""The scripts behind numbers of models/entropic/README.md's table that need no run:
entropic_close_pairs.close_pairs against a count of every pair by hand, and
entropic_nusselt_error.error_rows on series whose mean and spread are known. Plain Python.
"""

import csv
import itertools
import os
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools",
                                "plots"))
from entropic_close_pairs import close_pairs  # noqa: E402
from entropic_nusselt_error import INDEPENDENT_WINDOWS, error_rows  # noqa: E402


class ClosePairsTest(unittest.TestCase):
    def test_counts_every_pair_as_a_double_loop_does(self):
        rng = np.random.default_rng(7)
        gas = rng.uniform(0.0, 1.0, (300, 2))
        gas[10] = gas[11] + 1e-12  # a merged pair
        gas[20] = gas[21] + [0.004, 0.0]
        gas[22] = gas[21] + [0.0, 0.004]  # three particles, three pairs
        walls = rng.uniform(0.0, 1.0, (80, 2))
        walls[0] = gas[30] + 1e-9
        distance = 0.01
        gas_pairs = [(i, j) for i, j in itertools.combinations(range(len(gas)), 2)
                     if np.linalg.norm(gas[i] - gas[j]) < distance]
        wall_pairs = [(i, k) for i in range(len(gas)) for k in range(len(walls))
                      if np.linalg.norm(gas[i] - walls[k]) < distance]
        in_pairs = {i for pair in gas_pairs for i in pair} | {i for i, _ in wall_pairs}
        nearest = min(np.linalg.norm(gas[i] - gas[j])
                      for i, j in itertools.combinations(range(len(gas)), 2))
        counted = close_pairs(gas, walls, distance)
        self.assertGreaterEqual(len(gas_pairs), 4)
        self.assertEqual(counted[:3], (len(gas_pairs), len(wall_pairs), len(in_pairs)))
        self.assertAlmostEqual(counted[3], nearest, delta=1e-15)

    def test_no_walls(self):
        gas = np.array([[0.0, 0.0], [1.0, 0.0], [1.05, 0.0]])
        self.assertEqual(close_pairs(gas, np.empty((0, 2)), 0.1)[:3], (1, 0, 2))


class NusseltErrorTest(unittest.TestCase):
    def test_mean_standard_error_and_walls(self):
        t = 0.25 * np.arange(1, 121) - 0.125  # 30 samples in the last quarter: the wiggle cancels
        wiggle = np.where(np.arange(len(t)) % 2 == 0, 0.1, -0.1)
        hot, cold = 2.0 + wiggle, 1.9 + wiggle
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "entropic_cavity.csv")
            with open(path, "w", newline="") as f:
                writer = csv.writer(f)
                writer.writerow(["run", "time", "nusselt_hot", "nusselt_cold"])
                for row in zip(t, hot, cold):
                    writer.writerow(["a", *row])
            (run, mean, standard_error, walls, bar), = list(error_rows(path))
        self.assertEqual(run, "a")
        self.assertAlmostEqual(mean, 1.95, delta=1e-12)
        self.assertAlmostEqual(standard_error, 0.1 / np.sqrt(INDEPENDENT_WINDOWS), delta=1e-12)
        self.assertAlmostEqual(walls, 0.05, delta=1e-12)
        self.assertEqual(bar, max(standard_error, walls))


if __name__ == "__main__":
    unittest.main()
