#!/usr/bin/python3
"""The measurement tools of tools/plots/ that read committed CSVs, on series whose answers are known:

- superfluid_second_sound_speed.py: a probe series running a known fraction slower than eq. (25)
  gives that fraction as the speed's difference, and the eps1 that the lag alone makes;
- convergence_slope.py: an error that falls as N^-p gives the slope p with no error, and a
  scattered one a standard error matching numpy's fit.

Usage: measurement_tools_test.py REVSPH_BINARY [unittest options]   (the binary is not used)
"""

import os
import sys
import unittest

import numpy as np

from revsph_testing import run_unittests

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools",
                                "plots"))

import convergence_slope  # noqa: E402
import superfluid_second_sound_speed as speed  # noqa: E402

REVSPH = None
WORK = None


class SecondSoundSpeedTest(unittest.TestCase):
    U2, A_S0 = 18.83, 7.255  # m/s; A s0 at A = 0.01, s0 = 725.5

    def series(self, slower):
        """The probe at (L/4, L/4), where eq. (25)'s amplitude is A s0 / 2, over one period."""
        w = speed.MODE * self.U2
        t = np.linspace(0.0, 2.0 * np.pi / w, 201)
        exact = speed.S0 + 0.5 * self.A_S0 * np.cos(w * t)
        probe = speed.S0 + 0.5 * self.A_S0 * np.cos((1.0 - slower) * w * t)
        return t, probe, exact

    def test_a_slower_wave_gives_its_speed_and_lag(self):
        t, probe, exact = self.series(0.01)
        row = speed.summarise("eps1-cosine-N300-A0.01", t, probe, exact, {}, [])
        self.assertAlmostEqual(row["u2"], self.U2, places=6)
        self.assertAlmostEqual(row["speed_difference"], -0.01, places=6)
        self.assertAlmostEqual(row["phase_lag_at_end"], 0.02 * np.pi, places=5)
        self.assertEqual((row["N"], row["support_over_dr"]), (300, 3))
        # The mode's RMS is half its amplitude: eps1 = max 0.5 |cos(0.99 w t) - cos(w t)|,
        # the probe's own difference over A s0 the same.
        w = speed.MODE * self.U2
        fine = np.linspace(0.0, t[-1], 100001)
        expected = 0.5 * np.max(np.abs(np.cos(0.99 * w * fine) - np.cos(w * fine)))
        self.assertAlmostEqual(row["eps1_lag_whole"], expected, delta=1e-5)
        self.assertAlmostEqual(row["probe_error_whole"], expected, delta=2e-4)

    def test_the_wide_support_is_read_from_the_name_or_the_list(self):
        t, probe, exact = self.series(0.0)
        self.assertEqual(speed.summarise("eps1-cosine-N50-A0.01-2h", t, probe, exact, {}, [])
                         ["support_over_dr"], 6)
        self.assertEqual(speed.summarise("probe-cosine-N300-A0.01", t, probe, exact, {},
                                         ["probe-cosine-N300-A0.01"])["support_over_dr"], 6)


class ConvergenceSlopeTest(unittest.TestCase):
    def test_a_power_law_gives_its_order_exactly(self):
        n = np.array([20.0, 30.0, 40.0, 60.0])
        slope, error = convergence_slope.slope_with_error(n, 3.0 * n ** -1.5)
        self.assertAlmostEqual(slope, 1.5, places=12)
        self.assertAlmostEqual(error, 0.0, places=10)

    def test_scatter_gives_the_fits_standard_error(self):
        n = np.array([20.0, 30.0, 40.0, 60.0])
        e = n ** -1.0 * np.array([1.0, 1.1, 0.9, 1.05])
        slope, error = convergence_slope.slope_with_error(n, e)
        (fitted, _), covariance = np.polyfit(-np.log(n), np.log(e), 1, cov=True)
        self.assertAlmostEqual(slope, fitted, places=12)
        self.assertAlmostEqual(error, np.sqrt(covariance[0, 0]), places=12)
        self.assertTrue(np.isnan(convergence_slope.slope_with_error(n[:2], e[:2])[1]))


if __name__ == "__main__":
    run_unittests(globals(), "revsph-measurement-tools-test-")
