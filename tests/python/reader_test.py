#!/usr/bin/python3
"""The installed Python reader (tools/python/revsph, docs/python.md), imported from where
`cmake --install` put it, never from the source tree:

  - a run folder's snapshots as Snapshot objects, each field a NumPy array with its unit and
    component names (a 2D velocity x, y; SHTC's distortion xx, xy, ..., zz, row-major), the
    energy and diagnostics tables with their units;
  - a chain of three segments continued in one folder reads as the same arrays, snapshot by
    snapshot, as the run that never stopped;
  - a branch (run --from OTHER/... --out THIS) is stitched to the run it continues;
  - a folder that holds no run is refused (NotARunError), not read as an empty run.

Usage: reader_test.py PREFIX   (the install prefix: PREFIX/bin/revsph and the package)
"""

import glob
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

PREFIX = os.path.abspath(sys.argv.pop(1))
REVSPH = os.path.join(PREFIX, "bin", "revsph")
sys.path.insert(0, glob.glob(os.path.join(PREFIX, "lib", "python3*", "dist-packages"))[0])
import revsph  # noqa: E402

CASE = ["--set", "output.snapshot_every=100", "--set", "output.energy_every=50", "--threads", "1"]


def run(*arguments, cwd):
    result = subprocess.run([REVSPH, *arguments], cwd=cwd, capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    return result


class Reader(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.TemporaryDirectory()
        w = cls.work.name
        run("run", "dambreak-small", *CASE, "--steps", "450", "--out", "whole", cwd=w)
        run("run", "dambreak-small", *CASE, "--steps", "130", "--out", "chain", cwd=w)
        run("run", "--from", "chain/snapshots/step_000000130.h5", "--steps", "170", *CASE[-2:],
            cwd=w)
        run("run", "--from", "chain/snapshots/step_000000300.h5", "--steps", "150", *CASE[-2:],
            cwd=w)
        run("run", "--from", "whole/snapshots/step_000000200.h5", "--steps", "250", *CASE[-2:],
            "--out", "branch", cwd=w)
        run("run", "twisting-column-small", "--steps", "3", "--threads", "1", "--out", "column",
            cwd=w)

    @classmethod
    def tearDownClass(cls):
        cls.work.cleanup()

    def folder(self, name):
        return os.path.join(self.work.name, name)

    def test_imported_from_the_install(self):
        self.assertTrue(os.path.realpath(revsph.__file__).startswith(os.path.realpath(PREFIX)))

    def test_fields_with_units_and_component_names(self):
        snapshot = revsph.open_run(self.folder("whole")).snapshots()[-1]
        self.assertEqual((snapshot.step, snapshot.time), (450, 450 * 1e-4))
        self.assertIn("fluid", snapshot.sets)
        velocity = snapshot.field("fluid", "velocity")
        self.assertEqual((velocity.unit, velocity.components), ("m/s", ["x", "y"]))
        self.assertEqual(velocity.values.shape, (5000, 2))
        mass = snapshot.field("fluid", "mass")
        self.assertEqual((mass.unit, mass.components, mass.values.ndim), ("kg/m", [], 1))
        with self.assertRaises(KeyError):
            snapshot.field("fluid", "no_such_field")
        column = revsph.open_run(self.folder("column")).snapshots()[0]
        distortion = column.field("material", "distortion_unimodular")
        self.assertEqual(distortion.components,
                         ["xx", "xy", "xz", "yx", "yy", "yz", "zx", "zy", "zz"])
        # Undistorted at the start: the identity, row-major.
        np.testing.assert_array_equal(distortion.values[0], np.eye(3).ravel())

    def test_tables_with_units(self):
        whole = revsph.open_run(self.folder("whole"))
        energy = whole.energy()
        self.assertEqual(energy.unit("time"), "s")
        self.assertEqual(energy.unit("kinetic"), "J/m")
        self.assertEqual(energy.unit("relative_error"), "1")
        self.assertEqual(list(energy.step), list(range(0, 451, 50)))
        kinetic = 0.0
        last = whole.snapshots()[-1]
        v, m = last.field("fluid", "velocity").values, last.field("fluid", "mass").values
        kinetic = 0.5 * np.sum(m * np.sum(v * v, axis=1))
        self.assertAlmostEqual(energy["kinetic"][-1] / kinetic, 1.0, delta=1e-12)
        # The dam break's model reports no diagnostics: only the run's own columns, among them
        # its count of fluid particles inside its container's walls, none.
        in_walls = whole.diagnostics()
        self.assertEqual(in_walls.unit("particles_in_walls"), "1")
        self.assertEqual(list(in_walls["particles_in_walls"]), [0.0] * len(in_walls.step))
        diagnostics = revsph.open_run(self.folder("column")).diagnostics()
        self.assertEqual(diagnostics.unit("time"), "s")

    def test_a_chain_reads_as_the_run_that_never_stopped(self):
        whole = revsph.open_run(self.folder("whole")).snapshots()
        chain = revsph.open_run(self.folder("chain")).snapshots()
        self.assertEqual([s.step for s in chain], [s.step for s in whole])
        for a, b in zip(whole, chain):
            self.assertEqual((a.time, a.state_hash), (b.time, b.state_hash))
            for particle_set in a.sets:
                for name in a.fields(particle_set):
                    np.testing.assert_array_equal(a.field(particle_set, name).values,
                                                  b.field(particle_set, name).values)
        chained = revsph.open_run(self.folder("chain")).energy()
        for column in chained.columns:
            np.testing.assert_array_equal(chained[column],
                                          revsph.open_run(self.folder("whole")).energy()[column])

    def test_a_branch_is_stitched_to_the_run_it_continues(self):
        branch = revsph.open_run(self.folder("branch"))
        steps = [s.step for s in branch.snapshots()]
        self.assertEqual(steps, [0, 100, 200, 300, 400, 450])
        self.assertTrue(branch.snapshot_paths()[0].startswith(self.folder("whole")))
        self.assertEqual(branch.snapshots()[-1].state_hash,
                         revsph.open_run(self.folder("whole")).snapshots()[-1].state_hash)

    def test_a_folder_that_is_not_a_run_is_refused(self):
        empty = self.folder("empty")
        os.makedirs(empty, exist_ok=True)
        # An empty folder, a run's own snapshots/ (a likely slip) and a folder of other files.
        for folder in [empty, os.path.join(self.folder("whole"), "snapshots"), PREFIX]:
            with self.assertRaises(revsph.NotARunError) as raised:
                revsph.open_run(folder)
            self.assertIn(f"{folder}: not a run folder (no energy.csv)", str(raised.exception))
        with self.assertRaises(FileNotFoundError):
            revsph.open_run(self.folder("no_such_folder"))


if __name__ == "__main__":
    unittest.main()
