#!/usr/bin/python3
"""A second, independent reader of a run's XDMF + HDF5 output.

Runs a small dam break with a few snapshots, then reads run.xdmf with xml.etree and the HDF5
files it points to with h5py (no revsph code), and checks what it finds against the engine's own
numbers: particle counts (summary.json), times (snapshot steps * dt, energy.csv), the kinetic
energy recomputed from the velocity and mass views (energy.csv `kinetic`), the position view
against the raw fixed-point integers, and the SHA-256 state hash reimplemented from its
definition in verify/state_hash.cpp (against the file's attribute and `revsph hash`).

Usage: xdmf_reader_test.py REVSPH_BINARY [unittest options]   (or REVSPH=... in the environment)
"""

import csv
import glob
import json
import os
import re
import subprocess
import unittest
import xml.etree.ElementTree as ET

import h5py
import numpy as np

from revsph_testing import python_state_hash, run_unittests, text_attr

REVSPH = None
WORK = None

STEPS = 300
SNAPSHOT_EVERY = 100
ENERGY_EVERY = 50
OVERRIDES = ["discretisation.dr=0.04", f"output.snapshot_every={SNAPSHOT_EVERY}",
             f"output.energy_every={ENERGY_EVERY}"]


def run_revsph(*args, timeout=240):
    return subprocess.run([REVSPH, *args], capture_output=True, text=True, timeout=timeout)


def parse_dimensions(text):
    return tuple(int(n) for n in text.split())


class XdmfReaderTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.out = os.path.join(WORK, "run")
        args = ["run", "dambreak-small", "--out", cls.out, "--steps", str(STEPS)]
        for override in OVERRIDES:
            args += ["--set", override]
        result = run_revsph(*args)
        if result.returncode != 0:
            raise AssertionError(f"revsph run failed ({result.returncode}):\n{result.stderr}")
        with open(os.path.join(cls.out, "summary.json")) as f:
            cls.summary = json.load(f)
        with open(os.path.join(cls.out, "energy.csv"), newline="") as f:
            # Header cells are `name [unit]`.
            cls.energy_header = next(csv.reader(f))
            f.seek(0)
            cls.energy_rows = [{k.split(" [")[0]: v for k, v in row.items()}
                               for row in csv.DictReader(f)]
        cls.energy_by_step = {int(row["step"]): row for row in cls.energy_rows}
        cls.snapshot_files = sorted(glob.glob(os.path.join(cls.out, "snapshots", "step_*.h5")))
        cls.xdmf_path = os.path.join(cls.out, "run.xdmf")
        cls.grids = cls.read_xdmf(cls.xdmf_path)

    @staticmethod
    def read_xdmf(path):
        """[(time, [(set name, element count, {name: (h5 file, dataset path, dims, role)})])]"""
        root = ET.parse(path).getroot()
        assert root.tag == "Xdmf", root.tag
        domain = root.find("Domain")
        temporal = domain.find("Grid")
        assert temporal.get("GridType") == "Collection", temporal.attrib
        assert temporal.get("CollectionType") == "Temporal", temporal.attrib
        base = os.path.dirname(os.path.abspath(path))
        grids = []
        for step_grid in temporal.findall("Grid"):
            assert step_grid.get("CollectionType") == "Spatial", step_grid.attrib
            time = float(step_grid.find("Time").get("Value"))
            sets = []
            for uniform in step_grid.findall("Grid"):
                assert uniform.get("GridType") == "Uniform", uniform.attrib
                topology = uniform.find("Topology")
                assert topology.get("TopologyType") == "Polyvertex", topology.attrib
                elements = int(topology.get("NumberOfElements"))
                items = {}

                def add(name, item, role, geometry_type=None):
                    if item.get("ItemType") == "Function":
                        # A 2D vector padded to 3 components for ParaView: its two columns,
                        # hyperslabs of the (N, 2) dataset, joined with a zero.
                        assert item.get("Function") == "JOIN($0, $1, 0 * $0)", item.attrib
                        assert parse_dimensions(item.get("Dimensions")) == (elements, 3)
                        slabs = item.findall("DataItem")
                        assert [s.get("ItemType") for s in slabs] == ["HyperSlab"] * 2
                        for column, slab in enumerate(slabs):
                            selection = slab.find("DataItem").text.split()
                            assert selection == ["0", str(column), "1", "1", str(elements),
                                                 "1"], selection
                        sources = {slab.findall("DataItem")[1].text for slab in slabs}
                        assert len(sources) == 1, sources
                        item, role = slabs[0].findall("DataItem")[1], "Vector (2D, padded)"
                    assert item.get("Format") == "HDF", item.attrib
                    assert item.get("NumberType") == "Float", item.attrib
                    assert item.get("Precision") == "8", item.attrib
                    file_part, _, dataset = item.text.strip().rpartition(":")
                    items[name] = (os.path.join(base, file_part), dataset,
                                   parse_dimensions(item.get("Dimensions")), role, geometry_type)

                geometry = uniform.find("Geometry")
                geometry_items = geometry.findall("DataItem")
                assert len(geometry_items) == 1, "one DataItem in Geometry"
                add("position", geometry_items[0], "geometry", geometry.get("GeometryType"))
                for attribute in uniform.findall("Attribute"):
                    assert attribute.get("Center") == "Node", attribute.attrib
                    add(attribute.get("Name"), attribute.find("DataItem"),
                        attribute.get("AttributeType"))
                sets.append((uniform.get("Name"), elements, items))
            grids.append((time, sets))
        return grids

    @staticmethod
    def snapshot_step(path):
        match = re.fullmatch(r"step_(\d{9})\.h5", os.path.basename(path))
        assert match, path
        return int(match.group(1))

    def test_run_completed(self):
        self.assertTrue(self.summary["completed"])
        self.assertEqual(self.summary["final_step"], STEPS)
        steps = [self.snapshot_step(p) for p in self.snapshot_files]
        self.assertEqual(steps, list(range(0, STEPS + 1, SNAPSHOT_EVERY)))
        self.assertEqual(len(self.grids), len(steps))
        self.assertEqual(self.summary["snapshots_written"], len(steps))

    def test_energy_header_gives_units(self):
        # A 2D run's energies are per unit length (J/m), its errors pure numbers.
        self.assertEqual(self.energy_header[:3], ["step", "time [s]", "kinetic [J/m]"])
        self.assertEqual(self.energy_header[-3:],
                         ["total [J/m]", "relative_error [1]", "mechanical_relative_error [1]"])

    def test_datasets_match_dimensions_and_topology(self):
        checked = 0
        for time, sets in self.grids:
            # Empty particle sets (no dummies here) have no grid.
            self.assertEqual(sorted(name for name, _, _ in sets),
                             sorted(name for name, count in self.summary["particles"].items()
                                    if count > 0))
            for set_name, elements, items in sets:
                self.assertIn("position", items)
                for name, (file, dataset, dims, role, geometry_type) in items.items():
                    with self.subTest(time=time, set=set_name, field=name):
                        self.assertTrue(os.path.isfile(file), file)
                        self.assertEqual(dataset, f"/particles/{set_name}/{name}")
                        with h5py.File(file, "r") as h5:
                            data = h5[dataset][()]
                        self.assertEqual(data.dtype, np.float64)
                        self.assertEqual(data.shape, dims)
                        self.assertEqual(data.shape[0], elements)
                        if role == "geometry":
                            self.assertEqual(geometry_type, "XY")
                            self.assertEqual(data.shape, (elements, 2))
                        elif len(dims) == 1:
                            self.assertEqual(role, "Scalar")
                        elif dims[1] == 2:
                            self.assertEqual(role, "Vector (2D, padded)")
                        else:
                            self.assertEqual(role, "Vector" if dims[1] == 3 else "Matrix")
                        self.assertTrue(np.all(np.isfinite(data)))
                        checked += 1
        self.assertGreater(checked, 4 * 2)

    def test_particle_counts_match_summary(self):
        for time, sets in self.grids:
            counts = {name: elements for name, elements, _ in sets}
            self.assertEqual(counts, {name: count for name, count in self.summary["particles"].items()
                                      if count > 0})
            file = sets[0][2]["position"][0]
            with h5py.File(file, "r") as h5:
                for set_name, count in self.summary["particles"].items():
                    self.assertEqual(h5[f"/state/{set_name}/position"].shape[0], count)

    def test_times_match_steps_and_energy_log(self):
        dt = self.summary["dt"]
        times = [time for time, _ in self.grids]
        self.assertEqual(times, sorted(times))
        files = []
        for time, sets in self.grids:
            file = sets[0][2]["position"][0]
            self.assertTrue(all(item[0] == file for _, _, items in sets for item in items.values()),
                            "one snapshot file per time")
            files.append(file)
        self.assertEqual([os.path.realpath(f) for f in files],
                         [os.path.realpath(f) for f in self.snapshot_files])
        for time, file in zip(times, files):
            step = self.snapshot_step(file)
            with self.subTest(step=step):
                self.assertEqual(time, step * dt)  # the engine's time is steps * dt, exactly
                with h5py.File(file, "r") as h5:
                    self.assertEqual(int(h5.attrs["step"]), step)
                    self.assertEqual(float(h5.attrs["time"]), time)
                    self.assertEqual(float(h5.attrs["dt"]), dt)
                self.assertIn(step, self.energy_by_step)
                self.assertEqual(float(self.energy_by_step[step]["time"]), time)
        # Every energy row is at a multiple of energy_every, and the times agree with step * dt.
        for row in self.energy_rows:
            self.assertEqual(int(row["step"]) % ENERGY_EVERY, 0)
            self.assertEqual(float(row["time"]), int(row["step"]) * dt)

    def test_kinetic_energy_matches_energy_log(self):
        for time, sets in self.grids:
            items = dict((name, items) for name, _, items in sets)["fluid"]
            file = items["velocity"][0]
            step = self.snapshot_step(file)
            with h5py.File(file, "r") as h5:
                velocity = h5[items["velocity"][1]][()]
                mass = h5[items["mass"][1]][()]
                per_particle = h5[items["kinetic_energy"][1]][()]
            # Serial sum in particle order, like the engine (any order agrees to ~1e-15).
            total = 0.0
            for m, v in zip(mass.tolist(), velocity.tolist()):
                v_squared = 0.0
                for component in v:
                    v_squared += component * component
                total += 0.5 * m * v_squared
            logged = float(self.energy_by_step[step]["kinetic"])
            with self.subTest(step=step, recomputed=total, logged=logged):
                self.assertGreaterEqual(total, 0.0)
                if step == 0:
                    self.assertEqual(logged, 0.0)
                    self.assertEqual(total, 0.0)
                else:
                    self.assertGreater(logged, 0.0)
                    self.assertLessEqual(abs(total - logged), 1e-12 * abs(logged))
                    self.assertLessEqual(abs(float(np.sum(per_particle)) - logged),
                                         1e-12 * abs(logged))
                    self.assertTrue(np.allclose(per_particle,
                                                0.5 * mass * np.sum(velocity * velocity, axis=1),
                                                rtol=1e-14, atol=0.0))
        final = self.summary["energy"]["final"]["kinetic"]
        self.assertEqual(final, float(self.energy_by_step[STEPS]["kinetic"]))

    def test_energy_errors_follow_their_definitions(self):
        """energy.csv's two relative errors recomputed from its own columns (docs/verify.md):
        relative_error = |E - E0| / max(|E0|, largest |term| so far); mechanical_relative_error
        = |E - E0| / M, M the running maximum over rows and terms of |kinetic| and, for every
        other term, |term - its first value|."""
        header = list(self.energy_rows[0].keys())
        self.assertEqual(header[-3:], ["total", "relative_error", "mechanical_relative_error"])
        terms = header[2:-3]
        self.assertIn("kinetic", terms)
        first = {name: float(self.energy_rows[0][name]) for name in terms}
        total0 = float(self.energy_rows[0]["total"])
        scale = mechanical = 0.0
        largest_deviation = 0.0
        for row in self.energy_rows:
            values = {name: float(row[name]) for name in terms}
            deviation = abs(float(row["total"]) - total0)
            largest_deviation = max(largest_deviation, deviation)
            scale = max([scale, abs(total0)] + [abs(v) for v in values.values()])
            mechanical = max([mechanical] + [abs(values[name]) if name == "kinetic"
                                             else abs(values[name] - first[name])
                                             for name in terms])
            expected = deviation / mechanical if mechanical > 0 else 0.0
            with self.subTest(step=row["step"]):
                self.assertAlmostEqual(float(row["relative_error"]), deviation / scale,
                                       delta=1e-12 * deviation / scale + 1e-300)
                self.assertAlmostEqual(float(row["mechanical_relative_error"]), expected,
                                       delta=1e-9 * expected + 1e-300)
        # The dam break starts at rest: what moved is the drop of the gravitational energy, and
        # that is far smaller than E0, which the water's compressional energy dominates.
        drop = first["gravitational"] - min(float(r["gravitational"]) for r in self.energy_rows)
        self.assertGreater(mechanical, 0.0)
        self.assertGreaterEqual(mechanical, drop * (1 - 1e-12))
        self.assertLess(mechanical, 0.1 * abs(total0))
        energy = self.summary["energy"]
        self.assertAlmostEqual(energy["mechanical_scale"], mechanical, delta=1e-12 * mechanical)
        self.assertAlmostEqual(energy["max_mechanical_relative_error"],
                               largest_deviation / mechanical,
                               delta=1e-9 * largest_deviation / mechanical + 1e-300)

    def test_position_view_is_raw_times_scale(self):
        for file in self.snapshot_files:
            with h5py.File(file, "r") as h5:
                for set_name in self.summary["particles"]:
                    raw_dataset = h5[f"/state/{set_name}/position"]
                    self.assertEqual(text_attr(raw_dataset.attrs["raw_kind"]), "fixed_point")
                    exponent = int(raw_dataset.attrs["scale_exponent"])
                    raw = raw_dataset[()]
                    self.assertEqual(raw.dtype, np.int64)
                    view = h5[f"/particles/{set_name}/position"][()]
                    expected = np.ldexp(raw.astype(np.float64), exponent)
                    with self.subTest(file=os.path.basename(file), set=set_name):
                        self.assertEqual(view.shape, raw.shape)
                        self.assertTrue(np.array_equal(view, expected))

    def test_state_hash_reimplemented(self):
        hashes = set()
        for file in self.snapshot_files:
            with h5py.File(file, "r") as h5:
                recorded = text_attr(h5.attrs["state_hash"])
                mine = python_state_hash(h5)
            result = run_revsph("hash", file)
            with self.subTest(file=os.path.basename(file)):
                self.assertEqual(result.returncode, 0, result.stderr)
                self.assertEqual(mine, recorded)
                self.assertEqual(result.stdout.strip(), recorded)
            hashes.add(mine)
        self.assertEqual(len(hashes), len(self.snapshot_files), "states differ between snapshots")
        with h5py.File(self.snapshot_files[0], "r") as h5:
            self.assertEqual(python_state_hash(h5), self.summary["initial_hash"])
        with h5py.File(self.snapshot_files[-1], "r") as h5:
            self.assertEqual(python_state_hash(h5), self.summary["final_hash"])


def main():
    run_unittests(globals(), "revsph_xdmf_")


if __name__ == "__main__":
    main()
