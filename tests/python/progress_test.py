#!/usr/bin/python3
"""Progress output (core/progress.hpp, docs/running.md "Progress"): on a terminal the live bar
(carriage returns and escape codes), on several processes plain lines although each process
writes to a terminal of its own (Open MPI forwards their output through a pseudo-terminal, also
into a redirected log), and REVSPH_PROGRESS=bar|lines|auto choosing; another value is bad input.

Each run writes to a pseudo-terminal, as a process under mpirun does; a launch on 2 processes is
simulated by the variable Open MPI sets in each (OMPI_COMM_WORLD_SIZE), which a build without MPI
reads (tests/mpi/log_and_memory_on_processes.cmake launches 2 processes of an MPI build).

Usage: progress_test.py REVSPH   (run by CTest as python.progress)
"""

import os
import pty
import subprocess
import sys
import tempfile
import unittest

REVSPH = os.path.abspath(sys.argv.pop(1))
LAUNCHER_VARIABLES = ("OMPI_COMM_WORLD_SIZE", "PMI_SIZE")
ESCAPES = ("\r", "\x1b")


def run_on_terminal(work, *arguments, **environment):
    """(exit status, what the run wrote to its terminal, stderr)."""
    env = {k: v for k, v in os.environ.items()
           if k not in LAUNCHER_VARIABLES and k != "REVSPH_PROGRESS"}
    env.update(environment)
    controller, terminal = pty.openpty()
    process = subprocess.Popen([REVSPH, *arguments], cwd=work, env=env, stdout=terminal,
                               stderr=subprocess.PIPE, stdin=subprocess.DEVNULL)
    os.close(terminal)
    output = b""
    while True:
        try:
            chunk = os.read(controller, 65536)
        except OSError:  # EIO: the terminal's other end is closed
            break
        if not chunk:
            break
        output += chunk
    os.close(controller)
    err = process.stderr.read().decode()
    process.stderr.close()
    return process.wait(), output.decode(), err


class Progress(unittest.TestCase):
    def setUp(self):
        self.work = tempfile.TemporaryDirectory()
        self.runs = 0

    def tearDown(self):
        self.work.cleanup()

    def run_case(self, **environment):
        self.runs += 1
        status, out, err = run_on_terminal(
            self.work.name, "run", "dambreak-small", "--steps", "5", "--threads", "1", "--out",
            f"run{self.runs}", **environment)
        self.assertEqual(status, 0, err)
        self.assertIn("run 5/5 steps", out)
        return out

    def assert_bar(self, out):
        self.assertIn("\r\x1b[K[", out)

    def assert_lines(self, out):
        for escape in ESCAPES:
            self.assertNotIn(escape, out.replace("\r\n", "\n"))

    def test_a_terminal_shows_the_bar(self):
        self.assert_bar(self.run_case())

    def test_on_several_processes_plain_lines(self):
        self.assert_lines(self.run_case(OMPI_COMM_WORLD_SIZE="2", OMPI_COMM_WORLD_RANK="0"))

    def test_the_setting_chooses(self):
        self.assert_bar(self.run_case(OMPI_COMM_WORLD_SIZE="2", REVSPH_PROGRESS="bar"))
        self.assert_lines(self.run_case(REVSPH_PROGRESS="lines"))
        self.assert_bar(self.run_case(REVSPH_PROGRESS="auto"))

    def test_another_setting_is_bad_input(self):
        status, out, err = run_on_terminal(self.work.name, "run", "dambreak-small", "--steps", "5",
                                           "--out", "bad", REVSPH_PROGRESS="sometimes")
        self.assertEqual(status, 2, err)
        self.assertEqual(err, 'revsph: error: REVSPH_PROGRESS: expected auto, bar or lines, got '
                              '"sometimes"\n')
        self.assertEqual(out, "")
        self.assertEqual(os.listdir(self.work.name), [])


if __name__ == "__main__":
    unittest.main()
