#!/usr/bin/python3
"""A run continued with `revsph run --from SNAPSHOT` is the run it continues (docs/restart.md):

  - it ends where the first run would have, whatever gave that run's length (--steps, --t-end,
    the case's [run]), kept in every snapshot and in summary.json's run_end; an explicit --steps
    on the continuing command still says how many more; a run already past its end is refused
    with one line naming that end;
  - a snapshot restarts from another working directory with its case file and input files
    (a points block's HDF5 file) deleted: it carries them, each with its SHA-256;
  - continuing in place from an earlier snapshot, which would remove the later ones, asks for
    --force.

Usage: continued_run_test.py REVSPH_BINARY [unittest options]
"""

import hashlib
import json
import os
import shutil
import subprocess
import unittest

import h5py

from revsph_testing import environment, run_unittests, text_attr

REVSPH = None
WORK = None
SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CONVERT = os.path.join(SOURCE, "tools", "points", "points_from_snapshot.py")
# The case's own end (run.t_end = 0.02 s, step 200 at dt = 1e-4 s) is short of the first runs'
# 300 steps: a continuation that forgot the first run's length stops at 200.
CASE = ["dambreak-small", "--threads", "1", "--set", "output.snapshot_every=100", "--set",
        "output.energy_every=50", "--set", "run.t_end=0.02"]


def revsph(*arguments, cwd=None):
    return subprocess.run([REVSPH, *map(str, arguments)], cwd=cwd or WORK, capture_output=True,
                          text=True, env=environment())


def summary(folder):
    with open(os.path.join(WORK, folder, "summary.json")) as f:
        return json.load(f)


def snapshot(folder, step):
    return os.path.join(folder, "snapshots", f"step_{step:09d}.h5")


class ContinuedRunTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        for arguments, folder in ((["--steps", 300], "steps"), (["--t-end", 0.03], "t_end")):
            made = revsph("run", *CASE, *arguments, "--out", folder)
            assert made.returncode == 0, made.stderr

    def continued(self, folder, *arguments):
        """`run --from FOLDER/snapshots/step_100.h5` into FOLDER-continued; its summary."""
        more = revsph("run", "--from", snapshot(folder, 100), "--threads", 1, *arguments,
                      "--out", folder + "-continued" + "".join(map(str, arguments)))
        self.assertEqual(more.returncode, 0, more.stderr)
        return summary(folder + "-continued" + "".join(map(str, arguments)))

    def test_the_end_of_steps_on_the_command_line_is_kept(self):
        whole = summary("steps")
        ours = self.continued("steps")
        self.assertTrue(ours["completed"])
        self.assertEqual(ours["final_step"], 300)
        self.assertEqual(ours["final_hash"], whole["final_hash"])
        self.assertEqual(whole["run_end"], {"step": 300, "from": "--steps 300 given at step 0"})
        self.assertEqual(ours["run_end"], whole["run_end"])
        with h5py.File(os.path.join(WORK, snapshot("steps", 100)), "r") as f:
            self.assertEqual(int(f.attrs["run_end_step"]), 300)
            self.assertEqual(text_attr(f.attrs["run_end_origin"]), "--steps 300 given at step 0")

    def test_the_end_of_t_end_on_the_command_line_is_kept(self):
        ours = self.continued("t_end")
        self.assertEqual(ours["final_step"], 300)
        self.assertEqual(ours["run_end"], {"t_end": 0.03, "from": "--t-end 0.03"})

    def test_the_end_of_the_case_is_kept(self):
        made = revsph("run", *CASE, "--set", "run.t_end=0.025", "--out", "case_end")
        self.assertEqual(made.returncode, 0, made.stderr)
        ours = self.continued("case_end")
        self.assertEqual(ours["final_step"], 250)
        self.assertEqual(ours["run_end"], {"t_end": 0.025, "from": "--set run.t_end=0.025"})

    def test_steps_on_the_continuing_command_say_how_many_more(self):
        ours = self.continued("steps", "--steps", 50)
        self.assertEqual(ours["final_step"], 150)
        self.assertEqual(ours["run_end"], {"step": 150, "from": "--steps 50 given at step 100"})

    def test_a_run_past_its_end_is_refused_naming_that_end(self):
        for arguments, end in ((["--t-end", 0.02], "t = 0.02 s from --t-end 0.02"),
                               (["--set", "run.t_end=0.01"],
                                "t = 0.01 s from --set run.t_end=0.01")):
            past = revsph("run", "--from", snapshot("steps", 300), *arguments, "--out", "past")
            self.assertEqual(past.returncode, 2, past.stderr)
            self.assertEqual(len(past.stderr.strip().splitlines()), 1, past.stderr)
            self.assertIn("already at step 300", past.stderr)
            self.assertIn("past the run's end, " + end, past.stderr)

    def test_continuing_in_place_from_an_earlier_snapshot_asks_for_force(self):
        made = revsph("run", *CASE, "--steps", 300, "--out", "in_place")
        self.assertEqual(made.returncode, 0, made.stderr)
        refused = revsph("run", "--from", snapshot("in_place", 100), "--threads", 1)
        self.assertEqual(refused.returncode, 2, refused.stderr)
        self.assertEqual(len(refused.stderr.strip().splitlines()), 1, refused.stderr)
        self.assertIn("2 later snapshots of in_place (after step 100) would be removed: --force "
                      "replaces them", refused.stderr.replace(WORK + "/", ""))
        for step in (200, 300):
            self.assertTrue(os.path.isfile(os.path.join(WORK, snapshot("in_place", step))))
        forced = revsph("run", "--from", snapshot("in_place", 100), "--threads", 1, "--force")
        self.assertEqual(forced.returncode, 0, forced.stderr)
        self.assertIn("its 2 later snapshots removed", forced.stdout)
        self.assertEqual(summary("in_place")["final_step"], 300)
        self.assertEqual(summary("in_place")["final_hash"], summary("steps")["final_hash"])

    def test_a_snapshot_restarts_without_its_case_and_input_files(self):
        first = os.path.join(WORK, "first")
        case = os.path.join(first, "case")
        os.makedirs(case)
        subprocess.run(["/usr/bin/python3", CONVERT, os.path.join(WORK, snapshot("steps", 0)),
                        "--set", "fluid", "--out", os.path.join(case, "fluid.h5")],
                       check=True, capture_output=True)
        with open(os.path.join(case, "fluid.h5"), "rb") as f:
            fluid = f.read()
        text = revsph("cases", "dambreak-small").stdout
        box = 'shape = "box"\nlattice = "square"\nmin = [0.0, 0.0]\nmax = [1.0, 2.0]'
        self.assertEqual(text.count(box), 1)
        with open(os.path.join(case, "dam.toml"), "w") as out:
            out.write(text.replace(box, 'shape = "points"\nfile = "fluid.h5"'))
        made = revsph("run", "case/dam.toml", "--steps", 200, "--threads", 1, "--set",
                      "output.snapshot_every=100", "--out", "run", cwd=first)
        self.assertEqual(made.returncode, 0, made.stderr)
        shutil.rmtree(case)
        elsewhere = os.path.join(WORK, "elsewhere")
        os.makedirs(elsewhere)
        more = revsph("run", "--from", os.path.join("..", "first", snapshot("run", 100)),
                      "--threads", 1, "--out", "continued", cwd=elsewhere)
        self.assertEqual(more.returncode, 0, more.stderr)
        ours = summary(os.path.join(elsewhere, "continued"))
        self.assertEqual(ours["final_step"], 200)
        self.assertEqual(ours["final_hash"], summary(os.path.join(first, "run"))["final_hash"])
        with h5py.File(os.path.join(first, snapshot("run", 100)), "r") as f:
            self.assertEqual(text_attr(f.attrs["case_source"]), os.path.join(case, "dam.toml"))
            carried = f["inputs/0"]
            self.assertEqual(text_attr(carried.attrs["name"]), "fluid.h5")
            self.assertEqual(text_attr(carried.attrs["path"]), os.path.join(case, "fluid.h5"))
            self.assertEqual(text_attr(carried.attrs["sha256"]), hashlib.sha256(fluid).hexdigest())
            self.assertEqual(carried[()].tobytes(), fluid)
        with h5py.File(os.path.join(elsewhere, snapshot("continued", 200)), "r") as f:
            self.assertEqual(f["inputs/0"][()].tobytes(), fluid, "carried on by the continuation")


if __name__ == "__main__":
    run_unittests(globals(), "revsph-continued-")
