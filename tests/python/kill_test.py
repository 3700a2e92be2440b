#!/usr/bin/python3
"""SIGKILL a run at random moments; every snapshot left behind must be complete and readable.

A reference run (not killed) gives the duration of the run and the state hash of every snapshot.
Then the same run is started again and again and killed with SIGKILL after a random delay
(seeded; the seed and every delay are printed): a few very early kills (before the first
snapshot is written), the rest spread over the whole run (one random moment in each of equal
slices of its duration). After each kill:
  - every snapshots/step_*.h5 (final names only; *.tmp leftovers are counted and ignored) opens
    with h5py, every dataset of field_order and every view is readable with the right shape,
    the state hash recorded in it is the reference run's hash at that step, and `revsph hash`
    on it exits 0 and prints that hash;
  - run.xdmf, if present, is well-formed XML and references only snapshot files that exist and
    passed the checks above;
  - energy.csv holds only complete lines (header plus rows with every column, steps increasing);
  - a restart from the newest complete snapshot (`revsph run --from`) for a few steps exits 0,
    and where the reference run has a snapshot at its final step the hashes agree.
A summary line reports kills tried, snapshots checked and tmp leftovers seen.

Usage: kill_test.py REVSPH_BINARY [unittest options]   (or REVSPH=... in the environment)
Environment: REVSPH_KILL_SEED (default: from the clock), REVSPH_KILLS (default 24).
"""

import concurrent.futures
import csv
import glob
import os
import random
import shutil
import signal
import statistics
import subprocess
import time
import unittest
import xml.etree.ElementTree as ET

import h5py
import numpy as np

from revsph_testing import environment, run_unittests, snapshot_step, text_attr

REVSPH = None
WORK = None

STEPS = 80
SNAPSHOT_EVERY = 4
RESTART_STEPS = SNAPSHOT_EVERY
EARLY_KILLS = 4
OVERRIDES = ["discretisation.dr=0.04", f"output.snapshot_every={SNAPSHOT_EVERY}",
             "output.energy_every=2"]


def run_command(out):
    args = [REVSPH, "run", "dambreak-small", "--out", out, "--steps", str(STEPS)]
    for override in OVERRIDES:
        args += ["--set", override]
    return args


class SnapshotProblem(Exception):
    pass


def check_snapshot_file(path, particle_counts):
    """Reads everything in the snapshot with h5py; returns (step, recorded hash)."""
    try:
        with h5py.File(path, "r") as h5:
            if text_attr(h5.attrs["format"]) != "revsph-snapshot":
                raise SnapshotProblem("format attribute")
            step = int(h5.attrs["step"])
            recorded = text_attr(h5.attrs["state_hash"])
            order = [text_attr(x) for x in h5.attrs["field_order"]]
            if not order:
                raise SnapshotProblem("empty field_order")
            for set_and_name in order:
                particle_set = set_and_name.split("/", 1)[0]
                dataset = h5["/state/" + set_and_name]
                components = int(dataset.attrs["components"])
                data = dataset[()]
                expected = (particle_counts[particle_set],) if components == 1 else (
                    particle_counts[particle_set], components)
                if data.dtype != np.int64 or data.shape != expected:
                    raise SnapshotProblem(f"{set_and_name}: {data.dtype} {data.shape}, "
                                          f"expected int64 {expected}")
            for particle_set, count in particle_counts.items():
                group = h5["/particles/" + particle_set]
                for name in group:
                    data = group[name][()]
                    if data.dtype != np.float64 or data.shape[0] != count:
                        raise SnapshotProblem(f"view {particle_set}/{name}: {data.shape}")
    except SnapshotProblem:
        raise
    except Exception as error:  # h5py raises OSError, KeyError, … for a damaged file
        raise SnapshotProblem(f"{type(error).__name__}: {error}") from error
    if step != snapshot_step(path):
        raise SnapshotProblem(f"step attribute {step} in {os.path.basename(path)}")
    return step, recorded


def last_logged_step(out):
    """The step of the last complete energy.csv row, None if there is none."""
    try:
        with open(os.path.join(out, "energy.csv")) as f:
            lines = [line for line in f.read().split("\n")[1:-1] if line]
    except FileNotFoundError:
        return None
    return int(lines[-1].split(",")[0]) if lines else None


def revsph_hash(path):
    result = subprocess.run([REVSPH, "hash", path], capture_output=True, text=True, timeout=60,
                            env=environment())
    return result.returncode, result.stdout.strip(), result.stderr.strip()


class KillTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        seed_text = os.environ.get("REVSPH_KILL_SEED")
        cls.seed = int(seed_text) if seed_text else int(time.time() * 1000) % (2 ** 31)
        cls.kills = max(20, int(os.environ.get("REVSPH_KILLS", "24")))
        print(f"kill_test: seed {cls.seed} (set REVSPH_KILL_SEED to repeat the delays)", flush=True)

        # The reference run: how long it takes, where the first snapshot appears, every hash.
        out = os.path.join(WORK, "reference")
        start = time.monotonic()
        process = subprocess.Popen(run_command(out), stdout=subprocess.DEVNULL,
                                   stderr=subprocess.PIPE, text=True, env=environment())
        first_snapshot = None
        while process.poll() is None:
            if first_snapshot is None and glob.glob(os.path.join(out, "snapshots", "step_*.h5")):
                first_snapshot = time.monotonic() - start
            time.sleep(0.002)
        cls.duration = time.monotonic() - start
        stderr = process.stderr.read()
        process.stderr.close()
        if process.returncode != 0:
            raise AssertionError(f"reference run failed ({process.returncode}): {stderr}")
        cls.first_snapshot = first_snapshot if first_snapshot is not None else cls.duration
        cls.reference = {}
        cls.particle_counts = None
        for path in glob.glob(os.path.join(out, "snapshots", "step_*.h5")):
            with h5py.File(path, "r") as h5:
                cls.reference[int(h5.attrs["step"])] = text_attr(h5.attrs["state_hash"])
                if cls.particle_counts is None:
                    order = [text_attr(x) for x in h5.attrs["field_order"]]
                    cls.particle_counts = {
                        entry.split("/", 1)[0]: h5["/state/" + entry].shape[0] for entry in order}
        expected_steps = list(range(0, STEPS + 1, SNAPSHOT_EVERY))
        if sorted(cls.reference) != expected_steps:
            raise AssertionError(f"reference snapshots at {sorted(cls.reference)}")
        print(f"kill_test: reference run {cls.duration:.2f} s, first snapshot after "
              f"{cls.first_snapshot:.3f} s, {len(cls.reference)} snapshots", flush=True)

    def moments(self):
        """The kill moments: EARLY_KILLS delays in seconds before the reference run's first
        snapshot, then one random fraction of the run's duration in each of equal slices (in
        random order). A fraction becomes a delay with the current estimate of the duration."""
        rng = random.Random(self.seed)
        early = [("early", rng.uniform(0.0, self.first_snapshot)) for _ in range(EARLY_KILLS)]
        slices = self.kills - EARLY_KILLS
        spread = [("fraction", rng.uniform(k / slices, (k + 1) / slices)) for k in range(slices)]
        rng.shuffle(spread)
        return early + spread, rng

    def check_run_directory(self, out, pool):
        """Returns (snapshots checked, tmp leftovers, newest complete snapshot or None)."""
        snapshot_dir = os.path.join(out, "snapshots")
        names = sorted(os.listdir(snapshot_dir)) if os.path.isdir(snapshot_dir) else []
        finals = [os.path.join(snapshot_dir, n) for n in names if snapshot_step(n) is not None]
        tmp = [n for n in names if n.endswith(".tmp")]
        unexpected = [n for n in names if snapshot_step(n) is None and not n.endswith(".h5.tmp")]
        self.assertEqual(unexpected, [], "unexpected files in snapshots/")
        tmp += [n for n in os.listdir(out) if n.endswith(".tmp")] if os.path.isdir(out) else []

        complete = {}
        for path in finals:
            try:
                step, recorded = check_snapshot_file(path, self.particle_counts)
            except SnapshotProblem as problem:
                self.fail(f"{path}: incomplete or unreadable snapshot: {problem}")
            self.assertIn(step, self.reference, path)
            self.assertEqual(recorded, self.reference[step], f"{path}: state differs from the "
                                                             f"reference run at step {step}")
            complete[os.path.realpath(path)] = (step, recorded)
        for path, (status, printed, stderr) in zip(finals, pool.map(revsph_hash, finals)):
            self.assertEqual(status, 0, f"revsph hash {path}: {stderr}")
            self.assertEqual(printed, complete[os.path.realpath(path)][1], path)

        xdmf = os.path.join(out, "run.xdmf")
        if os.path.exists(xdmf):
            try:
                root = ET.parse(xdmf).getroot()
            except ET.ParseError as error:
                self.fail(f"{xdmf} is not well-formed XML: {error}")
            referenced = set()
            for item in root.iter("DataItem"):
                if item.get("Format") != "HDF":
                    continue  # a function of others (a 2D vector padded to 3 components)
                file_part = item.text.strip().rpartition(":")[0]
                referenced.add(os.path.realpath(os.path.join(out, file_part)))
            for path in referenced:
                self.assertIn(path, complete, f"run.xdmf references {path}, which is missing or "
                                              f"incomplete")
            times = [float(t.get("Value")) for t in root.iter("Time")]
            self.assertEqual(len(times), len(referenced))

        energy = os.path.join(out, "energy.csv")
        if os.path.exists(energy):
            with open(energy, newline="") as f:
                text = f.read()
            if text:
                self.assertTrue(text.endswith("\n"), f"{energy}: last line incomplete: "
                                                     f"{text.splitlines()[-1]!r}")
                rows = list(csv.reader(text.splitlines()))
                header = rows[0]
                self.assertEqual(header[:2], ["step", "time [s]"])
                self.assertEqual(header[-3:], ["total [J/m]", "relative_error [1]",
                                               "mechanical_relative_error [1]"])
                steps = []
                for row in rows[1:]:
                    self.assertEqual(len(row), len(header), f"{energy}: row {row}")
                    values = [float(v) for v in row]
                    self.assertTrue(all(np.isfinite(values)), row)
                    steps.append(int(row[0]))
                self.assertEqual(steps, sorted(set(steps)))

        newest = None
        if complete:
            newest = max(complete, key=lambda p: complete[p][0])
        return len(finals), len(tmp), newest

    def restart(self, snapshot, out):
        step = snapshot_step(snapshot)
        result = subprocess.run([REVSPH, "run", "--from", snapshot, "--out", out, "--steps",
                                 str(RESTART_STEPS)], capture_output=True, text=True, timeout=120,
                                env=environment())
        self.assertEqual(result.returncode, 0, f"restart from {snapshot}: {result.stderr}")
        final = os.path.join(out, "snapshots", f"step_{step + RESTART_STEPS:09d}.h5")
        self.assertTrue(os.path.isfile(final), final)
        if step + RESTART_STEPS in self.reference:
            with h5py.File(final, "r") as h5:
                self.assertEqual(text_attr(h5.attrs["state_hash"]),
                                 self.reference[step + RESTART_STEPS],
                                 f"restart from step {step} diverges from the reference run")
            return True
        return False

    def test_kill_at_random_moments(self):
        moments, rng = self.moments()
        # The pace of a run changes with the load of the machine: the duration used to place the
        # kills is the median of recent observations (the reference run, then each killed run's
        # progress in energy.csv, logged every 2 steps).
        durations = [self.duration]
        kills = snapshots = leftovers = restarts = compared = finished = empty = 0
        attempt = 0
        with concurrent.futures.ThreadPoolExecutor(max_workers=4) as pool:
            while kills < self.kills:
                if attempt < len(moments):
                    kind, value = moments[attempt]
                else:  # a run finished before its kill: another random moment of the run
                    kind, value = "fraction", rng.uniform(0.0, 0.9)
                duration = statistics.median(durations[-5:])
                delay = value if kind == "early" else value * duration
                attempt += 1
                out = os.path.join(WORK, f"kill_{attempt:03d}")
                process = subprocess.Popen(run_command(out), stdout=subprocess.DEVNULL,
                                           stderr=subprocess.DEVNULL, env=environment())
                time.sleep(delay)
                if process.poll() is None:
                    os.kill(process.pid, signal.SIGKILL)
                status = process.wait()
                # A run may end on its own between poll() and the signal: the status says which.
                alive = status == -signal.SIGKILL
                if alive:
                    kills += 1
                else:
                    finished += 1
                    self.assertEqual(status, 0, f"run {attempt} (not killed) failed")
                progress = last_logged_step(out)
                if not alive:
                    durations.append(delay)
                elif progress is not None and progress >= STEPS // 10:
                    durations.append(delay * STEPS / progress)
                checked, tmp, newest = self.check_run_directory(out, pool)
                snapshots += checked
                leftovers += tmp
                note = ""
                if newest is not None:
                    restarts += 1
                    compared += self.restart(newest, os.path.join(WORK, f"restart_{attempt:03d}"))
                    note = f", restarted from step {snapshot_step(newest)}"
                else:
                    empty += alive
                moment = (f"{value:.3f} s (early)" if kind == "early" else
                          f"{value:.3f} x {duration:.3f} s = {delay:.3f} s")
                print(f"kill_test: run {attempt}: {'SIGKILL' if alive else 'finished'} after "
                      f"{moment}, logged step {progress}: {checked} snapshots complete, "
                      f"{tmp} tmp leftovers{note}", flush=True)
                shutil.rmtree(out, ignore_errors=True)
                shutil.rmtree(os.path.join(WORK, f"restart_{attempt:03d}"), ignore_errors=True)
        print(f"kill_test summary: seed {self.seed}: kills tried {kills} "
              f"({empty} before the first snapshot, {finished} runs finished before their kill), "
              f"snapshots checked {snapshots}, tmp leftovers seen {leftovers}, "
              f"restarts {restarts} ({compared} compared with the reference run)", flush=True)
        self.assertGreaterEqual(kills, 20)
        self.assertGreater(snapshots, 0)


def main():
    run_unittests(globals(), "revsph_kill_")


if __name__ == "__main__":
    main()
