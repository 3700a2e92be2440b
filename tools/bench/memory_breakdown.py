#!/usr/bin/python3
"""Where the bytes per particle go (issue 31, item 8): the heap at its peak, by component, and
the process's peak resident size beside the size of a process that holds no particles.

Usage: /usr/bin/python3 tools/bench/memory_breakdown.py [CASE] [--steps N] [--revsph PATH]
           [--set KEY=VALUE ...] [--stacks N]

Runs `revsph run CASE --steps N --threads 1` under heaptrack (Debian package heaptrack; it
records every allocation with its stack) and sums the heap held at the peak by the first
component found on each allocation's stack (snapshot output before the rest: a snapshot's
copies and derived views are the peak). Prints MB and bytes per particle (all particles, walls
included). Default: the Table-1 dam break (`dambreak`), 20 steps (a snapshot at the start and
one at the end). --stacks N also prints the N largest allocation sites at the peak (the
innermost three frames of revsph's own code).
"""

import argparse
import collections
import json
import os
import pathlib
import resource
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]

# (a function name fragment on the allocation's stack, the component it stands for): the first
# that matches wins.
COMPONENTS = [
    ("write_snapshot", "snapshot output: state copies and derived views"),
    ("derived_views", "derived views (outside a snapshot)"),
    ("HalfPairList::", "pair list"),
    ("find_neighbours", "neighbour list (initial state correction)"),
    ("SlotLayout", "slot layout: gathered copies of the state"),
    ("sum_pairs_over", "pair sums: per-slot accumulators"),
    ("update_derived", "derived per-slot fields (density, pressure, ...)"),
    ("CellList", "cell list"),
    ("fill_vector_field", "state fields"),
    ("fill_scalar_field", "state fields"),
    ("create_in", "model set-up (state, constants)"),
    ("H5", "HDF5"),
    ("CLI::", "command line (CLI11)"),
    ("toml::", "case file (toml++)"),
    ("OPENSSL", "OpenSSL (state hash)"),
    ("CRYPTO", "OpenSSL (state hash)"),
]


def peak_rss_of(command, env):
    """Peak resident size (bytes) of a child process, alone."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    subprocess.run(command, env=env, check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    return after * 1024 if after > before else None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("case", nargs="?", default="dambreak")
    parser.add_argument("--steps", type=int, default=20)
    parser.add_argument("--revsph", default=str(ROOT / "build" / "bin" / "revsph"))
    parser.add_argument("--set", action="append", default=[], dest="overrides")
    parser.add_argument("--stacks", type=int, default=0,
                        help="also print the N largest allocation sites at the peak")
    args = parser.parse_args()
    env = dict(os.environ, GOMP_SPINCOUNT=os.environ.get("GOMP_SPINCOUNT", "1000"))
    overrides = [item for pair in args.overrides for item in ("--set", pair)]

    baseline = peak_rss_of([args.revsph, "cases"], env)
    with tempfile.TemporaryDirectory(prefix="revsph-memory-") as work:
        work = pathlib.Path(work)
        run = [args.revsph, "run", args.case, *overrides, "--steps", str(args.steps),
               "--threads", "1", "--out", str(work / "out"), "--force"]
        # The run's own peak resident size, without heaptrack's overhead.
        subprocess.run(run, env=env, check=True, stdout=subprocess.DEVNULL)
        summary = json.loads((work / "out" / "summary.json").read_text())
        subprocess.run(["heaptrack", "-o", str(work / "heap"), *run], env=env, check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        recording = next(work.glob("heap*.zst"), None) or next(work.glob("heap*"))
        subprocess.run(["heaptrack_print", "-f", str(recording), "--print-flamegraph",
                        str(work / "peak.txt"), "--flamegraph-cost-type", "peak"], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        groups = collections.Counter()
        sites = collections.Counter()
        for line in (work / "peak.txt").read_text().splitlines():
            stack, cost = line.rsplit(" ", 1)
            frames = stack.split(";")
            name = next((component for fragment, component in COMPONENTS
                         if any(fragment in frame for frame in frames)), "other")
            groups[name] += int(cost)
            # The site: the innermost frames of revsph's own code (namespace revsph).
            own = [frame.split("(")[0][-70:] for frame in frames if "revsph::" in frame]
            sites[" < ".join(reversed(own[-3:]))] += int(cost)

    particles = sum(summary["particles"].values())
    heap = sum(groups.values())
    rss = summary.get("peak_memory_bytes")
    print(f"{args.case}: {particles} particles ({summary['particles']}), {args.steps} steps, "
          f"1 thread")
    print(f"{'component':52s} {'MB':>8s} {'B/particle':>11s}")
    for name, cost in groups.most_common():
        print(f"{name:52s} {cost / 1e6:8.2f} {cost / particles:11.1f}")
    print(f"{'heap at its peak (heaptrack)':52s} {heap / 1e6:8.2f} {heap / particles:11.1f}")
    for site, cost in sites.most_common(args.stacks):
        print(f"  {cost / particles:7.1f} B/particle  {site}")
    if rss:
        print(f"{'peak resident size of the run (summary.json)':52s} {rss / 1e6:8.2f} "
              f"{rss / particles:11.1f}")
    if baseline:
        print(f"{'resident size of `revsph cases` (no particles)':52s} {baseline / 1e6:8.2f} "
              f"{baseline / particles:11.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
