#!/usr/bin/python3
"""The paper-1 figure scripts (tools/plots/) on a tiny reversal experiment.

Runs `revsph verify` on a coarse dam break (dr = 0.04 m, 1 250 fluid particles, 1 000 steps each
way) in fixed and in floating point, then each plotting script and tools/plots/paper1_figures.py,
and checks exit statuses, that the PNGs are written, and numbers against computations made here
from the raw files: the leading-edge RMS against two made-up reference files in the layout of
the published ones (fronts, time scaling, the T <= 2 cut and interpolation redone here), the
largest energy error against revsph's summary.json and energy.csv, and the FixPA/FloPA
deviations (exactly 0 in fixed point, positive in floating point, the FloPA value recomputed).
Skipped where python3-matplotlib is not installed.

Usage: figures_test.py REVSPH_BINARY [unittest options]   (or REVSPH=... in the environment)
"""

import csv
import glob
import json
import math
import os
import re
import subprocess
import unittest

import h5py
import numpy as np

from revsph_testing import environment, run_unittests

REVSPH = None
WORK = None

PYTHON = "/usr/bin/python3"
PLOTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "plots")
# Reference files in the layout of the shared refdata (primary time column t sqrt(2g/L), derived
# t sqrt(g/L) rounded to 3 decimals, X), with made-up values: the test checks the scoring, not
# the physics, and must not depend on data outside the repository.
REFERENCES = {
    "dambreak_front_martin_moyce1952.csv": [(0.20, 1.02), (0.41, 1.11), (0.84, 1.22),
                                            (3.10, 4.00)],
    "dambreak_front_koshizuka_oka1996.csv": [(0.0, 1.0), (0.381, 1.111), (0.769, 1.252),
                                             (1.153, 1.505)],
}
STEPS = 1000
DR = 0.04
OVERRIDES = [f"discretisation.dr={DR}", "output.snapshot_every=100", "output.energy_every=10"]


def run(command, timeout=120):
    result = subprocess.run([str(c) for c in command], capture_output=True, text=True,
                            timeout=timeout, env=environment())
    return result


def script(name, *args):
    return run([PYTHON, os.path.join(PLOTS, name), *args])


def number_after(pattern, text):
    match = re.search(pattern + r"\s*([-+0-9.eE]+|nan)", text)
    if not match:
        raise AssertionError(f"no match for {pattern!r} in:\n{text}")
    return float(match.group(1))


def fluid_x_series(run_dir):
    times, x = [], []
    for path in sorted(glob.glob(os.path.join(run_dir, "forward", "snapshots", "step_*.h5"))):
        with h5py.File(path, "r") as f:
            times.append(float(f.attrs["time"]))
            x.append(np.array(f["particles/fluid/position"][:, 0]))
    return np.array(times), x


def front(xs, gap_limit):
    """The leading edge as leading_edge.py documents it, recomputed by walking the particles
    from the wall: the end of the first stretch without a gap wider than gap_limit."""
    ordered = sorted(xs)
    edge = ordered[0]
    for value in ordered[1:]:
        if value - edge > gap_limit:
            break
        edge = value
    return edge + DR / 2


def write_references(directory):
    os.makedirs(directory)
    for name, rows in REFERENCES.items():
        with open(os.path.join(directory, name), "w") as f:
            f.write("# made up for figures_test\nt_sqrt_2g_over_L,t_sqrt_g_over_L,X\n")
            for t, x in rows:
                f.write(f"{t},{t / math.sqrt(2):.3f},{x}\n")


class FiguresTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        if run([PYTHON, "-c", "import matplotlib"]).returncode != 0:
            raise unittest.SkipTest("python3-matplotlib is not installed")
        cls.refdata = os.path.join(WORK, "refdata")
        write_references(cls.refdata)
        cls.fixed = os.path.join(WORK, "fixed")
        cls.float = os.path.join(WORK, "float")
        for out, extra, statuses in ((cls.fixed, [], (0,)),
                                     (cls.float, ["--arithmetic", "float"], (0, 1))):
            command = [REVSPH, "verify", "dambreak-small", "--steps", STEPS, "--out", out,
                       "--threads", "1", *extra]
            for override in OVERRIDES:
                command += ["--set", override]
            result = run(command)
            if result.returncode not in statuses:
                raise AssertionError(f"{command} failed ({result.returncode}):\n"
                                     f"{result.stdout}\n{result.stderr}")

    def assert_png(self, path):
        self.assertTrue(os.path.isfile(path), path)
        with open(path, "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n", path)
        self.assertGreater(os.path.getsize(path), 1000, path)
        self.assertLess(os.path.getsize(path), 300_000, path)

    def test_energy_budget(self):
        out = os.path.join(WORK, "energy")
        result = script("energy_budget.py", self.fixed, self.float, "--out", out,
                        "--label", "fixed", "--label", "float")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assert_png(os.path.join(out, "energy_budget.png"))
        self.assert_png(os.path.join(out, "energy_drift.png"))
        with open(os.path.join(self.fixed, "summary.json")) as f:
            expected = json.load(f)["energy"]["max_relative_error_forward"]
        printed = number_after(r"fixed: max relative total-energy error \(forward\)",
                               result.stdout)
        self.assertAlmostEqual(printed, expected, delta=1e-5 * expected)
        with open(os.path.join(self.fixed, "forward", "energy.csv"), newline="") as f:
            rows = [{k.split(" [")[0]: v for k, v in row.items()} for row in csv.DictReader(f)]
        total = [float(r["total"]) for r in rows]
        drop = float(rows[0]["gravitational"]) - float(rows[-1]["gravitational"])
        fig5 = max(abs(e - total[0]) for e in total) / drop
        printed = number_after(r"fixed: .*?max \|E - E0\| / \(E_g\(0\) - E_g\(t_end\)\)",
                               result.stdout)
        self.assertAlmostEqual(printed, fig5, delta=1e-5 * fig5)

    def test_leading_edge(self):
        out = os.path.join(WORK, "front")
        result = script("leading_edge.py", self.fixed, "--out", out, "--refdata", self.refdata)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assert_png(os.path.join(out, "leading_edge.png"))
        times, xs = fluid_x_series(self.fixed)
        T = times * math.sqrt(9.8 / 1.0)  # the case: g = 9.8 m/s^2, column width 1 m
        X = np.array([front(x, 3 * DR) for x in xs])
        X_raw = np.array([x.max() + DR / 2 for x in xs])
        for name, label in (("dambreak_front_martin_moyce1952.csv", "Martin & Moyce 1952"),
                            ("dambreak_front_koshizuka_oka1996.csv", "Koshizuka & Oka 1996")):
            pairs = [(t / math.sqrt(2), x) for t, x in REFERENCES[name]
                     if t / math.sqrt(2) <= 2.0 and T[0] <= t / math.sqrt(2) <= T[-1]]
            self.assertGreaterEqual(len(pairs), 2, name)
            match = re.search(re.escape(label) + r".*?over T <= 2: ([0-9.]+) \((\d+) points; "
                              r"raw front ([0-9.]+)\)", result.stdout)
            self.assertTrue(match, result.stdout)
            self.assertEqual(int(match.group(2)), len(pairs), label)
            for series, printed in ((X, match.group(1)), (X_raw, match.group(3))):
                d = [np.interp(t, T, series) - x for t, x in pairs]
                rms = math.sqrt(sum(v * v for v in d) / len(d))
                self.assertAlmostEqual(float(printed), rms, delta=6e-5, msg=label)

    def test_fixpa_flopa(self):
        out = os.path.join(WORK, "fixpa")
        result = script("fixpa_flopa.py", self.fixed, self.float, "--out", out)
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        self.assert_png(os.path.join(out, "fixpa_flopa.png"))
        lines = result.stdout.splitlines()
        fixed_line = next(line for line in lines if line.startswith(self.fixed))
        float_line = next(line for line in lines if line.startswith(self.float))
        self.assertEqual(number_after("max", fixed_line), 0.0)
        self.assertEqual(number_after("RMS", fixed_line), 0.0)
        self.assertIn("identical", fixed_line)
        printed = number_after("max", float_line)
        self.assertGreater(printed, 0.0)
        first = os.path.join(self.float, "forward", "snapshots", "step_000000000.h5")
        last = os.path.join(self.float, "backward", "snapshots", f"step_{2 * STEPS:09d}.h5")
        with h5py.File(first, "r") as a, h5py.File(last, "r") as b:
            d = np.hypot(*(b["particles/fluid/position"][:] - a["particles/fluid/position"][:]).T)
        self.assertAlmostEqual(printed, float(d.max()), delta=1e-5 * float(d.max()))

    def test_paper1_figures(self):
        runs = os.path.join(WORK, "runs")
        figures = os.path.join(WORK, "figures")
        os.makedirs(runs)
        # The tiny experiments stand in for every run the command expects.
        for name, target in (("dambreak-full", self.fixed), ("dambreak-small-fixed", self.fixed),
                             ("dambreak-small-float", self.float),
                             ("dambreak-small-courant0.1", self.fixed),
                             ("dambreak-small-courant0.05", self.fixed)):
            os.symlink(target, os.path.join(runs, name))
        common = ["--runs", runs, "--out", figures, "--revsph", REVSPH, "--no-gresho",
                  "--refdata", self.refdata]
        listing = script("paper1_figures.py", "--list", *common)
        self.assertEqual(listing.returncode, 0, listing.stderr)
        names = [n for line in re.findall(r"^(\S.*\.png)$", listing.stdout, re.MULTILINE)
                 for n in line.split(", ")]
        self.assertEqual(len(names), 6, listing.stdout)
        for fig in ("Fig. 3", "Fig. 4", "Fig. 5", "Figs. 8-12", "Fig. 6"):
            self.assertIn(fig, listing.stdout)
        self.assertNotIn("(missing)", listing.stdout)
        result = script("paper1_figures.py", *common)
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        for name in names:
            self.assert_png(os.path.join(figures, name))
        # paper1_numbers.csv: one row per run present, numbers against summary.json and energy.csv.
        with open(os.path.join(figures, "paper1_numbers.csv"), newline="") as f:
            numbers = {row["run"]: row for row in csv.DictReader(f)}
        self.assertEqual(set(numbers), {"dambreak-full", "dambreak-small-fixed",
                                        "dambreak-small-float", "dambreak-small-courant0.1",
                                        "dambreak-small-courant0.05"})
        with open(os.path.join(self.fixed, "summary.json")) as f:
            expected = json.load(f)["energy"]["max_relative_error_forward"]
        fixed = numbers["dambreak-small-fixed"]
        self.assertAlmostEqual(float(fixed["max_relative_energy_error"]), expected,
                               delta=1e-3 * expected)
        with open(os.path.join(self.fixed, "forward", "energy.csv"), newline="") as f:
            rows = [{k.split(" [")[0]: float(v) for k, v in row.items()}
                    for row in csv.DictReader(f)]
        drop = rows[0]["gravitational"] - rows[-1]["gravitational"]
        kinetic = (rows[-1]["kinetic"] - rows[0]["kinetic"]) / drop
        self.assertAlmostEqual(float(fixed["kinetic_share_at_end"]), kinetic, delta=1e-4)
        self.assertEqual(fixed["dr"], "0.04")
        self.assertEqual(fixed["returned_bitwise"], "true")
        self.assertEqual(numbers["dambreak-small-float"]["returned_bitwise"], "false")


if __name__ == "__main__":
    run_unittests(globals(), "revsph-figures-test-")
