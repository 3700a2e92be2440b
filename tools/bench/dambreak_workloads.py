#!/usr/bin/python3
"""The dam-break benchmark's workloads and results (tools/bench/dambreak_benchmark.py): what is
measured, at which sizes and thread counts, and the records each run leaves."""

from __future__ import annotations

import argparse
import json
import statistics
from dataclasses import dataclass, field
from pathlib import Path


REPO_ROOT = Path(__file__).resolve().parents[2]
DEFAULT_REVSPH = REPO_ROOT / "build" / "bin" / "revsph"
DEFAULT_CACHE_DIR = Path("/tmp/revsph-bench-cache")
DEFAULT_REPEATS = 5

SUITES = ["table1", "scaling", "3d"]
# Thread counts per suite unless --threads is given.  Scaling only needs the
# production setting (2 threads on the reference machine); the thread speed-up
# is measured by table1 and 3d.
DEFAULT_SUITE_THREADS = {"table1": [1, 2], "scaling": [2], "3d": [1, 2]}

CASE_2D = "dambreak"
CASE_3D = "dambreak-3d-small"

TABLE1_DR = 0.005
TABLE1_STEPS = 400
# The disordered state: simulated time, and the dr it is made at.
SPLASH_TIME = 0.5

DEFAULT_SCALING_RESOLUTIONS = [0.01, 0.005, 0.0025, 0.00125]
SCALING_PARTICLE_STEPS = 3.2e7
DEFAULT_3D_RESOLUTIONS = [0.0125, 0.00625]
# 3D steps cost about 8x more per particle than 2D ones; this keeps a 1-thread
# run near 10 s.
THREE_D_PARTICLE_STEPS = 3.2e6
MIN_STEPS = 20
# "Linear in N": the largest rate over the smallest rate, across sizes.
LINEARITY_TOLERANCE = 1.2

PROFILE_STEPS = 100
PROFILE_SYMBOLS = 12
PROFILE_SYMBOL_WIDTH = 140

QUICK_STEP_FRACTION = 0.1
# A snapshot interval larger than any run: only the first and last states are
# written, so output costs (almost) nothing.
NO_SNAPSHOTS = "output.snapshot_every=100000000"


def fluid_particles_2d(dr: float) -> float:
    """The 2D dam-break column is 1 m x 2 m, filled on a lattice of spacing dr."""
    return 2.0 / (dr * dr)


def fluid_particles_3d(dr: float) -> float:
    """The small 3D column is 0.25 m x 0.25 m x 0.5 m."""
    return 0.25 * 0.25 * 0.5 / dr ** 3


# --------------------------------------------------------------------------
# What is measured
# --------------------------------------------------------------------------


@dataclass(frozen=True)
class Workload:
    """One thing to time: a built-in case at a resolution, or a continuation of a snapshot."""

    suite: str
    label: str
    steps: int
    case: str
    dr: float
    snapshot: Path | None = None

    def command(self, revsph: Path, threads: int, out_dir: str) -> list[str]:
        if self.snapshot is not None:
            start = ["--from", str(self.snapshot)]
        else:
            start = [self.case, "--set", f"discretisation.dr={self.dr:g}"]
        return ([str(revsph), "run"] + start
                + ["--steps", str(self.steps), "--threads", str(threads),
                   "--out", out_dir, "--force", "--set", NO_SNAPSHOTS])

    @property
    def title(self) -> str:
        """How the workload is named in the determinism list and the progress log."""
        return f"{self.suite} {self.label}"


@dataclass
class RunResult:
    """What one revsph process reported in its summary.json."""

    threads: int
    steps: int
    fluid_particles: int
    wall_particles: int
    wall_seconds: float
    particle_steps_per_second: float
    peak_memory_bytes: int
    final_hash: str
    build: dict


@dataclass
class ConfigurationSummary:
    """All repeats of one (workload, threads) configuration."""

    threads: int
    runs: list[RunResult] = field(default_factory=list)

    @property
    def rates(self) -> list[float]:
        return [run.particle_steps_per_second for run in self.runs]

    @property
    def median_rate(self) -> float:
        return statistics.median(self.rates)

    @property
    def peak_memory_bytes(self) -> int:
        return max(run.peak_memory_bytes for run in self.runs)

    @property
    def total_particles(self) -> int:
        first = self.runs[0]
        return first.fluid_particles + first.wall_particles


@dataclass
class WorkloadResults:
    """Every thread count of one workload, keyed by thread count (ascending)."""

    workload: Workload
    by_threads: dict[int, ConfigurationSummary]

    @property
    def hash_is_invariant(self) -> bool:
        """True if every run of this workload ended in the same state hash."""
        hashes = {run.final_hash for summary in self.by_threads.values()
                  for run in summary.runs}
        return len(hashes) == 1

    @property
    def first_run(self) -> RunResult:
        return next(iter(self.by_threads.values())).runs[0]


@dataclass
class SplashState:
    """Where the t = 0.5 s snapshot came from, for the record."""

    path: Path
    origin: str
    sha256: str


@dataclass
class ProfileResult:
    """The perf summary of one run, or why there is none."""

    note: str
    command: str = ""
    particle_steps_per_second: float | None = None
    # (share in percent, shared object, symbol), largest first
    symbols: list[tuple[float, str, str]] = field(default_factory=list)


class BenchmarkError(RuntimeError):
    """A run failed; the benchmark stops with exit status 1."""



def threads_for_suite(suite: str, arguments: argparse.Namespace) -> list[int]:
    return arguments.threads if arguments.threads is not None else DEFAULT_SUITE_THREADS[suite]
