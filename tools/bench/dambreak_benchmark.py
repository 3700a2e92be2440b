#!/usr/bin/python3
"""Benchmark revsph on the dam break: particle-steps per second, threads, memory.

One command measures several suites (select with --suite; default: all):

  table1   the Table-1 dam break (2D, dr = 0.005 m, 80 000 fluid particles),
           1 and 2 threads, in two states, 400 steps each:
             "t=0"    the fresh lattice (the column starts to fall), and
             "t=0.5s" continued from the t = 0.5 s state, where the fluid is
                      splashing and disordered (the expensive phase).
           Their mean is reported as the representative figure of a full run;
           it is the harmonic mean of the two rates, i.e. the rate of a run
           that spends equally many steps in both states.
  scaling  the 2D dam break at dr = 0.01, 0.005, 0.0025, 0.00125 m (2e4 to
           1.28e6 fluid particles) with 2 threads, 3.2e7 particle-steps per run
           (at least 20 steps); reports each size's rate relative to the mean
           rate of all sizes and whether max/min of the rates is within 1.2
           ("linear in N within 20 %").
  3d       dambreak-3d-small at dr = 0.0125 and 0.00625 m (16 000 and 128 000
           fluid particles), 1 and 2 threads, 3.2e6 particle-steps per run.

Every configuration is a separate process, run R times (default 5):

    revsph run CASE --set discretisation.dr=DR --steps N --threads K --out DIR --force \
        --set output.snapshot_every=100000000
    revsph run --from SNAPSHOT.h5 --steps N --threads K --out DIR --force \
        --set output.snapshot_every=100000000                  (the t=0.5s state)

and the figures are read from DIR/summary.json.  Because each configuration
has its own process, "peak_memory_bytes" (getrusage maxrss) is its own peak.

The t = 0.5 s state is made once per binary with

    revsph run dambreak --set discretisation.dr=0.005 --t-end 0.5 --out DIR \
        --set output.snapshot_every=100000000

(20 000 steps: several minutes) and kept in --cache-dir under a name holding
the binary's SHA-256, so a rebuilt engine never continues from a state that
another build produced.  --snapshot PATH uses an existing snapshot instead.

Reported per configuration (workload x threads):
  * the median particle-steps per second over the repeats, with min and max
    (particle-steps = fluid particles x steps, as computed by revsph itself);
  * the speed-up of the median against the smallest thread count;
  * the peak resident memory (largest over the repeats), and that divided by
    the total number of particles (fluid + wall);
and per workload whether the final state hash was identical in every run,
across thread counts and repeats (the engine is bitwise deterministic, so a
difference is a bug).

With --profile, one 1-thread run of the t=0.5s state (100 steps) is recorded
with `perf record -F 999 -g` and the top symbols of
`perf report --stdio --no-children` are reported (or "perf not available").

With --output FILE a markdown record is written: command line, date, machine
(CPU, cores, memory, kernel), the build of revsph (compiler, flags, commit),
the inputs, one table per suite, the determinism check and the profile.
Recorded runs live in tools/bench/results/.

Exit status: 0 on success; 1 if a run failed or the binary changed while the
benchmark ran (nothing is written then); 2 if the binary (or the snapshot
given with --snapshot) is missing; 3 if a final state hash differed between
runs of one workload.  A failed profile is reported, not an error.

Standard library only; run with /usr/bin/python3 from any directory.
"""

from __future__ import annotations

import argparse
import datetime
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
from dataclasses import field
from pathlib import Path


from dambreak_workloads import (BenchmarkError, CASE_2D, CASE_3D, ConfigurationSummary,
    DEFAULT_3D_RESOLUTIONS, DEFAULT_CACHE_DIR, DEFAULT_REPEATS, DEFAULT_REVSPH,
    DEFAULT_SCALING_RESOLUTIONS, MIN_STEPS, NO_SNAPSHOTS, PROFILE_STEPS, PROFILE_SYMBOLS,
    ProfileResult, QUICK_STEP_FRACTION, REPO_ROOT, RunResult, SCALING_PARTICLE_STEPS, SPLASH_TIME,
    SUITES, SplashState, TABLE1_DR, TABLE1_STEPS, THREE_D_PARTICLE_STEPS, Workload,
    WorkloadResults, fluid_particles_2d, fluid_particles_3d, threads_for_suite)
from dambreak_report import (file_sha256, load_average, markdown_report, print_console_report)

# --------------------------------------------------------------------------
# Command line
# --------------------------------------------------------------------------


def parse_arguments(argv: list[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(
        description="Benchmark revsph on the dam break: particle-steps/s, thread "
                    "speed-up, peak memory, determinism and a profile.")
    parser.add_argument("--suite", nargs="+", choices=SUITES, default=SUITES,
                        help="suites to run (default: all: %(default)s)")
    parser.add_argument("--revsph", type=Path, default=DEFAULT_REVSPH,
                        help="path of the revsph binary (default: %(default)s)")
    parser.add_argument("--repeats", type=positive_int, default=DEFAULT_REPEATS,
                        help="runs per configuration; the median is reported "
                             "(default: %(default)s)")
    parser.add_argument("--threads", type=positive_int, nargs="+", default=None,
                        metavar="K",
                        help="thread counts for every suite (default: table1 1 2, "
                             "scaling 2, 3d 1 2)")
    parser.add_argument("--steps", type=positive_int, default=None,
                        help="the same number of time steps for every run (default: "
                             f"table1 {TABLE1_STEPS}; scaling "
                             f"{SCALING_PARTICLE_STEPS:.1e} and 3d "
                             f"{THREE_D_PARTICLE_STEPS:.1e} particle-steps, "
                             f"at least {MIN_STEPS} steps)")
    parser.add_argument("--resolutions", type=positive_float, nargs="+",
                        default=DEFAULT_SCALING_RESOLUTIONS, metavar="DR",
                        help="dr in m of the scaling suite (default: %(default)s)")
    parser.add_argument("--resolutions-3d", type=positive_float, nargs="+",
                        default=DEFAULT_3D_RESOLUTIONS, metavar="DR",
                        help="dr in m of the 3d suite (default: %(default)s)")
    parser.add_argument("--snapshot", type=Path, default=None,
                        help="use this t = 0.5 s dam-break snapshot (dr = 0.005) instead "
                             "of making one in --cache-dir")
    parser.add_argument("--cache-dir", type=Path, default=DEFAULT_CACHE_DIR,
                        help="where the t = 0.5 s snapshot is made and kept, per binary "
                             "(default: %(default)s)")
    parser.add_argument("--profile", action="store_true",
                        help=f"profile one 1-thread run of the t=0.5s state "
                             f"({PROFILE_STEPS} steps) with perf")
    parser.add_argument("--output", type=Path, default=None,
                        help="write a markdown record of the run to this file "
                             "(default: print only)")
    parser.add_argument("--quick", action="store_true",
                        help="smoke test of this script: 1 repeat and 10%% of the steps; "
                             "its figures are too short to quote")
    arguments = parser.parse_args(argv)
    arguments.revsph = arguments.revsph.absolute()
    if arguments.snapshot is not None:
        arguments.snapshot = arguments.snapshot.absolute()
    arguments.cache_dir = arguments.cache_dir.absolute()
    if arguments.quick:
        arguments.repeats = 1
    # Run the suites in their canonical order, each once, however they were given.
    arguments.suite = [suite for suite in SUITES if suite in arguments.suite]
    if arguments.threads is not None:
        arguments.threads = sorted(set(arguments.threads))
    return arguments


def positive_int(text: str) -> int:
    value = int(text)
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be at least 1, got {text}")
    return value


def positive_float(text: str) -> float:
    """A spatial step: particle counts and step counts divide by it."""
    value = float(text)
    if not value > 0.0:
        raise argparse.ArgumentTypeError(f"must be positive, got {text}")
    return value



def scaled_steps(default_steps: int, arguments: argparse.Namespace) -> int:
    """Apply --steps and --quick to a suite's default step count."""
    steps = arguments.steps if arguments.steps is not None else default_steps
    return shortened_for_quick(steps, arguments.quick)


def shortened_for_quick(steps: int, quick: bool) -> int:
    """--quick tests the script, not the engine: a tenth of the steps is enough."""
    return max(1, round(steps * QUICK_STEP_FRACTION)) if quick else steps


def steps_for_particle_steps(target: float, fluid_particles: float) -> int:
    """Steps that make about `target` particle-steps, so every size runs equally long."""
    return max(MIN_STEPS, round(target / fluid_particles))


def needs_splash_state(arguments: argparse.Namespace) -> bool:
    return "table1" in arguments.suite or arguments.profile


def build_workloads(arguments: argparse.Namespace, splash: SplashState | None) -> list[Workload]:
    """Every workload of the selected suites, in the order they are run."""
    workloads = []
    if "table1" in arguments.suite:
        steps = scaled_steps(TABLE1_STEPS, arguments)
        workloads.append(Workload("table1", "t=0", steps, CASE_2D, TABLE1_DR))
        workloads.append(Workload("table1", f"t={SPLASH_TIME:g}s", steps, CASE_2D, TABLE1_DR,
                                  snapshot=splash.path))
    def sized(suite, resolutions, particle_steps, fluid_particles, case):
        """One workload per resolution, each with about `particle_steps` particle-steps."""
        return [Workload(suite, f"dr={dr:g}",
                         scaled_steps(steps_for_particle_steps(particle_steps,
                                                               fluid_particles(dr)), arguments),
                         case, dr)
                for dr in resolutions]

    if "scaling" in arguments.suite:
        workloads += sized("scaling", arguments.resolutions, SCALING_PARTICLE_STEPS,
                           fluid_particles_2d, CASE_2D)
    if "3d" in arguments.suite:
        workloads += sized("3d", arguments.resolutions_3d, THREE_D_PARTICLE_STEPS,
                           fluid_particles_3d, CASE_3D)
    return workloads


# --------------------------------------------------------------------------
# Running revsph
# --------------------------------------------------------------------------


def read_summary(command: list[str], out_dir: Path, steps: int | None) -> dict:
    """summary.json of a finished run, checked to have completed (all `steps`, if given)."""
    with open(out_dir / "summary.json", encoding="utf-8") as file:
        summary = json.load(file)
    if not summary.get("completed", False) or (steps is not None and summary["steps"] != steps):
        raise BenchmarkError(f"{shlex.join(command)} did not complete {steps} steps: "
                             f"{summary.get('failure', 'steps = ' + str(summary.get('steps')))}")
    return summary


def run_checked(command: list[str], **kwargs) -> subprocess.CompletedProcess:
    process = subprocess.run(command, text=True, **kwargs)
    if process.returncode != 0:
        output = (process.stdout or "") + (process.stderr or "")
        raise BenchmarkError(f"{shlex.join(command)} exited with status "
                             f"{process.returncode}:\n{output}")
    return process


def stepping_rate(summary: dict) -> float:
    """Particle-steps per second of the time steps alone.

    revsph reports it as stepping_particle_steps_per_second (no initial and final snapshot
    writes, which dominate short runs of large problems); older builds only had the rate over
    the whole run."""
    return summary.get("stepping_particle_steps_per_second",
                       summary["particle_steps_per_second"])


def run_revsph_once(revsph: Path, workload: Workload, threads: int) -> RunResult:
    """Run one configuration in its own process and read its summary.json."""
    with tempfile.TemporaryDirectory(prefix="revsph-bench-") as out_dir:
        command = workload.command(revsph, threads, out_dir)
        run_checked(command, capture_output=True)
        summary = read_summary(command, Path(out_dir), workload.steps)
    return RunResult(
        threads=summary["threads"],
        steps=summary["steps"],
        fluid_particles=summary["particles"].get("fluid", 0),
        wall_particles=summary["particles"].get("wall", 0),
        wall_seconds=summary.get("stepping_seconds", summary["wall_seconds"]),
        particle_steps_per_second=stepping_rate(summary),
        peak_memory_bytes=summary["peak_memory_bytes"],
        final_hash=summary["final_hash"],
        build=summary.get("build", {}),
    )


def run_benchmark(arguments: argparse.Namespace,
                  workloads: list[Workload]) -> list[WorkloadResults]:
    """Run every configuration of every workload.

    Within a workload the thread counts are interleaved repeat by repeat, so
    slow drifts of the machine (other load, clock changes) affect them alike.
    """
    results = []
    total_runs = sum(len(threads_for_suite(w.suite, arguments)) for w in workloads) \
        * arguments.repeats
    run_number = 0
    for workload in workloads:
        thread_counts = threads_for_suite(workload.suite, arguments)
        by_threads = {k: ConfigurationSummary(k) for k in thread_counts}
        for repeat in range(arguments.repeats):
            for threads in thread_counts:
                run_number += 1
                result = run_revsph_once(arguments.revsph, workload, threads)
                by_threads[threads].runs.append(result)
                log(f"[{run_number}/{total_runs}] {workload.title} threads={threads} "
                    f"repeat {repeat + 1}/{arguments.repeats}: {workload.steps} steps in "
                    f"{result.wall_seconds:.2f} s, "
                    f"{result.particle_steps_per_second:.3e} particle-steps/s, "
                    f"peak {result.peak_memory_bytes / 1e6:.1f} MB")
        results.append(WorkloadResults(workload, by_threads))
    return results


def log(message: str) -> None:
    print(message, file=sys.stderr, flush=True)


# --------------------------------------------------------------------------
# The t = 0.5 s state
# --------------------------------------------------------------------------


def splash_generation_command(revsph: Path, out_dir: Path) -> list[str]:
    return [str(revsph), "run", CASE_2D, "--set", f"discretisation.dr={TABLE1_DR:g}",
            "--t-end", f"{SPLASH_TIME:g}", "--out", str(out_dir), "--force",
            "--set", NO_SNAPSHOTS]


def final_snapshot_of(run_dir: Path, summary: dict) -> Path:
    """The snapshot of a run's last state (revsph always writes it)."""
    return run_dir / "snapshots" / f"step_{summary['final_step']:09d}.h5"


def cached_splash_snapshot(run_dir: Path) -> Path | None:
    """The cached state if run_dir holds a completed run that reached t = 0.5 s, else None."""
    try:
        with open(run_dir / "summary.json", encoding="utf-8") as file:
            summary = json.load(file)
        reached = abs(summary["time"] - SPLASH_TIME) <= summary["dt"]
        snapshot = final_snapshot_of(run_dir, summary)
    except (OSError, ValueError, KeyError, TypeError):
        return None
    if summary.get("completed") and reached and snapshot.is_file():
        return snapshot
    return None


def obtain_splash_state(arguments: argparse.Namespace, binary_sha256: str) -> SplashState:
    """The t = 0.5 s snapshot: given, cached for this binary, or made now.

    The cache entry is named after the binary's SHA-256: a state made by
    another build may differ bit for bit (the engine is being changed), and
    the benchmark must continue exactly what this binary computes.  A new
    entry is made in a scratch directory and renamed into place only when
    complete, so an interrupted run never leaves a half-written cache.
    """
    if arguments.snapshot is not None:
        return SplashState(arguments.snapshot, "given with --snapshot",
                           file_sha256(arguments.snapshot))
    run_dir = arguments.cache_dir / f"dambreak-t{SPLASH_TIME:g}s-{binary_sha256[:16]}"
    snapshot = cached_splash_snapshot(run_dir)
    if snapshot is not None:
        log(f"using the cached t = {SPLASH_TIME:g} s state {snapshot}")
        return SplashState(snapshot, f"cached in {arguments.cache_dir} for this binary",
                           file_sha256(snapshot))

    arguments.cache_dir.mkdir(parents=True, exist_ok=True)
    scratch = Path(tempfile.mkdtemp(prefix="making-", dir=arguments.cache_dir))
    command = splash_generation_command(arguments.revsph, scratch)
    log(f"making the t = {SPLASH_TIME:g} s dam-break state (dr = {TABLE1_DR:g}, all threads); "
        f"this takes several minutes (about 10 on 2 cores) and is done once per binary "
        f"(--snapshot PATH uses an existing state instead):\n"
        f"  {shlex.join(command)}")
    try:
        # revsph's progress goes to stderr with ours; our stdout stays the report.
        sys.stderr.flush()
        run_checked(command, stdout=sys.stderr)
        read_summary(command, scratch, None)
        if cached_splash_snapshot(scratch) is None:
            raise BenchmarkError(f"{shlex.join(command)} did not reach t = {SPLASH_TIME:g} s")
        if file_sha256(arguments.revsph) != binary_sha256:
            raise BenchmarkError(f"{arguments.revsph} changed while the t = {SPLASH_TIME:g} s "
                                 "state was made (rebuilt?)")
        shutil.rmtree(run_dir, ignore_errors=True)  # an incomplete entry, if any
        scratch.rename(run_dir)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    snapshot = cached_splash_snapshot(run_dir)
    if snapshot is None:
        raise BenchmarkError(f"the state made in {run_dir} cannot be read back")
    return SplashState(snapshot, f"made by this benchmark ({shlex.join(command)}), "
                                 f"kept in {arguments.cache_dir}", file_sha256(snapshot))


# --------------------------------------------------------------------------
# Profile
# --------------------------------------------------------------------------

# perf report's column separator: a tab never occurs in a symbol, so the
# columns split exactly however long the symbols are.
PERF_SEPARATOR = "\t"
PERF_REPORT_OPTIONS = ["--stdio", "--no-children", "-g", "none", "--sort", "dso,symbol",
                       "--fields", "overhead,dso,sym"]


def parse_perf_report(text: str, limit: int) -> list[tuple[float, str, str]]:
    """(share, shared object, symbol) of the `limit` largest entries of a flat perf report.

    Symbols are shortened (see shortened_symbol) and entries that then read
    the same are added up: template instances that differ only in their
    arguments, like the fluid-fluid and fluid-wall neighbour searches, are one
    cost in a summary.
    """
    shares: dict[tuple[str, str], float] = {}
    for line in text.splitlines():
        if line.startswith("#"):
            continue
        # Overhead, object and symbol come first; perf may append columns of
        # its own (IPC) that a summary does not need.
        fields = [part.strip() for part in line.split(PERF_SEPARATOR)]
        if len(fields) < 3 or not fields[0].endswith("%"):
            continue
        try:
            share = float(fields[0][:-1])
        except ValueError:
            continue
        symbol = re.sub(r"^\[.\]\s*", "", fields[2])  # drop perf's [.] / [k] marker
        key = (fields[1], shortened_symbol(symbol))
        shares[key] = shares.get(key, 0.0) + share
    ranked = sorted(shares.items(), key=lambda item: -item[1])
    return [(share, dso, symbol) for (dso, symbol), share in ranked[:limit]]


def shortened_symbol(symbol: str) -> str:
    """A demangled C++ symbol with its parameter lists elided: `f<2>(…)`, not 500 characters.

    Template arguments and lambda numbers stay, so distinct functions stay
    distinct; `operator()` and `(anonymous namespace)` are kept as they are.
    """
    anonymous = "(anonymous namespace)"
    text = symbol.replace(anonymous, "\0")
    pieces = []
    depth = 0
    elided = False
    for character in text:
        if character == "(":
            if depth == 0:
                pieces.append("(")
                elided = False
            else:
                elided = True
            depth += 1
        elif character == ")" and depth > 0:
            depth -= 1
            if depth == 0:
                pieces.append("…)" if elided else ")")
        elif depth > 0:
            elided = True
        else:
            pieces.append(character)
    return "".join(pieces).replace("\0", anonymous)


def profile_splash_state(arguments: argparse.Namespace, splash: SplashState) -> ProfileResult:
    """perf profile of one 1-thread run of the t = 0.5 s state.

    One thread, because a flat profile of one thread shows where the work
    goes without OpenMP waiting mixed in.  Failure of perf (missing, or not
    permitted) is reported in the record, not raised: the timings stand alone.
    """
    perf = shutil.which("perf")
    if perf is None:
        return ProfileResult("perf not available")
    steps = shortened_for_quick(PROFILE_STEPS, arguments.quick)
    workload = Workload("profile", f"t={SPLASH_TIME:g}s", steps, CASE_2D, TABLE1_DR,
                        snapshot=splash.path)
    with tempfile.TemporaryDirectory(prefix="revsph-profile-") as scratch:
        scratch_path = Path(scratch)
        data = scratch_path / "perf.data"
        run_command = workload.command(arguments.revsph, 1, str(scratch_path / "run"))
        record = [perf, "record", "-F", "999", "-g", "-o", str(data), "--"] + run_command
        report = [perf, "report"] + PERF_REPORT_OPTIONS + [
            "--field-separator", PERF_SEPARATOR, "-i", str(data)]
        shown_command = (shlex.join(["perf", "record", "-F", "999", "-g", "--"]
                                    + workload.command(arguments.revsph, 1, "TMPDIR"))
                         + "\n" + shlex.join(["perf", "report"] + PERF_REPORT_OPTIONS))
        log(f"profiling {steps} steps of the t = {SPLASH_TIME:g} s state on 1 thread with perf")
        try:
            run_checked(record, capture_output=True)
            summary = read_summary(run_command, scratch_path / "run", steps)
            output = run_checked(report, capture_output=True).stdout
        except (BenchmarkError, OSError) as error:
            return ProfileResult(f"perf failed: {str(error).strip().splitlines()[0]}",
                                 shown_command)
    symbols = parse_perf_report(output, PROFILE_SYMBOLS)
    if not symbols:
        return ProfileResult("perf report listed no symbols", shown_command)
    return ProfileResult(f"{steps} steps, 1 thread", shown_command,
                         stepping_rate(summary), symbols)


def main(argv: list[str]) -> int:
    arguments = parse_arguments(argv)
    if not (arguments.revsph.is_file() and os.access(arguments.revsph, os.X_OK)):
        log(f"error: revsph binary not found at {arguments.revsph}; build it with\n"
            f"  cmake -S {REPO_ROOT} -B {REPO_ROOT / 'build'} -DCMAKE_BUILD_TYPE=Release "
            f"&& cmake --build {REPO_ROOT / 'build'} -j2\nor pass --revsph PATH")
        return 2
    if arguments.snapshot is not None and not arguments.snapshot.is_file():
        log(f"error: snapshot {arguments.snapshot} not found")
        return 2
    cpus = os.cpu_count() or 1
    most_threads = max(max(threads_for_suite(suite, arguments)) for suite in arguments.suite)
    if most_threads > cpus:
        log(f"warning: {most_threads} threads requested but only {cpus} CPUs")

    started = datetime.datetime.now().astimezone()
    binary_sha256 = file_sha256(arguments.revsph)
    load_before = load_average()
    splash = None
    profile = None
    try:
        if needs_splash_state(arguments):
            splash = obtain_splash_state(arguments, binary_sha256)
        workloads = build_workloads(arguments, splash)
        results = run_benchmark(arguments, workloads)
        if arguments.profile:
            profile = profile_splash_state(arguments, splash)
    except BenchmarkError as error:
        log(f"error: {error}")
        return 1

    print_console_report(results, profile)
    if file_sha256(arguments.revsph) != binary_sha256:
        log(f"error: {arguments.revsph} changed while the benchmark ran (rebuilt?); "
            "the results mix two binaries and are not recorded")
        return 1
    if arguments.output is not None:
        arguments.output.parent.mkdir(parents=True, exist_ok=True)
        arguments.output.write_text(
            markdown_report(arguments, workloads, results, splash, profile, started,
                            binary_sha256, load_before),
            encoding="utf-8")
        print(f"\nwrote {arguments.output}")
    all_invariant = all(result.hash_is_invariant for result in results)
    return 0 if all_invariant else 3


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
