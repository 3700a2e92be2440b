#!/usr/bin/python3
"""Restarts that continue a run (docs/restart.md), against the run that never stopped:

  - a chain of three segments in one folder (`revsph run --from` its last snapshot, no --out)
    ends with the same state hash, an energy.csv identical byte for byte (every running scale
    carried: the relative errors are the same digits), the same run.xdmf series and the same
    diagnostics extremes in summary.json;
  - SIGTERM in the middle of a run ends it with status 143, a last snapshot of a whole step and
    summary.json marked incomplete; continuing from that snapshot gives the same files again;
  - --from with --out elsewhere starts a branch holding the rows before the snapshot;
  - output.snapshot_interval writes a snapshot after each step passing a multiple of it.

Usage: continue_test.py REVSPH_BINARY [unittest options]
"""

import json
import os
import signal
import subprocess
import sys
import tempfile
import time
import unittest

REVSPH = os.environ.get("REVSPH") or (sys.argv.pop(1) if len(sys.argv) > 1 else "revsph")
CASE = ["dambreak-small", "--set", "output.snapshot_every=250", "--set", "output.energy_every=50",
        "--threads", "1"]


def revsph(*arguments, cwd):
    return subprocess.run([REVSPH, *arguments], cwd=cwd, capture_output=True, text=True)


def read(path):
    with open(path, "rb") as f:
        return f.read()


def summary(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)


class ContinueTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.TemporaryDirectory()
        made = revsph("run", *CASE, "--steps", "1200", "--out", "whole", cwd=cls.work.name)
        assert made.returncode == 0, made.stderr
        cls.whole = os.path.join(cls.work.name, "whole")

    @classmethod
    def tearDownClass(cls):
        cls.work.cleanup()

    def assertSameRun(self, folder):
        for name in ("energy.csv", "run.xdmf"):
            self.assertEqual(read(os.path.join(folder, name)), read(os.path.join(self.whole, name)),
                             f"{folder}/{name} differs from the run that never stopped")
        ours, theirs = summary(folder), summary(self.whole)
        self.assertTrue(ours["completed"])
        self.assertEqual(ours["final_hash"], theirs["final_hash"])
        self.assertEqual(ours["energy"], theirs["energy"])

    def test_three_segments_in_one_folder(self):
        work = self.work.name
        first = revsph("run", *CASE, "--steps", "333", "--out", "chain", cwd=work)
        self.assertEqual(first.returncode, 0, first.stderr)
        for start, steps in ((333, "400"), (733, "467")):
            snapshot = f"chain/snapshots/step_{start:09d}.h5"
            more = revsph("run", "--from", snapshot, "--steps", steps, "--threads", "1", cwd=work)
            self.assertEqual(more.returncode, 0, more.stderr)
            self.assertIn(f"continuing chain from step {start}", more.stdout.replace(work + "/", ""))
        self.assertSameRun(os.path.join(work, "chain"))
        # Every earlier snapshot file is still there, the segments' ends included.
        names = os.listdir(os.path.join(work, "chain", "snapshots"))
        self.assertIn("step_000000333.h5", names)
        self.assertIn("step_000000733.h5", names)

    def test_sigterm_leaves_a_snapshot_to_continue_from(self):
        work = self.work.name
        run = subprocess.Popen([REVSPH, "run", *CASE, "--steps", "1200", "--out", "stopped",
                                "--set", "output.progress_interval=0.05"],
                               cwd=work, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        # Wait for the first progress line past step 0: the run is stepping.
        deadline = time.time() + 60
        for line in run.stdout:
            if line.startswith("run ") and not line.startswith("run 0/") or time.time() > deadline:
                break
        run.send_signal(signal.SIGTERM)
        out, err = run.communicate(timeout=60)
        if run.returncode == 0:
            self.skipTest("the run ended before the signal came")
        self.assertEqual(run.returncode, 143, err)
        self.assertEqual(len(err.strip().splitlines()), 1, err)
        self.assertIn("interrupted by SIGTERM after step", err)
        stopped = summary(os.path.join(work, "stopped"))
        self.assertFalse(stopped["completed"])
        last = stopped["last_snapshot"]
        self.assertTrue(os.path.isfile(os.path.join(work, last)), last)
        more = revsph("run", "--from", last, "--t-end", "0.12", "--threads", "1", cwd=work)
        self.assertEqual(more.returncode, 0, more.stderr)
        self.assertSameRun(os.path.join(work, "stopped"))

    def test_a_branch_in_another_folder_keeps_the_rows_before_it(self):
        work = self.work.name
        branch = revsph("run", "--from", "whole/snapshots/step_000000500.h5", "--steps", "700",
                        "--threads", "1", "--out", "branch", cwd=work)
        self.assertEqual(branch.returncode, 0, branch.stderr)
        self.assertEqual(read(os.path.join(work, "branch", "energy.csv")),
                         read(os.path.join(self.whole, "energy.csv")))
        self.assertEqual(summary(os.path.join(work, "branch"))["final_hash"],
                         summary(self.whole)["final_hash"])

    def test_snapshot_interval_in_simulated_seconds(self):
        work = self.work.name
        made = revsph("run", "dambreak-small", "--steps", "1000", "--threads", "1", "--set",
                      "output.snapshot_interval=0.025", "--out", "interval", cwd=work)
        self.assertEqual(made.returncode, 0, made.stderr)
        # dt = 1e-4 s: 0.025 s is 250 steps (step 750's 0.07499999999999999 s counts as 0.075).
        self.assertEqual(sorted(os.listdir(os.path.join(work, "interval", "snapshots"))),
                         [f"step_{n:09d}.h5" for n in (0, 250, 500, 750, 1000)])


if __name__ == "__main__":
    unittest.main()
