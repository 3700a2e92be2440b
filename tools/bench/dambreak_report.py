#!/usr/bin/python3
"""The dam-break benchmark's report (tools/bench/dambreak_benchmark.py): speed-up and scaling
tables, the hash invariance, the profile, the machine and build, as Markdown and on the console."""

from __future__ import annotations

import argparse
import datetime
import hashlib
import os
import platform
import shlex
import statistics
import subprocess
import sys
from pathlib import Path


from dambreak_workloads import (CASE_3D, LINEARITY_TOLERANCE, MIN_STEPS, PROFILE_SYMBOL_WIDTH,
    ProfileResult, REPO_ROOT, SCALING_PARTICLE_STEPS, SPLASH_TIME, SplashState, TABLE1_DR,
    THREE_D_PARTICLE_STEPS, Workload, WorkloadResults, threads_for_suite)

# --------------------------------------------------------------------------
# Analysis and formatting
# --------------------------------------------------------------------------


def harmonic_mean(values: list[float]) -> float:
    """The mean rate of a run that spends equally many steps at each of these rates."""
    return len(values) / sum(1.0 / value for value in values)


def speedup_header(results: list[WorkloadResults]) -> str:
    smallest = min(min(r.by_threads) for r in results)
    return f"speed-up vs {smallest} thread{'s' if smallest > 1 else ''}"


def speedup_cell(result: WorkloadResults, threads: int) -> str:
    """Median rate against the smallest thread count of this workload ('-' if alone)."""
    if len(result.by_threads) < 2:
        return "-"
    baseline = result.by_threads[min(result.by_threads)].median_rate
    return f"{result.by_threads[threads].median_rate / baseline:.2f}"


def measurement_cells(result: WorkloadResults, threads: int) -> list[str]:
    """The columns every suite table shares, from 'fluid particles' to 'bytes/particle'."""
    summary = result.by_threads[threads]
    first = summary.runs[0]
    return [
        str(first.fluid_particles),
        str(first.wall_particles),
        str(threads),
        str(first.steps),
        f"{summary.median_rate:.3e}",
        f"{min(summary.rates):.3e}",
        f"{max(summary.rates):.3e}",
        speedup_cell(result, threads),
        f"{summary.peak_memory_bytes / 1e6:.1f}",
        f"{summary.peak_memory_bytes / summary.total_particles:.0f}",
    ]


def measurement_header(results: list[WorkloadResults]) -> list[str]:
    return ["fluid particles", "wall particles", "threads", "steps",
            "median particle-steps/s", "min", "max", speedup_header(results),
            "peak memory (MB)", "bytes/particle"]


def table1_rows(results: list[WorkloadResults]) -> list[list[str]]:
    """One row per (state, threads), then the mean of the states per thread count."""
    rows = [["state"] + measurement_header(results)]
    for result in results:
        for threads in result.by_threads:
            rows.append([result.workload.label] + measurement_cells(result, threads))
    common_threads = [k for k in results[0].by_threads
                      if all(k in r.by_threads for r in results)]
    means = {k: harmonic_mean([r.by_threads[k].median_rate for r in results])
             for k in common_threads}
    for threads, mean in means.items():
        speedup = f"{mean / means[min(means)]:.2f}" if len(means) > 1 else "-"
        rows.append(["mean of the states (full run)", "", "", str(threads), "",
                     f"{mean:.3e}", "", "", speedup, "", ""])
    return rows


def scaling_rows(results: list[WorkloadResults]) -> list[list[str]]:
    """One row per (dr, threads), with the rate relative to the mean over sizes."""
    header = measurement_header(results)
    # The ratio goes right after the median it is computed from.
    ratio_column = header.index("median particle-steps/s") + 1
    header.insert(ratio_column, "rate / mean of sizes")
    rows = [["dr (m)"] + header]
    mean_rates = scaling_mean_rates(results)
    for result in results:
        for threads in result.by_threads:
            cells = measurement_cells(result, threads)
            ratio = result.by_threads[threads].median_rate / mean_rates[threads]
            cells.insert(ratio_column, f"{ratio:.2f}")
            rows.append([f"{result.workload.dr:g}"] + cells)
    return rows


def scaling_mean_rates(results: list[WorkloadResults]) -> dict[int, float]:
    """Per thread count, the arithmetic mean of the median rates over all sizes."""
    thread_counts = sorted({k for r in results for k in r.by_threads})
    return {k: statistics.mean(r.by_threads[k].median_rate for r in results
                               if k in r.by_threads)
            for k in thread_counts}


def scaling_verdict_lines(results: list[WorkloadResults]) -> list[str]:
    """Per thread count: is the cost per particle-step independent of N (within 20 %)?"""
    lines = []
    for threads in scaling_mean_rates(results):
        rates = [r.by_threads[threads].median_rate for r in results if threads in r.by_threads]
        if len(rates) < 2:
            lines.append(f"{threads} thread{'s' if threads > 1 else ''}: one size only, "
                         "no verdict on linearity in N")
            continue
        spread = max(rates) / min(rates)
        verdict = "yes" if spread <= LINEARITY_TOLERANCE else "no"
        lines.append(f"{threads} thread{'s' if threads > 1 else ''}: max/min of the median "
                     f"rates over {len(rates)} sizes = {spread:.2f}; linear in N within "
                     f"{(LINEARITY_TOLERANCE - 1) * 100:.0f} %: {verdict}")
    return lines


def three_d_rows(results: list[WorkloadResults]) -> list[list[str]]:
    rows = [["dr (m)"] + measurement_header(results)]
    for result in results:
        for threads in result.by_threads:
            rows.append([f"{result.workload.dr:g}"] + measurement_cells(result, threads))
    return rows


def format_markdown_table(rows: list[list[str]], text_columns: int = 0) -> str:
    """A markdown table with padded columns, readable as plain text too.

    The first `text_columns` columns hold names and are aligned left; the
    others hold numbers and are aligned right, so digits line up.
    """
    widths = [max(len(row[i]) for row in rows) for i in range(len(rows[0]))]

    def format_row(row: list[str]) -> str:
        cells = [cell.ljust(width) if i < text_columns else cell.rjust(width)
                 for i, (cell, width) in enumerate(zip(row, widths))]
        return "| " + " | ".join(cells) + " |"

    separator = "|" + "|".join(
        ":" + "-" * (width + 1) if i < text_columns else "-" * (width + 1) + ":"
        for i, width in enumerate(widths)) + "|"
    return "\n".join([format_row(rows[0]), separator] + [format_row(row) for row in rows[1:]])


def results_of_suite(results: list[WorkloadResults], suite: str) -> list[WorkloadResults]:
    return [result for result in results if result.workload.suite == suite]


def suite_sections(results: list[WorkloadResults]) -> list[str]:
    """Markdown lines: one section per suite that ran."""
    lines = []
    table1 = results_of_suite(results, "table1")
    if table1:
        lines += [
            f"### table1: Table-1 dam break (2D, dr = {TABLE1_DR:g} m)",
            "",
            f"`t=0` starts from the fresh lattice; `t={SPLASH_TIME:g}s` continues from the "
            f"t = {SPLASH_TIME:g} s state (splashing, disordered fluid). The last rows are the "
            "harmonic mean of the two median rates: the rate of a run spending equally many "
            "steps in both states, the representative figure of a full run.",
            "",
            format_markdown_table(table1_rows(table1), text_columns=1),
            "",
        ]
    scaling = results_of_suite(results, "scaling")
    if scaling:
        lines += [
            "### scaling: 2D dam break, rate against problem size",
            "",
            "Steps per run are chosen for about "
            f"{SCALING_PARTICLE_STEPS:.1e} particle-steps (at least {MIN_STEPS} steps). "
            "`rate / mean of sizes` is the median rate over the mean of the median rates of "
            "all sizes with the same thread count.",
            "",
            format_markdown_table(scaling_rows(scaling)),
            "",
        ]
        lines += [f"- {line}" for line in scaling_verdict_lines(scaling)] + [""]
    three_d = results_of_suite(results, "3d")
    if three_d:
        lines += [
            f"### 3d: {CASE_3D}",
            "",
            f"Steps per run are chosen for about {THREE_D_PARTICLE_STEPS:.1e} particle-steps "
            f"(at least {MIN_STEPS} steps).",
            "",
            format_markdown_table(three_d_rows(three_d)),
            "",
        ]
    return lines


def hash_invariance_lines(results: list[WorkloadResults]) -> list[str]:
    lines = []
    for result in results:
        verdict = "yes" if result.hash_is_invariant else "no"
        runs = sum(len(summary.runs) for summary in result.by_threads.values())
        runs_text = f"{runs} run{'s' if runs > 1 else ''}"
        threads = ", ".join(str(k) for k in result.by_threads)
        if result.hash_is_invariant:
            hashes = f"{result.first_run.final_hash[:16]}…"
        else:
            # Which thread count (or repeat) diverged is the first clue to the bug.
            hashes = "; ".join(
                f"{k} thread{'s' if k > 1 else ''}: "
                + ", ".join(f"{run.final_hash[:16]}…" for run in summary.runs)
                for k, summary in result.by_threads.items())
        lines.append(f"{result.workload.title}: hash invariant: {verdict} "
                     f"({runs_text}, threads {threads}; {hashes})")
    return lines


def profile_lines(profile: ProfileResult) -> list[str]:
    """Markdown lines of the profile summary."""
    if not profile.symbols:
        lines = [f"Profile: {profile.note}."]
        if profile.command:
            lines += ["", "```sh", profile.command, "```"]
        return lines
    rate = (f", {profile.particle_steps_per_second:.3e} particle-steps/s under perf"
            if profile.particle_steps_per_second else "")
    lines = [
        f"One run of the t = {SPLASH_TIME:g} s state ({profile.note}{rate}), flat profile "
        "(self time, no children) of the whole process, so loading the snapshot and writing "
        "the final state are included. Parameter lists are elided and symbols that then read "
        f"the same are added up; the top {len(profile.symbols)}:",
        "",
        "```sh",
        profile.command,
        "```",
        "",
    ]
    rows = [["symbol", "object", "share of samples"]]
    for share, dso, symbol in profile.symbols:
        if len(symbol) > PROFILE_SYMBOL_WIDTH:
            symbol = symbol[:PROFILE_SYMBOL_WIDTH - 1] + "…"
        rows.append(["`" + symbol.replace("|", "\\|") + "`", f"`{dso}`", f"{share:.1f} %"])
    return lines + [format_markdown_table(rows, text_columns=2)]


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


def build_description(results: list[WorkloadResults], revsph: Path,
                      binary_sha256: str) -> list[tuple[str, str]]:
    build = results[0].first_run.build if results else {}
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


def example_commands(arguments: argparse.Namespace, workloads: list[Workload]) -> list[str]:
    """One revsph command per kind of workload (the first of each suite, and the snapshot run)."""
    examples = []
    seen = set()
    for workload in workloads:
        kind = (workload.suite, workload.snapshot is not None)
        if kind in seen:
            continue
        seen.add(kind)
        threads = threads_for_suite(workload.suite, arguments)[0]
        examples.append(shlex.join(workload.command(arguments.revsph, threads, "TMPDIR")))
    return examples


def markdown_report(arguments: argparse.Namespace, workloads: list[Workload],
                    results: list[WorkloadResults], splash: SplashState | None,
                    profile: ProfileResult | None, started: datetime.datetime,
                    binary_sha256: str, load_before: str) -> str:
    lines = [
        "# Dam-break benchmark",
        "",
        f"- date: {started.isoformat(timespec='seconds')}",
        f"- suites: {', '.join(arguments.suite)}",
        f"- command (run in `{os.getcwd()}`):",
        "",
        "  ```sh",
        f"  {invoked_command_line()}",
        "  ```",
        "",
        f"- each configuration is a separate process, {arguments.repeats} repeat(s), e.g.",
        "",
        "  ```sh",
    ]
    lines += [f"  {example}" for example in example_commands(arguments, workloads)]
    lines += ["  ```", ""]
    if arguments.quick:
        lines += ["- **--quick**: a smoke test of the script; the figures are too short to "
                  "quote.", ""]
    lines += ["## Machine", ""]
    lines += [f"- {name}: {value}" for name, value in machine_description(load_before)]
    lines += ["", "## Build", ""]
    lines += [f"- {name}: {value}"
              for name, value in build_description(results, arguments.revsph, binary_sha256)]
    if splash is not None:
        lines += [
            "",
            "## Inputs",
            "",
            f"- t = {SPLASH_TIME:g} s state: {splash.path}",
            f"  - {splash.origin}",
            f"  - SHA-256: {splash.sha256}",
        ]
    lines += [
        "",
        "## Results",
        "",
        "Particle-steps/s counts fluid particles x steps over the wall time of the time steps "
        "alone (revsph's stepping_particle_steps_per_second: without the first and last "
        "snapshot writes); the "
        "median, min and max are over the repeats. Peak memory is the largest maxrss over the "
        "repeats (MB = 10^6 bytes); bytes/particle divides it by fluid + wall particles.",
        "",
    ]
    lines += suite_sections(results)
    lines += [
        "## Determinism",
        "",
        "Final state hash identical across thread counts and repeats:",
        "",
    ]
    lines += [f"- {line}" for line in hash_invariance_lines(results)]
    if profile is not None:
        lines += ["", "## Profile", ""] + profile_lines(profile)
    return "\n".join(lines) + "\n"


def print_console_report(results: list[WorkloadResults], profile: ProfileResult | None) -> None:
    for line in suite_sections(results):
        print(line)
    for line in hash_invariance_lines(results):
        print(line)
    if profile is not None:
        print()
        for line in profile_lines(profile):
            print(line)


