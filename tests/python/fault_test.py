#!/usr/bin/python3
"""Faults stop a run with the stated message, a non-zero status and an intact last snapshot;
damaged and foreign snapshot files are refused.

The case files are derived from `revsph cases dambreak-small` (parsed with tomllib, edited,
written back as TOML) so that each fault happens naturally in the middle of a run:
  - escaping particle: no walls, the domain ends 0.2 m below the column, which falls out of it;
  - overflow: the same free fall with a velocity scale of 2^-62 m/s (range +-2 m/s) in a deep
    domain: the velocity leaves the fixed-point range before the particles leave the domain;
  - NaN: walls with epsilon = 0, a good snapshot edited with h5py so that one fluid particle sits
    exactly on a wall particle (0/0 in the wall force), its state hash recomputed in Python.
The particle index each fault names is worked out independently: for the first two from the
snapshot one step before the fault, by redoing the kick and drift of the failing step in exact
integer arithmetic; for the NaN by choosing the particle.

Usage: fault_test.py REVSPH_BINARY [unittest options]   (or REVSPH=... in the environment)
"""

import glob
import json
import os
import re
import shutil
import subprocess
import tomllib
import unittest

import h5py
import numpy as np

from revsph_testing import (environment, python_state_hash, run_unittests, snapshot_step,
                            text_attr)

REVSPH = None
WORK = None

# Exit statuses of revsph.
OK, BAD_INPUT, STOPPED = 0, 2, 3
FREE_FALL_DR = 0.05  # 20 x 40 fluid particles
SNAPSHOT_EVERY = 200
INT64_MIN, INT64_MAX = -(2 ** 63), 2 ** 63 - 1


# ----------------------------------------------------------------------------------------------
# helpers

def run_revsph(*args, timeout=240):
    return subprocess.run([REVSPH, *[str(a) for a in args]], capture_output=True, text=True,
                          timeout=timeout, env=environment())


def toml_value(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value)
    if isinstance(value, list):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    raise TypeError(value)


def toml_text(case):
    """Writes the subset of TOML that case files use: scalars, arrays, tables, arrays of tables."""
    lines = [f"{key} = {toml_value(value)}" for key, value in case.items()
             if not isinstance(value, dict) and not (isinstance(value, list) and value
                                                     and isinstance(value[0], dict))]
    for key, value in case.items():
        if isinstance(value, dict):
            lines += ["", f"[{key}]"] + [f"{k} = {toml_value(v)}" for k, v in value.items()]
        elif isinstance(value, list) and value and isinstance(value[0], dict):
            for table in value:
                lines += ["", f"[[{key}]]"] + [f"{k} = {toml_value(v)}" for k, v in table.items()]
    return "\n".join(lines) + "\n"


def builtin_case(name="dambreak-small"):
    result = run_revsph("cases", name)
    assert result.returncode == 0, result.stderr
    return tomllib.loads(result.stdout)


def write_case(case, name):
    path = os.path.join(WORK, name + ".toml")
    with open(path, "w") as f:
        f.write(toml_text(case))
    return path


def free_fall_case(name, domain_min_y, velocity_exponent=None, extra_block=None):
    """The dam-break column without walls, falling freely; `extra_block` = (min, max) adds a
    second fluid block (its particles come after the column's)."""
    case = builtin_case()
    case["name"] = name
    case["discretisation"]["dr"] = FREE_FALL_DR
    case["particles"] = [b for b in case["particles"] if b["kind"] == "fluid"]
    assert len(case["particles"]) == 1
    if extra_block is not None:
        block = dict(case["particles"][0])
        block["min"], block["max"] = extra_block
        case["particles"].append(block)
    case["domain"]["min"] = [case["domain"]["min"][0], domain_min_y]
    case["output"] = {"energy_every": 100, "snapshot_every": SNAPSHOT_EVERY}
    if velocity_exponent is not None:
        case["fixed_point"] = {"velocity_exponent": velocity_exponent}
    return case


def read_state(path):
    """Raw state, views and attributes of a snapshot."""
    with h5py.File(path, "r") as h5:
        state = {}
        for entry in h5.attrs["field_order"]:
            dataset = h5["/state/" + text_attr(entry)]
            state[text_attr(entry)] = (dataset[()], int(dataset.attrs["scale_exponent"]))
        views = {name: h5["/particles/fluid/" + name][()] for name in h5["/particles/fluid"]}
        attrs = {key: h5.attrs[key] for key in ("step", "dt", "time")}
    return state, views, attrs


def fixed_increment(value, exponent):
    """Arith::try_increment's conversion: llrint(value * 2^-exponent), None if out of range."""
    quotient = value * 2.0 ** (-exponent)
    out = ~(np.abs(quotient) < 2.0 ** 63)
    rounded = np.rint(np.where(out, 0.0, quotient)).astype(np.int64)
    return rounded, out


def checked_add(raw, delta):
    """raw + delta in int64 and a mask of the entries that overflow."""
    total = raw.astype(object) + delta.astype(object)
    overflow = np.vectorize(lambda t: t < INT64_MIN or t > INT64_MAX)(total).astype(bool)
    return np.where(overflow, 0, total).astype(np.int64), overflow


def first_kick_and_drift(path):
    """Redoes the first kick (v += round(dt/2 a)) and the drift (x += round(dt v)) of the step
    after the snapshot, exactly as the engine does (core/verlet.hpp, FixedArithmetic). The
    acceleration view holds the exact doubles of the fixed-point force sums the kick uses."""
    state, views, attrs = read_state(path)
    dt = float(attrs["dt"])
    x, x_exponent = state["fluid/position"]
    v, v_exponent = state["fluid/velocity"]
    a = views["acceleration"]
    delta, out = fixed_increment((0.5 * dt) * a, v_exponent)
    v1, overflow = checked_add(v, delta)
    kick_overflow = out | overflow
    drift = dt * (v1.astype(np.float64) * 2.0 ** v_exponent)
    delta_x, out_x = fixed_increment(drift, x_exponent)
    assert not out_x.any()
    x1, overflow_x = checked_add(x, delta_x)
    assert not overflow_x.any()
    return {"x": x1.astype(np.float64) * 2.0 ** x_exponent, "v1": v1, "a": a,
            "kick_overflow": kick_overflow, "dt": dt, "v_exponent": v_exponent,
            "step": int(attrs["step"])}


def first_particle(mask_rows):
    """The lowest particle index whose row has a True entry (FaultRecorder keeps the lowest)."""
    rows = np.nonzero(mask_rows.reshape(mask_rows.shape[0], -1).any(axis=1))[0]
    return int(rows[0]) if rows.size else None


# ----------------------------------------------------------------------------------------------

class FaultTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        # A good run with walls and epsilon = 0: the base of the NaN case and the refusals.
        case = builtin_case()
        case["name"] = "walls-eps0"
        case["discretisation"]["dr"] = 0.04
        case["wall"]["epsilon"] = 0.0
        case["output"] = {"energy_every": 50, "snapshot_every": 50}
        cls.wall_case = write_case(case, "walls-eps0")
        cls.wall_out = os.path.join(WORK, "walls-eps0")
        result = run_revsph("run", cls.wall_case, "--out", cls.wall_out, "--steps", 100)
        if result.returncode != OK:
            raise AssertionError(f"the base run failed ({result.returncode}): {result.stderr}")
        cls.good = os.path.join(cls.wall_out, "snapshots", "step_000000100.h5")
        cls.other_good = os.path.join(cls.wall_out, "snapshots", "step_000000050.h5")

    # -- checks shared by the fault cases -------------------------------------------------------

    def stopped_message(self, result):
        """The one stderr line of a stopped run; returns the message after 'the run stopped: '."""
        self.assertEqual(result.returncode, STOPPED, result.stderr)
        lines = result.stderr.splitlines()
        self.assertEqual(len(lines), 1, result.stderr)
        prefix = "revsph: error: the run stopped: "
        self.assertTrue(lines[0].startswith(prefix), lines[0])
        return lines[0][len(prefix):]

    def assert_intact_snapshot(self, path):
        self.assertTrue(os.path.isfile(path), path)
        with h5py.File(path, "r") as h5:
            for entry in h5.attrs["field_order"]:
                h5["/state/" + text_attr(entry)][()]
            for set_name in h5["/particles"]:
                for name in h5["/particles/" + set_name]:
                    h5[f"/particles/{set_name}/{name}"][()]
            recorded = text_attr(h5.attrs["state_hash"])
            self.assertEqual(python_state_hash(h5), recorded, path)
            step = int(h5.attrs["step"])
        result = run_revsph("hash", path)
        self.assertEqual(result.returncode, OK, result.stderr)
        self.assertEqual(result.stdout.strip(), recorded)
        return step, recorded

    def stopped_run(self, out, message, fault_step):
        """summary.json of a stopped run, and its last snapshot checked; returns that snapshot."""
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        self.assertIs(summary["completed"], False)
        self.assertIn(message, summary["failure"])
        self.assertEqual(summary["final_step"], fault_step - 1)
        if fault_step > 1 + summary["start_step"]:
            # The steps taken before the fault were timed (it read 0 for a stopped run).
            self.assertGreater(summary["stepping_seconds"], 0.0)
            self.assertGreater(summary["stepping_particle_steps_per_second"], 0.0)
        snapshots = sorted(glob.glob(os.path.join(out, "snapshots", "step_*.h5")))
        self.assertEqual(glob.glob(os.path.join(out, "snapshots", "*.tmp")), [])
        self.assertIn("last_snapshot", summary)
        last = summary["last_snapshot"]
        self.assertEqual(os.path.realpath(last), os.path.realpath(snapshots[-1]))
        step, _ = self.assert_intact_snapshot(last)
        self.assertEqual(step, snapshot_step(last))
        self.assertLess(step, fault_step)
        self.assertEqual(summary["snapshots_written"], len(snapshots))
        return last, summary

    def snapshot_before(self, last, fault_step, name):
        """Continues from `last` to the step before the fault (restart must work); returns the
        snapshot at fault_step - 1."""
        out = os.path.join(WORK, name)
        steps = fault_step - 1 - snapshot_step(last)
        result = run_revsph("run", "--from", last, "--out", out, "--steps", steps)
        self.assertEqual(result.returncode, OK, f"restart from {last}: {result.stderr}")
        before = os.path.join(out, "snapshots", f"step_{fault_step - 1:09d}.h5")
        self.assert_intact_snapshot(before)
        return before

    def assert_same_fault_again(self, before, message, name):
        """One step from the snapshot before the fault reproduces the fault exactly."""
        result = run_revsph("run", "--from", before, "--out", os.path.join(WORK, name),
                            "--steps", 5)
        self.assertEqual(self.stopped_message(result), message)

    # -- the three faults -----------------------------------------------------------------------

    def test_escaping_particle(self):
        # A second, small block hangs lower than the column and leaves the domain first: the
        # particle named is not particle 0.
        domain_min_y = -0.2
        case = free_fall_case("escape", domain_min_y, extra_block=([2.0, -0.1], [2.5, 0.1]))
        path = write_case(case, "escape")
        out = os.path.join(WORK, "escape")
        result = run_revsph("run", path, "--out", out, "--steps", 100000)
        message = self.stopped_message(result)
        match = re.fullmatch(r"step (\d+): fluid particle (\d+): position: left the domain: "
                             r"outside the domain on axis (\d) \(coordinate (\S+), "
                             r"domain \[(\S+), (\S+)\]\)", message)
        self.assertIsNotNone(match, message)
        step, particle, axis = (int(match.group(k)) for k in range(1, 4))
        coordinate = float(match.group(4))
        self.assertEqual(axis, 1)
        self.assertEqual(float(match.group(5)), domain_min_y)
        self.assertLess(coordinate, domain_min_y)
        last, _ = self.stopped_run(out, message, step)
        # A few snapshots before the fault: the fall takes ~0.2 s = ~800 steps.
        self.assertGreaterEqual(snapshot_step(last), 3 * SNAPSHOT_EVERY)

        before = self.snapshot_before(last, step, "escape-before")
        predicted = first_kick_and_drift(before)
        with h5py.File(before, "r") as h5:
            x_before = h5["/particles/fluid/position"][()]
        lo = np.array(case["domain"]["min"], dtype=float)
        hi = np.array(case["domain"]["max"], dtype=float)
        self.assertTrue(np.all((x_before >= lo) & (x_before <= hi)), "inside before the step")
        self.assertFalse(predicted["kick_overflow"].any())
        outside = ~((predicted["x"] >= lo) & (predicted["x"] <= hi))
        self.assertEqual(first_particle(outside), particle)
        column = round(1.0 / FREE_FALL_DR) * round(2.0 / FREE_FALL_DR)
        self.assertGreaterEqual(particle, column, "a particle of the lower block")
        self.assertAlmostEqual(predicted["x"][particle, 1], coordinate,
                               delta=1e-5 * abs(coordinate))
        self.assert_same_fault_again(before, message, "escape-again")

    def test_velocity_overflow(self):
        case = free_fall_case("overflow", -1.0, velocity_exponent=-62)  # |v| < 2 m/s
        path = write_case(case, "overflow")
        out = os.path.join(WORK, "overflow")
        result = run_revsph("run", path, "--out", out, "--steps", 100000)
        message = self.stopped_message(result)
        match = re.fullmatch(r"step (\d+): fluid particle (\d+): velocity: overflow or non-finite "
                             r"value in a kick", message)
        self.assertIsNotNone(match, message)
        step, particle = int(match.group(1)), int(match.group(2))
        last, _ = self.stopped_run(out, message, step)
        self.assertGreaterEqual(snapshot_step(last), 3 * SNAPSHOT_EVERY)

        before = self.snapshot_before(last, step, "overflow-before")
        with h5py.File(before, "r") as h5:
            self.assertEqual(int(h5["/state/fluid/velocity"].attrs["scale_exponent"]), -62)
            velocity = h5["/particles/fluid/velocity"][()]
            position = h5["/particles/fluid/position"][()]
        self.assertTrue(np.all(np.abs(velocity) < 2.0))
        self.assertTrue(np.all(position[:, 1] > -1.0), "the particles are still in the domain")
        predicted = first_kick_and_drift(before)
        if predicted["kick_overflow"].any():  # in the first kick of the step: exact
            expected = first_particle(predicted["kick_overflow"])
        else:
            # In the second kick, with the acceleration at the drifted positions; in free fall
            # it is the acceleration before the drift (gravity alone: pressure is zero).
            delta, out_of_range = fixed_increment((0.5 * predicted["dt"]) * predicted["a"],
                                                  predicted["v_exponent"])
            _, overflow = checked_add(predicted["v1"], delta)
            expected = first_particle(overflow | out_of_range)
        self.assertEqual(expected, particle)
        self.assert_same_fault_again(before, message, "overflow-again")

    def nan_snapshot(self):
        """The good snapshot with one fluid particle moved exactly onto a wall particle, hash
        rewritten; returns (path, fluid particle, wall particle, step)."""
        if hasattr(self, "_nan"):
            return self._nan
        path = os.path.join(WORK, "nan.h5")
        shutil.copy(self.good, path)
        with h5py.File(path, "r+") as h5:
            fluid = h5["/particles/fluid/position"][()]
            wall = h5["/particles/wall/position"][()]
            dr = 0.04
            distance = np.linalg.norm(fluid[:, None, :] - wall[None, :, :], axis=2)
            near = np.nonzero(distance.min(axis=1) < 1.5 * dr)[0]
            self.assertGreater(near.size, 2)
            particle = int(near[len(near) // 2])  # not the lowest index: the report must name it
            wall_particle = int(np.argmin(distance[particle]))
            raw = h5["/state/fluid/position"][()]
            raw[particle] = h5["/state/wall/position"][wall_particle]
            h5["/state/fluid/position"][...] = raw
            h5.attrs["state_hash"] = python_state_hash(h5)
            step = int(h5.attrs["step"])
        FaultTest._nan = (path, particle, wall_particle, step)
        return FaultTest._nan

    def nan_run(self):
        """`revsph run --from` the NaN snapshot (once); returns its result and directory."""
        if not hasattr(self, "_nan_run"):
            path = self.nan_snapshot()[0]
            out = os.path.join(WORK, "nan-run")
            FaultTest._nan_run = (run_revsph("run", "--from", path, "--out", out, "--steps", 20),
                                  out)
        return FaultTest._nan_run

    def test_nan_stops_the_run(self):
        path, particle, wall_particle, step = self.nan_snapshot()
        self.assert_intact_snapshot(path)  # revsph accepts the rewritten hash
        result, out = self.nan_run()
        message = self.stopped_message(result)
        # The forces of the restart state are those of the first step after the snapshot.
        self.assertTrue(message.startswith(f"step {step + 1}: fluid particle {particle}: "
                                           f"acceleration: "),
                        f"{message!r} (fluid particle {particle} on wall particle "
                        f"{wall_particle}, restart at step {step})")
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        self.assertIs(summary["completed"], False)
        self.assertIn(message, summary["failure"])
        self.assertEqual(summary["final_step"], step)

    def test_nan_run_keeps_its_restart_snapshot(self):
        path, particle, wall_particle, step = self.nan_snapshot()
        edited_hash = self.assert_intact_snapshot(path)[1]
        result, out = self.nan_run()
        self.assertEqual(result.returncode, STOPPED, result.stderr)
        # The snapshot written at the start of the restarted run holds the state it started from.
        restart_snapshot = os.path.join(out, "snapshots", f"step_{step:09d}.h5")
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        self.assertEqual(summary.get("last_snapshot"), restart_snapshot,
                         "the stopped run has no snapshot of its restart step")
        self.assertEqual(self.assert_intact_snapshot(restart_snapshot), (step, edited_hash))

    def test_good_snapshot_continues(self):
        # The same snapshot unedited runs on: the fault above comes from the edit.
        result = run_revsph("run", "--from", self.good, "--out", os.path.join(WORK, "good-run"),
                            "--steps", 5)
        self.assertEqual(result.returncode, OK, result.stderr)

    # -- refused files --------------------------------------------------------------------------

    def assert_refused(self, path, *phrases, diff=True):
        """hash, run --from and (if `diff`) diff on either side refuse the file: status 2, one
        error line naming the file and containing `phrases`, nothing on stdout, no output
        directory."""
        out = os.path.join(WORK, "refused-" + os.path.basename(path))
        commands = {"hash": ["hash", path],
                    "run --from": ["run", "--from", path, "--out", out, "--steps", 1]}
        if diff:
            commands["diff (first)"] = ["diff", path, self.good]
            commands["diff (second)"] = ["diff", self.good, path]
        for name, args in commands.items():
            with self.subTest(command=name, file=os.path.basename(path)):
                result = run_revsph(*args)
                self.assertEqual(result.returncode, BAD_INPUT, result.stderr)
                lines = result.stderr.splitlines()
                self.assertEqual(len(lines), 1, result.stderr)
                self.assertTrue(lines[0].startswith("revsph: error: "), lines[0])
                self.assertIn(path, lines[0])
                for phrase in phrases:
                    self.assertIn(phrase, lines[0])
                self.assertEqual(result.stdout, "")
                self.assertFalse(os.path.exists(out), "nothing is written for a refused file")

    def test_edit_without_new_hash_is_refused(self):
        path = os.path.join(WORK, "edited-stale-hash.h5")
        shutil.copy(self.good, path)
        with h5py.File(path, "r+") as h5:
            raw = h5["/state/fluid/position"][()]
            raw[7, 0] += 1  # one unit in the last place of one coordinate
            h5["/state/fluid/position"][...] = raw
            self.assertNotEqual(python_state_hash(h5), text_attr(h5.attrs["state_hash"]))
        # diff reads it with a warning instead (test_diff_locates_the_edit_of_a_stale_hash_file).
        self.assert_refused(path, "hash", diff=False)

    def test_diff_locates_the_edit_of_a_stale_hash_file(self):
        # A comparison is how one finds what was changed in a damaged file: diff warns that the
        # hash does not match, and still names the edited value.
        path = os.path.join(WORK, "edited-for-diff.h5")
        shutil.copy(self.good, path)
        with h5py.File(path, "r+") as h5:
            raw = h5["/state/fluid/velocity"][()]
            raw[11, 1] -= 3
            h5["/state/fluid/velocity"][...] = raw
        for args in ((self.good, path), (path, self.good)):
            with self.subTest(order=[os.path.basename(a) for a in args]):
                result = run_revsph("diff", *args)
                self.assertEqual(result.returncode, 1, result.stderr)
                warnings = result.stderr.splitlines()
                self.assertEqual(len(warnings), 1, result.stderr)
                self.assertTrue(warnings[0].startswith(f"revsph: warning: {path}: "), warnings[0])
                self.assertIn("does not match the hash recorded", warnings[0])
                verdict = [line for line in result.stdout.splitlines()
                           if line.startswith("verdict: ")]
                self.assertEqual(len(verdict), 1, result.stdout)
                self.assertIn("first difference at fluid particle 11, velocity[1]", verdict[0])
                self.assertRegex(verdict[0], r"; 1 of \d+ values differ")
                self.assertIn("largest difference 3 units in the last place", verdict[0])
        # The intact file alone: no warning.
        result = run_revsph("diff", self.good, self.good)
        self.assertEqual((result.returncode, result.stderr), (OK, ""))

    def test_truncated_snapshot_is_refused(self):
        path = os.path.join(WORK, "truncated.h5")
        with open(self.good, "rb") as f:
            data = f.read()
        with open(path, "wb") as f:
            f.write(data[:len(data) // 2])
        self.assert_refused(path)

    def test_foreign_hdf5_is_refused(self):
        path = os.path.join(WORK, "foreign.h5")
        with h5py.File(path, "w") as h5:
            h5["/state/fluid/position"] = np.zeros((4, 2), dtype=np.int64)
            h5.attrs["step"] = 3
        self.assert_refused(path, "not a revsph snapshot")

    def test_future_format_version_is_refused(self):
        path = os.path.join(WORK, "version99.h5")
        shutil.copy(self.good, path)
        with h5py.File(path, "r+") as h5:
            h5.attrs["format_version"] = np.int64(99)
            self.assertEqual(python_state_hash(h5), text_attr(h5.attrs["state_hash"]))
        self.assert_refused(path, "version 99")

    def test_full_disk_stops_the_run_cleanly(self):
        # A full disk while writing a snapshot (issue 33's fault list): the one-line message and
        # exit status 3, where HDF5's exit handler used to crash afterwards (exit 139). A file
        # size limit stands in for the full disk: with SIGXFSZ ignored, writes past it fail
        # (EFBIG) as they would with ENOSPC.
        out = os.path.join(WORK, "full_disk")
        def limit_file_size():
            import resource
            import signal
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
            resource.setrlimit(resource.RLIMIT_FSIZE, (100 * 1024, 100 * 1024))
        result = subprocess.run([REVSPH, "run", "dambreak-small", "--steps", "10", "--out", out],
                                capture_output=True, text=True, timeout=240, env=environment(),
                                preexec_fn=limit_file_size)
        self.assertEqual(result.returncode, STOPPED, result.stderr)
        errors = [line for line in result.stderr.splitlines() if line.startswith("revsph: error:")]
        self.assertEqual(len(errors), 1, result.stderr)
        self.assertIn("writing snapshot", errors[0])
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        self.assertFalse(summary["completed"])
        self.assertIn("writing snapshot", summary["failure"])

    def test_intact_snapshots_are_accepted(self):
        # The reference for the refusals: the same commands accept the unmodified files.
        for path in (self.good, self.other_good):
            self.assert_intact_snapshot(path)
        result = run_revsph("diff", self.good, self.good)
        self.assertEqual(result.returncode, OK, result.stderr)
        result = run_revsph("diff", self.good, self.other_good)
        self.assertEqual(result.returncode, 1, result.stderr)


def main():
    run_unittests(globals(), "revsph_fault_")


if __name__ == "__main__":
    main()
