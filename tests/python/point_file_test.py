#!/usr/bin/python3
"""Starting a run from a snapshot's physical fields, edited (docs/point-files.md): a fluid taken
from a dambreak-small snapshot by tools/points/points_from_snapshot.py, its velocities doubled
with h5py, read back by a [[particles]] block of shape "points". The new run's particles sit
bit for bit where the snapshot had them (the same raw fixed-point positions), its masses are
the snapshot's, and its kinetic energy at step 0 is four times the snapshot's, computed here
with numpy from the snapshot's views.

Usage: point_file_test.py REVSPH_BINARY [unittest options]
"""

import csv
import os
import subprocess
import sys
import tempfile
import unittest

import h5py
import numpy as np

REVSPH = os.environ.get("REVSPH") or (sys.argv.pop(1) if len(sys.argv) > 1 else "revsph")
SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CONVERT = os.path.join(SOURCE, "tools", "points", "points_from_snapshot.py")


def run(*arguments, cwd):
    return subprocess.run([REVSPH, *arguments], cwd=cwd, capture_output=True, text=True)


class EditedSnapshotFields(unittest.TestCase):
    def test_a_fluid_from_an_edited_snapshot(self):
        with tempfile.TemporaryDirectory() as work:
            made = run("run", "dambreak-small", "--steps", "300", "--threads", "1", "--out",
                       "first", cwd=work)
            self.assertEqual(made.returncode, 0, made.stderr)
            snapshot = os.path.join(work, "first", "snapshots", "step_000000300.h5")
            subprocess.run(["/usr/bin/python3", CONVERT, snapshot, "--set", "fluid", "--fields",
                            "velocity", "mass", "--out", os.path.join(work, "fluid.h5")],
                           check=True, capture_output=True)
            with h5py.File(os.path.join(work, "fluid.h5"), "r+") as points:
                points["velocity"][...] *= 2.0
            case = run("cases", "dambreak-small", cwd=work).stdout
            box = 'shape = "box"\nlattice = "square"\nmin = [0.0, 0.0]\nmax = [1.0, 2.0]'
            self.assertEqual(case.count(box), 1)
            with open(os.path.join(work, "edited.toml"), "w") as out:
                out.write(case.replace(box, 'shape = "points"\nfile = "fluid.h5"'))
            second = run("run", "edited.toml", "--steps", "0", "--out", "second", cwd=work)
            self.assertEqual(second.returncode, 0, second.stderr)

            start = os.path.join(work, "second", "snapshots", "step_000000000.h5")
            with h5py.File(snapshot, "r") as old, h5py.File(start, "r") as new:
                np.testing.assert_array_equal(new["state/fluid/position"][...],
                                              old["state/fluid/position"][...])
                np.testing.assert_array_equal(new["particles/fluid/mass"][...],
                                              old["particles/fluid/mass"][...])
                fluid = old["particles/fluid"]
                kinetic = 0.5 * np.sum(fluid["mass"][...] *
                                       np.sum(fluid["velocity"][...] ** 2, axis=1))
            with open(os.path.join(work, "second", "energy.csv")) as rows:
                first_row = {k.split(" [")[0]: v for k, v in next(csv.DictReader(rows)).items()}
            # The doubled velocities in the state's fixed point: 4 KE up to its rounding.
            self.assertAlmostEqual(float(first_row["kinetic"]) / (4.0 * kinetic), 1.0, delta=1e-12)

    def test_a_field_the_set_up_does_not_fill_is_refused(self):
        with tempfile.TemporaryDirectory() as work:
            with open(os.path.join(work, "fluid.csv"), "w") as out:
                out.write("x [m], y [m], pressure [Pa]\n0.5, 0.5, 1.0\n")
            case = run("cases", "dambreak-small", cwd=work).stdout
            box = 'shape = "box"\nlattice = "square"\nmin = [0.0, 0.0]\nmax = [1.0, 2.0]'
            with open(os.path.join(work, "bad.toml"), "w") as out:
                out.write(case.replace(box, 'shape = "points"\nfile = "fluid.csv"\n'
                                            'spacing = 0.02'))
            bad = run("run", "bad.toml", "--steps", "1", "--out", "bad", cwd=work)
            self.assertEqual(bad.returncode, 2, bad.stderr)
            self.assertEqual(len(bad.stderr.strip().splitlines()), 1, bad.stderr)
            self.assertIn("particles[0].file: column pressure: no such initial value of set "
                          "fluid", bad.stderr)


if __name__ == "__main__":
    unittest.main()
