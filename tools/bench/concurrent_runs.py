#!/usr/bin/python3
"""Two runs at once against the same two one after the other, on a shared machine.

A user of a 2-core machine starts two 2-thread runs at the same time; they should cost about what
running them one after the other costs, not several times more (OpenMP threads spinning at
barriers while their partner has no core: tools/revsph/openmp_waiting.hpp). For each workload and
repeat, this times two runs in sequence and then the same two started together, and prints the
ratio concurrent / sequential (the issue's criterion: at most 1.5).

  /usr/bin/python3 tools/bench/concurrent_runs.py --revsph build/bin/revsph --repeats 3

Set GOMP_SPINCOUNT or OMP_WAIT_POLICY in the environment to measure libgomp's own policies.
"""

import argparse
import statistics
import subprocess
import tempfile
import time

WORKLOADS = {
    "dambreak-small, 2000 steps": ["dambreak-small", "--steps", "2000"],
    "Table-1 dam break, 400 steps": ["dambreak", "--steps", "400"],
}


def command(revsph, workload, threads, out):
    return [revsph, "run", *workload, "--threads", str(threads), "--out", out, "--force", "--set",
            "output.snapshot_every=100000000"]


def timed(commands):
    start = time.monotonic()
    processes = [subprocess.Popen(c, stdout=subprocess.DEVNULL) for c in commands]
    for p in processes:
        if p.wait() != 0:
            raise SystemExit(f"failed: {' '.join(p.args)}")
    return time.monotonic() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--revsph", default="build/bin/revsph")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="revsph-concurrent-") as work:
        runs = [f"{work}/a", f"{work}/b"]
        print("| workload | one after the other (s) | at once (s) | ratio |")
        print("|---|---|---|---|")
        for name, workload in WORKLOADS.items():
            ratios = []
            for _ in range(args.repeats):
                sequential = sum(timed([command(args.revsph, workload, args.threads, out)])
                                 for out in runs)
                concurrent = timed([command(args.revsph, workload, args.threads, out)
                                    for out in runs])
                ratios.append(concurrent / sequential)
                print(f"| {name} | {sequential:.2f} | {concurrent:.2f} | "
                      f"{concurrent / sequential:.2f} |", flush=True)
            print(f"| {name}: median ratio | | | {statistics.median(ratios):.2f} |", flush=True)


if __name__ == "__main__":
    main()
