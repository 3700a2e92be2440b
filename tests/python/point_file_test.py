#!/usr/bin/python3
"""Point files through the revsph binary (docs/point-files.md).

Starting a run from a snapshot's physical fields, edited: a fluid taken from a dambreak-small
snapshot by tools/points/points_from_snapshot.py, its velocities doubled with h5py, read back by a
[[particles]] block of shape "points". The new run's particles sit bit for bit where the snapshot
had them (the same raw fixed-point positions), its masses and densities are the snapshot's, and
its kinetic energy at step 0 is four times the snapshot's, computed here with numpy from the
snapshot's views.

Bad point files end in one line `revsph: error: ...` and exit 2, naming the file, the line and
the column. A Taylor-Green vortex whose file gives wcsph its pressure starts with that pressure
(read back from the step-0 snapshot) and keeps its kinetic energy closer than one without.

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
                            "velocity", "mass", "density", "--out",
                            os.path.join(work, "fluid.h5")],
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
                # The density constants chosen for the snapshot's densities give them back.
                np.testing.assert_array_equal(new["particles/fluid/density"][...],
                                              old["particles/fluid/density"][...])
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
                out.write("x [m], y [m], temperature [K]\n0.5, 0.5, 1.0\n")
            case = run("cases", "dambreak-small", cwd=work).stdout
            box = 'shape = "box"\nlattice = "square"\nmin = [0.0, 0.0]\nmax = [1.0, 2.0]'
            with open(os.path.join(work, "bad.toml"), "w") as out:
                out.write(case.replace(box, 'shape = "points"\nfile = "fluid.csv"\n'
                                            'spacing = 0.02'))
            bad = run("run", "bad.toml", "--steps", "1", "--out", "bad", cwd=work)
            self.assertEqual(bad.returncode, 2, bad.stderr)
            self.assertEqual(len(bad.stderr.strip().splitlines()), 1, bad.stderr)
            self.assertIn("particles[0].file: ", bad.stderr)
            self.assertIn("fluid.csv: column temperature: no such initial value of set fluid",
                          bad.stderr)


def dambreak_with_points(work, file_name):
    """dambreak-small with its water column replaced by the particles of `file_name`."""
    case = run("cases", "dambreak-small", cwd=work).stdout
    box = 'shape = "box"\nlattice = "square"\nmin = [0.0, 0.0]\nmax = [1.0, 2.0]'
    assert case.count(box) == 1
    with open(os.path.join(work, "case.toml"), "w") as out:
        out.write(case.replace(box, f'shape = "points"\nfile = "{file_name}"\nspacing = 0.02'))
    return "case.toml"


class BadPointFiles(unittest.TestCase):
    def refusal(self, file_name, content):
        """The one line revsph writes for a dambreak whose fluid is `content`, exit 2."""
        with tempfile.TemporaryDirectory() as work:
            with open(os.path.join(work, file_name), "wb") as out:
                out.write(content.encode() if isinstance(content, str) else content)
            bad = run("run", dambreak_with_points(work, file_name), "--steps", "1", "--out", "o",
                      cwd=work)
            self.assertEqual(bad.returncode, 2, bad.stderr)
            lines = bad.stderr.strip().splitlines()
            self.assertEqual(len(lines), 1, bad.stderr)
            self.assertTrue(lines[0].startswith("revsph: error: case.toml: particles[0]"),
                            lines[0])
            self.assertIn(file_name, lines[0])
            return lines[0]

    def test_each_fault_names_file_line_and_column(self):
        head = "x [m], y [m], velocity_x [m/s], velocity_y [m/s]\n"
        faults = [
            # Two rows at one place: the second started with velocity 0.
            ("duplicate", "fluid.csv",
             head + "0.51, 0.51, 1, 0\n0.55, 0.51, 1, 0\n0.51, 0.51, 1, 0\n",
             "fluid.csv line 4: the same position as line 2"),
            # A mass not positive was a run fault (exit 3, "density not positive").
            ("negative_mass", "fluid.csv",
             "x [m], y [m], mass [kg/m]\n0.51, 0.51, 0.4\n0.55, 0.51, -0.4\n",
             "fluid.csv line 3, column mass: -0.4 [kg/m], but a mass is positive"),
            ("zero_mass", "fluid.csv", "x [m], y [m], mass [kg/m]\n0.51, 0.51, 0\n",
             "fluid.csv line 2, column mass: 0 [kg/m]"),
            ("half_a_vector", "fluid.csv", "x [m], y [m], velocity_x [m/s]\n0.51, 0.51, 1\n",
             "no column velocity_y [m/s]: a file gives every component of velocity"),
            ("csv_named_h5", "fluid.h5", head + "0.51, 0.51, 1, 0\n",
             "fluid.h5: named .h5 but not an HDF5 file"),
            # rho0 c^2 / 7 = 2.06e6 Pa: a lower pressure would need a negative density.
            ("pressure_below_zero_density", "fluid.csv",
             "x [m], y [m], pressure [Pa]\n0.51, 0.51, -3e6\n",
             "fluid.csv line 2, column pressure: -3e+06 [Pa], but it must be above "
             "-2.05714e+06 Pa"),
            ("density_and_pressure", "fluid.csv",
             "x [m], y [m], density [kg/m^3], pressure [Pa]\n0.51, 0.51, 1000, 0\n",
             "columns density and pressure give one thing (the initial density)"),
        ]
        for name, file_name, content, expected in faults:
            with self.subTest(name):
                self.assertIn(expected, self.refusal(file_name, content))

    def test_a_byte_order_mark_before_the_header_is_skipped(self):
        with tempfile.TemporaryDirectory() as work:
            with open(os.path.join(work, "fluid.csv"), "w", encoding="utf-8-sig") as out:
                out.write("x [m], y [m], velocity_x [m/s], velocity_y [m/s]\n"
                          "0.51, 0.51, 1.5, -0.5\n0.55, 0.51, 1.5, -0.5\n")
            made = run("run", dambreak_with_points(work, "fluid.csv"), "--steps", "0", "--out",
                       "o", cwd=work)
            self.assertEqual(made.returncode, 0, made.stderr)
            with h5py.File(os.path.join(work, "o", "snapshots", "step_000000000.h5"), "r") as f:
                np.testing.assert_array_equal(f["particles/fluid/velocity"][...],
                                              [[1.5, -0.5], [1.5, -0.5]])


TAYLOR_GREEN = """model = "wcsph"
dimension = 2
name = "taylor-green"

[physics]
rest_density = 1.0
sound_speed = 10.0
gravity = 0.0

[discretisation]
dr = 0.03125
support_radius_over_dr = 3.0
courant_number = 0.2

[domain]
min = [0.0, 0.0]
max = [1.0, 1.0]
periodic = "xy"

[[particles]]
kind = "fluid"
shape = "points"
file = "{file}"

[run]
t_end = 1.0

[output]
energy_every = 5
snapshot_every = 100000
"""


def taylor_green_points(path, cells, with_pressure):
    """u = U sin kx cos ky, v = -U cos kx sin ky, p = rho U^2 / 4 (cos 2kx + cos 2ky), U = 1,
    rho = 1, k = 2 pi on the unit square; returns the pressures."""
    dr = 1.0 / cells
    x, y = np.meshgrid((np.arange(cells) + 0.5) * dr, (np.arange(cells) + 0.5) * dr)
    x, y = x.ravel(), y.ravel()
    k = 2.0 * np.pi
    columns = [x, y, np.sin(k * x) * np.cos(k * y), -np.cos(k * x) * np.sin(k * y)]
    header = "x [m], y [m], velocity_x [m/s], velocity_y [m/s]"
    pressure = 0.25 * (np.cos(2.0 * k * x) + np.cos(2.0 * k * y))
    if with_pressure:
        columns.append(pressure)
        header += ", pressure [Pa]"
    np.savetxt(path, np.column_stack(columns), delimiter=", ", header=header, comments="",
               fmt="%.17g")
    return np.column_stack([x, y]), pressure


class TaylorGreenPressure(unittest.TestCase):
    def run_vortex(self, work, with_pressure, steps):
        name = "with" if with_pressure else "without"
        positions, pressure = taylor_green_points(os.path.join(work, name + ".csv"), 32,
                                                  with_pressure)
        with open(os.path.join(work, name + ".toml"), "w") as out:
            out.write(TAYLOR_GREEN.format(file=name + ".csv"))
        made = run("run", name + ".toml", "--steps", str(steps), "--threads", "2", "--out", name,
                   cwd=work)
        self.assertEqual(made.returncode, 0, made.stderr)
        with open(os.path.join(work, name, "energy.csv")) as rows:
            kinetic = [float({k.split(" [")[0]: v for k, v in row.items()}["kinetic"])
                       for row in csv.DictReader(rows)]
        return positions, pressure, np.array(kinetic)

    def test_the_files_pressure_is_the_initial_pressure(self):
        with tempfile.TemporaryDirectory() as work:
            positions, pressure, kinetic = self.run_vortex(work, True, 30)
            start = os.path.join(work, "with", "snapshots", "step_000000000.h5")
            with h5py.File(start, "r") as f:
                np.testing.assert_array_equal(f["particles/fluid/position"][...], positions)
                initial = f["particles/fluid/pressure"][...]
            # The density is held in fixed point (its scale's step below 1e-12 kg/m^3 here);
            # the Tait pressure's slope there is c^2 (rho/rho0)^6: the pressure to 1e-9 Pa, of
            # pressures up to 0.5 Pa.
            self.assertLess(np.max(np.abs(initial - pressure)), 1e-9)
            _, _, without = self.run_vortex(work, False, 30)
            # Without its pressure the vortex starts out of balance: sound waves take kinetic
            # energy and give it back (5.9e-3 of it within 30 steps, half the time sound takes
            # to cross the box); with it, 9.6e-4. (Later, from about step 40, the inviscid vortex
            # on a square lattice loses its kinetic energy to noise either way.)
            drift_with = np.max(np.abs(kinetic / kinetic[0] - 1.0))
            drift_without = np.max(np.abs(without / without[0] - 1.0))
            print(f"\nTaylor-Green, 30 steps: max |KE/KE0 - 1| {drift_with:.2e} with the file's "
                  f"pressure, {drift_without:.2e} without", file=sys.stderr)
            self.assertLess(drift_with, 0.25 * drift_without)


if __name__ == "__main__":
    unittest.main()
