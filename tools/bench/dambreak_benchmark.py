#!/usr/bin/python3
"""Benchmark the WCSPH dam break: particle-steps per second and peak memory.

For every spatial step dr (default 0.02, 0.01, 0.005 m) and every thread count
(default 1 and 2) this script runs

    revsph run dambreak --set discretisation.dr=DR --steps N --threads K --out DIR --force

as a separate process, R times (default 5), and reads DIR/summary.json.  Each
configuration is its own process, so "peak_memory_bytes" (getrusage maxrss of
that process) is the peak memory of that configuration alone.

Reported per (dr, threads):
  * the median particle-steps per second over the repeats, with min and max
    (particle-steps = fluid particles x steps, as computed by revsph itself);
  * the speed-up of the median against the smallest thread count;
  * the peak resident memory (largest over the repeats), and that divided by
    the total number of particles (fluid + wall);
and per dr whether the final state hash was identical in every run, across
thread counts and repeats (a free determinism check: it must be "yes").

With --output FILE a markdown record is written: command line, date, machine
(CPU, cores, memory, kernel), the build of revsph (compiler, flags, commit)
and the table.  Recorded runs live in tools/bench/results/.

Exit status: 0 on success; 1 if a run failed or the binary changed while the
benchmark ran (nothing is written then); 2 if the binary is missing; 3 if a
final state hash differed between runs of one resolution.

Standard library only; run with /usr/bin/python3 from any directory.
"""

from __future__ import annotations

import argparse
import datetime
import hashlib
import json
import os
import platform
import shlex
import statistics
import subprocess
import sys
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

REPO_ROOT = Path(__file__).resolve().parents[2]
DEFAULT_REVSPH = REPO_ROOT / "build" / "bin" / "revsph"
CASE = "dambreak"

DEFAULT_RESOLUTIONS = [0.02, 0.01, 0.005]
DEFAULT_THREADS = [1, 2]
DEFAULT_REPEATS = 5
# Steps per resolution, chosen so that one run takes a few seconds.
DEFAULT_STEPS = {0.02: 2000, 0.01: 1000, 0.005: 400}
# For a resolution not in DEFAULT_STEPS: aim at this many fluid particle-steps.
# The dam-break column is 1 m x 2 m, i.e. 2 / dr^2 fluid particles.
FALLBACK_PARTICLE_STEPS = 2.0e7
QUICK_STEP_FRACTION = 0.1


@dataclass
class RunResult:
    """What one revsph process reported in its summary.json."""

    dr: float
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
    """All repeats of one (dr, threads) configuration."""

    dr: float
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


# --------------------------------------------------------------------------
# Command line
# --------------------------------------------------------------------------


def parse_arguments(argv: list[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(
        description="Benchmark the WCSPH dam break (particle-steps/s and peak memory).")
    parser.add_argument("--revsph", type=Path, default=DEFAULT_REVSPH,
                        help="path of the revsph binary (default: %(default)s)")
    parser.add_argument("--repeats", type=positive_int, default=DEFAULT_REPEATS,
                        help="runs per configuration; the median is reported "
                             "(default: %(default)s)")
    parser.add_argument("--steps", type=positive_int, default=None,
                        help="time steps for every resolution (default: per resolution, "
                             + ", ".join(f"dr={dr}: {n}" for dr, n in DEFAULT_STEPS.items())
                             + ")")
    parser.add_argument("--resolutions", type=float, nargs="+", default=DEFAULT_RESOLUTIONS,
                        metavar="DR", help="spatial steps dr in m (default: %(default)s)")
    parser.add_argument("--threads", type=positive_int, nargs="+", default=DEFAULT_THREADS,
                        metavar="K", help="thread counts (default: %(default)s)")
    parser.add_argument("--output", type=Path, default=None,
                        help="write a markdown record of the run to this file "
                             "(default: print only)")
    parser.add_argument("--quick", action="store_true",
                        help="smoke test: 1 repeat and 10%% of the steps")
    arguments = parser.parse_args(argv)
    arguments.revsph = arguments.revsph.absolute()
    if arguments.quick:
        arguments.repeats = 1
    arguments.threads = sorted(set(arguments.threads))
    return arguments


def positive_int(text: str) -> int:
    value = int(text)
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be at least 1, got {text}")
    return value


def steps_for_resolution(dr: float, arguments: argparse.Namespace) -> int:
    """Time steps to run at spatial step dr (before the --quick reduction)."""
    if arguments.steps is not None:
        steps = arguments.steps
    elif dr in DEFAULT_STEPS:
        steps = DEFAULT_STEPS[dr]
    else:
        fluid_particles = 2.0 / (dr * dr)
        steps = max(10, round(FALLBACK_PARTICLE_STEPS / fluid_particles))
    if arguments.quick:
        steps = max(1, round(steps * QUICK_STEP_FRACTION))
    return steps


# --------------------------------------------------------------------------
# Running revsph
# --------------------------------------------------------------------------


def revsph_command(revsph: Path, dr: float, steps: int, threads: int, out_dir: str) -> list[str]:
    return [str(revsph), "run", CASE,
            "--set", f"discretisation.dr={dr}",
            "--steps", str(steps),
            "--threads", str(threads),
            "--out", out_dir, "--force"]


def run_revsph_once(revsph: Path, dr: float, steps: int, threads: int) -> RunResult:
    """Run one configuration in its own process and read its summary.json."""
    with tempfile.TemporaryDirectory(prefix="revsph-bench-") as out_dir:
        command = revsph_command(revsph, dr, steps, threads, out_dir)
        process = subprocess.run(command, capture_output=True, text=True)
        if process.returncode != 0:
            raise RuntimeError(f"{shlex.join(command)} exited with status "
                               f"{process.returncode}:\n{process.stdout}{process.stderr}")
        with open(os.path.join(out_dir, "summary.json"), encoding="utf-8") as file:
            summary = json.load(file)
    if not summary.get("completed", False) or summary["steps"] != steps:
        raise RuntimeError(f"{shlex.join(command)} did not complete {steps} steps: "
                           f"{summary.get('failure', 'steps = ' + str(summary['steps']))}")
    return RunResult(
        dr=dr,
        threads=summary["threads"],
        steps=summary["steps"],
        fluid_particles=summary["particles"].get("fluid", 0),
        wall_particles=summary["particles"].get("wall", 0),
        wall_seconds=summary["wall_seconds"],
        particle_steps_per_second=summary["particle_steps_per_second"],
        peak_memory_bytes=summary["peak_memory_bytes"],
        final_hash=summary["final_hash"],
        build=summary.get("build", {}),
    )


def run_benchmark(arguments: argparse.Namespace) -> dict[float, dict[int, ConfigurationSummary]]:
    """Run every configuration; returns results[dr][threads].

    Within a resolution the thread counts are interleaved repeat by repeat, so
    slow drifts of the machine (other load, clock changes) affect them alike.
    """
    results: dict[float, dict[int, ConfigurationSummary]] = {}
    total_runs = len(arguments.resolutions) * len(arguments.threads) * arguments.repeats
    run_number = 0
    for dr in arguments.resolutions:
        steps = steps_for_resolution(dr, arguments)
        results[dr] = {k: ConfigurationSummary(dr, k) for k in arguments.threads}
        for repeat in range(arguments.repeats):
            for threads in arguments.threads:
                run_number += 1
                result = run_revsph_once(arguments.revsph, dr, steps, threads)
                results[dr][threads].runs.append(result)
                log(f"[{run_number}/{total_runs}] dr={dr} threads={threads} "
                    f"repeat {repeat + 1}/{arguments.repeats}: {steps} steps in "
                    f"{result.wall_seconds:.2f} s, "
                    f"{result.particle_steps_per_second:.3e} particle-steps/s, "
                    f"peak {result.peak_memory_bytes / 1e6:.1f} MB")
    return results


def log(message: str) -> None:
    print(message, file=sys.stderr, flush=True)


# --------------------------------------------------------------------------
# Analysis and formatting
# --------------------------------------------------------------------------


def hash_is_invariant(configurations: dict[int, ConfigurationSummary]) -> bool:
    """True if every run at this resolution ended in the same state hash."""
    hashes = {run.final_hash for summary in configurations.values() for run in summary.runs}
    return len(hashes) == 1


def results_table(results: dict[float, dict[int, ConfigurationSummary]]) -> list[list[str]]:
    """Header row followed by one row per (dr, threads)."""
    baseline_threads = min(next(iter(results.values())))
    header = ["dr (m)", "fluid particles", "wall particles", "threads", "steps",
              "median particle-steps/s", "min", "max",
              f"speed-up vs {baseline_threads} thread{'s' if baseline_threads > 1 else ''}",
              "peak memory (MB)", "bytes/particle"]
    rows = [header]
    for dr, configurations in results.items():
        baseline_rate = configurations[baseline_threads].median_rate
        for threads, summary in configurations.items():
            first = summary.runs[0]
            rows.append([
                f"{dr:g}",
                str(first.fluid_particles),
                str(first.wall_particles),
                str(threads),
                str(first.steps),
                f"{summary.median_rate:.3e}",
                f"{min(summary.rates):.3e}",
                f"{max(summary.rates):.3e}",
                f"{summary.median_rate / baseline_rate:.2f}",
                f"{summary.peak_memory_bytes / 1e6:.1f}",
                f"{summary.peak_memory_bytes / summary.total_particles:.0f}",
            ])
    return rows


def format_markdown_table(rows: list[list[str]]) -> str:
    """A markdown table with padded columns, readable as plain text too."""
    widths = [max(len(row[i]) for row in rows) for i in range(len(rows[0]))]

    def format_row(row: list[str]) -> str:
        return "| " + " | ".join(cell.rjust(width) for cell, width in zip(row, widths)) + " |"

    separator = "|" + "|".join("-" * (width + 1) + ":" for width in widths) + "|"
    return "\n".join([format_row(rows[0]), separator] + [format_row(row) for row in rows[1:]])


def hash_invariance_lines(results: dict[float, dict[int, ConfigurationSummary]]) -> list[str]:
    lines = []
    for dr, configurations in results.items():
        verdict = "yes" if hash_is_invariant(configurations) else "no"
        runs = sum(len(summary.runs) for summary in configurations.values())
        threads = ", ".join(str(k) for k in configurations)
        lines.append(f"dr={dr:g}: hash invariant: {verdict} "
                     f"({runs} runs, threads {threads})")
    return lines


def first_summary(configurations: dict[int, ConfigurationSummary]) -> ConfigurationSummary:
    return next(iter(configurations.values()))


# --------------------------------------------------------------------------
# Machine and build description
# --------------------------------------------------------------------------


def cpu_model() -> str:
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as file:
            for line in file:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def total_memory() -> str:
    try:
        with open("/proc/meminfo", encoding="utf-8") as file:
            for line in file:
                if line.startswith("MemTotal:"):
                    kilobytes = int(line.split()[1])
                    return f"{kilobytes * 1024 / 2**30:.1f} GiB"
    except (OSError, ValueError, IndexError):
        pass
    return "unknown"


def usable_cpu_count() -> str:
    try:
        return str(len(os.sched_getaffinity(0)))
    except AttributeError:
        return "unknown"


def repository_head() -> str:
    """The repository's current commit, read without changing anything."""
    try:
        head = subprocess.run(["git", "-C", str(REPO_ROOT), "rev-parse", "HEAD"],
                              capture_output=True, text=True, check=True).stdout.strip()
        changes = subprocess.run(
            ["git", "--no-optional-locks", "-C", str(REPO_ROOT), "status", "--porcelain",
             "--untracked-files=no"],
            capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"
    return head + (" (with uncommitted changes)" if changes else "")


def file_sha256(path: Path) -> str:
    digest = hashlib.sha256()
    with open(path, "rb") as file:
        for block in iter(lambda: file.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def openmp_environment() -> str:
    """OpenMP settings inherited by revsph (they can change timings)."""
    settings = [f"{name}={value}" for name, value in sorted(os.environ.items())
                if name.startswith(("OMP_", "GOMP_"))]
    return ", ".join(settings) if settings else "none set"


def load_average() -> str:
    try:
        return " ".join(f"{load:.2f}" for load in os.getloadavg())
    except OSError:
        return "unknown"


def machine_description(load_before: str) -> list[tuple[str, str]]:
    return [
        ("CPU", cpu_model()),
        ("cores (os.cpu_count)", str(os.cpu_count())),
        ("cores usable by this process", usable_cpu_count()),
        ("memory", total_memory()),
        ("kernel", f"{platform.system()} {platform.release()} ({platform.machine()})"),
        ("OS", platform.platform()),
        ("load average before the benchmark (1, 5, 15 min)", load_before),
        ("OpenMP environment", openmp_environment()),
    ]


def build_description(results: dict[float, dict[int, ConfigurationSummary]],
                      revsph: Path, binary_sha256: str) -> list[tuple[str, str]]:
    build = first_summary(next(iter(results.values()))).runs[0].build
    return [
        ("binary", str(revsph.resolve())),
        ("binary SHA-256", binary_sha256),
        ("version", str(build.get("version", "unknown"))),
        ("compiler", str(build.get("compiler", "unknown"))),
        ("build type", str(build.get("build_type", "unknown"))),
        ("flags", str(build.get("flags", "unknown"))),
        ("git commit (from the binary)", str(build.get("git_commit", "unknown"))),
        ("repository HEAD when benchmarked", repository_head()),
    ]


# --------------------------------------------------------------------------
# Report
# --------------------------------------------------------------------------


def invoked_command_line() -> str:
    return shlex.join([sys.executable] + sys.argv)


def markdown_report(arguments: argparse.Namespace,
                    results: dict[float, dict[int, ConfigurationSummary]],
                    started: datetime.datetime, binary_sha256: str, load_before: str) -> str:
    example_steps = steps_for_resolution(arguments.resolutions[0], arguments)
    example = shlex.join(revsph_command(
        arguments.revsph, arguments.resolutions[0], example_steps, arguments.threads[0],
        "TMPDIR"))
    lines = [
        "# Dam-break benchmark",
        "",
        f"- date: {started.isoformat(timespec='seconds')}",
        f"- command (run in `{os.getcwd()}`):",
        "",
        "  ```sh",
        f"  {invoked_command_line()}",
        "  ```",
        "",
        f"- each configuration is a separate process, {arguments.repeats} repeat(s), e.g.",
        "",
        "  ```sh",
        f"  {example}",
        "  ```",
        "",
        "## Machine",
        "",
    ]
    lines += [f"- {name}: {value}" for name, value in machine_description(load_before)]
    lines += ["", "## Build", ""]
    lines += [f"- {name}: {value}" for name, value in build_description(results, arguments.revsph,
                                                                  binary_sha256)]
    lines += [
        "",
        "## Results",
        "",
        "Particle-steps/s counts fluid particles x steps over the stepping wall time; the "
        "median, min and max are over the repeats. Peak memory is the largest maxrss over the "
        "repeats (MB = 10^6 bytes); bytes/particle divides it by fluid + wall particles.",
        "",
        format_markdown_table(results_table(results)),
        "",
        "Determinism (final state hash identical across thread counts and repeats):",
        "",
    ]
    lines += [f"- {line}" for line in hash_invariance_lines(results)]
    return "\n".join(lines) + "\n"


def print_console_report(results: dict[float, dict[int, ConfigurationSummary]]) -> None:
    print(format_markdown_table(results_table(results)))
    print()
    for line in hash_invariance_lines(results):
        print(line)


def main(argv: list[str]) -> int:
    arguments = parse_arguments(argv)
    if not (arguments.revsph.is_file() and os.access(arguments.revsph, os.X_OK)):
        log(f"error: revsph binary not found at {arguments.revsph}; build it with\n"
            f"  cmake -S {REPO_ROOT} -B {REPO_ROOT / 'build'} -DCMAKE_BUILD_TYPE=Release "
            f"&& cmake --build {REPO_ROOT / 'build'} -j2\nor pass --revsph PATH")
        return 2
    cpus = os.cpu_count() or 1
    if max(arguments.threads) > cpus:
        log(f"warning: {max(arguments.threads)} threads requested but only {cpus} CPUs")

    started = datetime.datetime.now().astimezone()
    binary_sha256 = file_sha256(arguments.revsph)
    load_before = load_average()
    try:
        results = run_benchmark(arguments)
    except RuntimeError as error:
        log(f"error: {error}")
        return 1

    print_console_report(results)
    if file_sha256(arguments.revsph) != binary_sha256:
        log(f"error: {arguments.revsph} changed while the benchmark ran (rebuilt?); "
            "the results mix two binaries and are not recorded")
        return 1
    if arguments.output is not None:
        arguments.output.parent.mkdir(parents=True, exist_ok=True)
        arguments.output.write_text(markdown_report(arguments, results, started, binary_sha256,
                                                    load_before), encoding="utf-8")
        print(f"\nwrote {arguments.output}")
    all_invariant = all(hash_is_invariant(configs) for configs in results.values())
    return 0 if all_invariant else 3


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
