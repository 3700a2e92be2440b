#!/usr/bin/python3
"""The fountain's jet measurement (tools/plots/superfluid_fountain.py) on snapshots written here,
whose answers are known:

- a column of particles, as wide as the capillary, rising through y = 33.7 mm at 0.5 m/s gives a
  jet speed of 0.5 m/s; fluid falling back through the mouth counts against it, fluid crossing
  outside the mouth not at all;
- eq. (31) from the cell's mean T, s and rho, with the heater's ramp;
- the entropy the pair term of eq. (19) carries through the superleak's mid-plane, on a lattice
  with a uniform J: rho^2 J (W - I), W the strip's width (17 mm) and I its edges' loss, the
  continuum integral of the Wendland kernel (computed here by quadrature, not by pairs);
- a run in two segments (the second restarted from the first's last snapshot, which it writes
  again) reads as one.

Usage: superfluid_fountain_test.py REVSPH_BINARY [unittest options]   (the binary is not used)
"""

import os
import sys
import unittest
from pathlib import Path

import h5py
import numpy as np

from revsph_testing import run_unittests

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools",
                                "plots"))

import superfluid_fountain as fountain  # noqa: E402
import superfluid_fountain_blocks as blocks  # noqa: E402

REVSPH = None
WORK = None
SPACING = fountain.D_CAPILLARY / 8  # the column: 8 particles across the capillary
RISE = 0.5                          # m/s
FALL = -0.2                         # m/s, a blob falling back into the mouth


CELL_T, CELL_S, CELL_RHO = 1.66, 340.0, 145.0
BELOW_T = 1.6585                    # under the superleak: the jump is 1.5 mK at t = 0
WARMING = 0.01                      # K/s, the cell's (not the bath's) temperature rise
ROWS = 700                          # rows of the column: it crosses the mouth for 0.26 s


def particles(time):
    """Positions at `time`: a column as wide as the capillary rising through the mouth, a blob
    falling back into it, a column rising outside it, and blocks in the cell and under the
    superleak; the same particles in the same order at every time, as in revsph's snapshots."""
    d = fountain.D_CAPILLARY
    xs = -d / 2 + SPACING * (np.arange(8) + 0.5)
    column = [(x, fountain.JET_HEIGHT - (k + 0.5) * SPACING + RISE * time)
              for k in range(ROWS) for x in xs]
    falling = [(x, 0.040 + k * SPACING + FALL * time) for k in range(20) for x in xs[2:6]]
    outside = [(0.010, 0.030 + k * SPACING + RISE * time) for k in range(50)]
    cell = [(x, y) for x in np.linspace(-0.007, 0.007, 10) for y in np.linspace(0.004, 0.016, 10)]
    below = [(x, y) for x in np.linspace(0.003, 0.007, 5) for y in np.linspace(-0.009, -0.004, 5)]
    return np.array(column + falling + outside + cell + below)


def write_snapshot(directory, step, time):
    position = particles(time)
    n = len(position)
    (directory / "snapshots").mkdir(parents=True, exist_ok=True)
    with h5py.File(directory / "snapshots" / f"step_{step:09d}.h5", "w") as f:
        f.attrs["time"] = time
        fluid = f.create_group("particles/fluid")
        fluid["position"] = position
        fluid["mass"] = np.full(n, CELL_RHO * SPACING**2)
        fluid["density"] = np.full(n, CELL_RHO)
        fluid["temperature"] = np.where(fountain.in_box(position, fountain.BELOW), BELOW_T,
                                        CELL_T + WARMING * time)
        fluid["mean_entropy"] = np.full(n, CELL_S)
        fluid["pressure"] = np.zeros(n)
        # v = RISE in the column; v_n 10 % faster there (a counterflow), 0 elsewhere.
        velocity = np.zeros((n, 2))
        velocity[: 8 * ROWS, 1] = RISE
        fluid["mean_velocity"] = velocity
        fluid["normal_velocity"] = 1.1 * velocity
        fluid["mean_superflow_velocity"] = velocity
        for kind in ("dummy", "wall"):
            f.create_group(f"particles/{kind}")["position"] = np.zeros((1, 2))


class FountainJet(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.runs = Path(WORK)
        name = "fountain-n4-w80"
        # 0.23 s in two segments, snapshots every 10 ms; the second repeats the first's last.
        for step in range(0, 13):
            write_snapshot(cls.runs / name, step, 0.01 * step)
        for step in range(12, 24):
            write_snapshot(cls.runs / f"{name}-2", step, 0.01 * step)
        cls.data = fountain.series(cls.runs, name)
        cls.summary = fountain.jet_summary(cls.runs, name)

    def test_segments_read_as_one_run(self):
        self.assertEqual(len(self.data["t"]), 24)
        self.assertTrue(np.all(np.diff(self.data["t"]) > 0))

    def test_rising_column_is_the_jet_speed_less_what_falls_back(self):
        speed = self.data["crossed"] / (np.diff(self.data["t"]) * fountain.D_CAPILLARY)
        # Only whole particles cross: one row of 8 more or less per 10 ms interval.
        row = 8 * SPACING**2 / (0.01 * fountain.D_CAPILLARY)
        # The blob falls through the mouth (33.7 mm) between 32 and 50 ms, 4 columns of 8 at
        # 0.2 m/s: 0.1 m/s off the jet in the intervals from 30 to 50 ms.
        np.testing.assert_allclose(speed[3:5], RISE - 0.1, atol=row)
        others = np.r_[speed[:3], speed[6:]]
        np.testing.assert_allclose(others, RISE, atol=row)
        _, mean_jet, _, _, _, _ = self.summary
        self.assertAlmostEqual(mean_jet, RISE, delta=row / 2)

    def test_temperature_jump_at_the_superleak(self):
        _, _, _, jump, _, _ = self.summary
        late = [t for t in 0.01 * np.arange(24) if t >= fountain.AVERAGE_FROM - 1e-9]
        self.assertAlmostEqual(jump, CELL_T - BELOW_T + WARMING * np.mean(late), places=12)

    def test_heat_kept_by_the_cell(self):
        _, _, _, _, stored, _ = self.summary
        late = [t for t in 0.01 * np.arange(24) if t >= fountain.AVERAGE_FROM - 1e-9]
        # The particles in the cell (|x| < 8 mm, 3 < y < 16.7 mm) and the capillary (|x| < 1.2
        # mm, up to its top), counted here from the positions.
        counts = []
        for t in late:
            x, y = particles(t).T
            cell = (np.abs(x) < 8e-3) & (y > 3e-3) & (y < 16.7e-3)
            capillary = (np.abs(x) < 1.2e-3) & (y > 16.7e-3) & (y < 33.7e-3)
            counts.append(np.sum(cell | capillary))
        mass = CELL_RHO * SPACING**2 * np.mean(counts)
        self.assertAlmostEqual(stored, mass * fountain.HEAT_CAPACITY * WARMING / 80.0, places=10)

    def test_counterflow_at_the_mouth(self):
        _, _, _, _, _, counterflow = self.summary
        self.assertAlmostEqual(counterflow, 1.1, places=12)

    def test_eq31_uses_the_cell_and_the_heaters_ramp(self):
        data, _, mean_ideal, _, _, _ = self.summary
        t = 0.01 * np.arange(24)
        power = 80.0 * np.minimum(t / 0.02, 1.0)
        ideal = power / ((CELL_T + WARMING * t) * CELL_S * CELL_RHO * fountain.D_CAPILLARY)
        np.testing.assert_allclose(data["ideal"], ideal, rtol=1e-12)
        # Its mean over t > 0.2 s: the trapezoid rule on the snapshots 0.20, 0.21, 0.22, 0.23.
        late = ideal[20:]
        self.assertAlmostEqual(mean_ideal, np.mean(0.5 * (late[:-1] + late[1:])), places=12)


class PairEntropyFluxTest(unittest.TestCase):
    def test_uniform_flux_through_the_plane_is_rho_squared_j_times_the_width(self):
        n = 12
        dr = fountain.D_CAPILLARY / n
        support = 5.6 * dr
        rho, u = 145.0, 0.02
        # A square lattice across x in (-12, 12) mm, its rows symmetric about the plane.
        xs = np.arange(-12e-3 + dr / 2, 12e-3, dr)
        ys = fountain.SUPERLEAK_PLANE + dr * (np.arange(-8, 8) + 0.5)
        x, y = np.meshgrid(xs, ys)
        count = x.size
        velocity = np.zeros((count, 2))
        velocity[:, 1] = u
        snapshot = {"position": np.column_stack([x.ravel(), y.ravel()]),
                    "mass": np.full(count, rho * dr * dr), "density": np.full(count, rho),
                    "mean_entropy": np.full(count, fountain.S0), "mean_velocity": velocity,
                    "mean_superflow_velocity": np.zeros((count, 2))}
        chi_n = fountain.CHI_N0
        j = fountain.S0 * (1.0 - chi_n) / (chi_n * rho) * u  # J = s (chi_s / chi_n) u / rho
        # I = int (-w') r^3 dr * int sin^2 |cos| dtheta (= 4/3): the pairs the strip's edges cut.
        r = np.linspace(0.0, support, 20001)
        q = r / support
        w_slope = -140.0 * q * (1.0 - q) ** 3 / (np.pi * support**3)  # w'(r), 2D Wendland C2
        f = -w_slope * r**3
        edge = np.sum(0.5 * (f[1:] + f[:-1]) * np.diff(r)) * 4.0 / 3.0
        # The strip |x| < 8.5 mm holds whole lattice columns, each dr wide.
        width = np.sum(np.abs(xs) < 8.5e-3) * dr
        expected = rho**2 * j * (width - edge)
        measured = fountain.pair_entropy_flux(snapshot, fountain.SUPERLEAK_PLANE, support)
        # The lattice sum of a kernel 5.6 spacings wide matches its integral to 3e-4 here.
        self.assertAlmostEqual(measured / expected, 1.0, delta=1e-3)
        # Reversed flow, reversed flux.
        snapshot["mean_velocity"] *= -1.0
        self.assertAlmostEqual(
            fountain.pair_entropy_flux(snapshot, fountain.SUPERLEAK_PLANE, support), -measured,
            delta=1e-9 * abs(measured))


class BlockMeansTest(unittest.TestCase):
    """superfluid_fountain_blocks.py on a jet series with known block means."""

    def series(self, deficits, per_block=10, interval=0.0025, start=0.19):
        """A series from `start` whose 25 ms blocks after 0.2 s lie `deficits` percent below a
        constant eq. (31) of 0.64 m/s; before 0.2 s the jet is far off (it must not count)."""
        t = start + interval * np.arange(4 + per_block * len(deficits) + 1)
        jet = np.concatenate([np.full(4, 0.1)] + [np.full(per_block, 0.64 * (1 - d / 100))
                                                  for d in deficits])
        return t[:-1], t[1:], jet, np.full(len(jet), 0.64)

    def test_window_mean_and_block_scatter(self):
        columns = self.series([1.0, 3.0, 2.0, 2.0])
        row = blocks.summarise("fountain-n6-w80", columns, 0.2, 0.2999, 0.025)
        self.assertEqual((row["N"], row["power_W_per_m"], row["blocks"]), (6, 80.0, 4))
        self.assertAlmostEqual(row["deficit_percent"], 2.0, places=9)
        spread = np.std([1.0, 3.0, 2.0, 2.0], ddof=1)
        self.assertAlmostEqual(row["block_std_points"], spread, places=9)
        self.assertAlmostEqual(row["block_error_points"], spread / 2.0, places=9)
        # Eq. (31) at T0, s0, rho0: W / (T0 s0 rho0 d), against which the same jet is slower.
        reference = 80.0 / (blocks.T0 * blocks.S0 * blocks.RHO0 * blocks.D_CAPILLARY)
        self.assertAlmostEqual(row["deficit_T0_percent"], 100 * (1 - 0.64 * 0.98 / reference),
                               places=9)

    def test_a_short_last_block_joins_the_one_before(self):
        columns = self.series([1.0, 3.0, 2.0])
        row = blocks.summarise("fountain-n4-w80", columns, 0.2, 0.2549, 0.025)
        self.assertEqual(row["blocks"], 2)
        self.assertEqual(row["block_deficits"], "1.00 2.83")  # (10 x 3 + 2 x 2) / 12

    def test_a_run_that_stops_before_the_window_ends_is_left_out(self):
        columns = self.series([1.0, 3.0])
        self.assertIsNone(blocks.summarise("fountain-n6-w80", columns, 0.2, 0.2924, 0.025))


if __name__ == "__main__":
    run_unittests(globals(), "revsph-fountain-test-")
