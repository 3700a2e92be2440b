#!/usr/bin/python3
"""Stepping throughput of a case on P processes x T threads, for the distributed run (issue 32).

Times `mpirun -np P revsph hash CASE --steps N` and `--steps 2N` for each layout and takes the
difference, so that the set-up (the same on every process) drops out: the rate is moving particles
x N steps / that time difference. Every layout runs in turn, --repeats rounds, alternating, and the
median is kept (the machines are shared and noisy: read the ratios, measured in one run).

  /usr/bin/python3 tools/bench/processes_vs_threads.py --revsph build-mpi/bin/revsph \
      --case dambreak --steps 100 --layouts 1x2 2x1 --repeats 3 --output tools/bench/results/X.md
"""

import argparse
import os
import statistics
import subprocess
import time

from markdown_record import emit


def timed(revsph, case, steps, processes, threads, sets):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMP_NUM_THREADS=str(threads))
    command = ["mpirun", "-np", str(processes), "--oversubscribe", "--bind-to", "none",
               "-x", "OMP_NUM_THREADS", revsph, "hash", case, "--steps", str(steps),
               "--threads", str(threads)]
    for s in sets:
        command += ["--set", s]
    start = time.perf_counter()
    result = subprocess.run(command, env=env, capture_output=True, text=True, check=True)
    return time.perf_counter() - start, result.stdout.strip().splitlines()[-1]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--revsph", required=True)
    parser.add_argument("--case", required=True)
    parser.add_argument("--steps", type=int, default=100)
    parser.add_argument("--layouts", nargs="+", default=["1x2", "2x1"],
                        help="PROCESSESxTHREADS each")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--particles", type=int, default=0,
                        help="moving particles of the case (for particle-steps/s)")
    parser.add_argument("--set", action="append", default=[], dest="sets")
    parser.add_argument("--output")
    args = parser.parse_args()

    layouts = [tuple(int(x) for x in layout.split("x")) for layout in args.layouts]
    seconds = {layout: [] for layout in layouts}
    hashes = set()
    for _ in range(args.repeats):
        for layout in layouts:
            short, first = timed(args.revsph, args.case, args.steps, *layout, args.sets)
            long, second = timed(args.revsph, args.case, 2 * args.steps, *layout, args.sets)
            seconds[layout].append(long - short)
            hashes.add(second)
    lines = [f"# {args.case}: {args.steps} steps, processes x threads",
             "",
             f"`{' '.join(['tools/bench/processes_vs_threads.py', '--case', args.case, '--steps', str(args.steps), '--layouts'] + args.layouts + ['--repeats', str(args.repeats)] + sum((['--set', s] for s in args.sets), []))}`",
             "",
             "| layout | median s per " + str(args.steps) + " steps | all | particle-steps/s | rate / first layout |",
             "|---|---|---|---|---|"]
    first = statistics.median(seconds[layouts[0]])
    for layout in layouts:
        median = statistics.median(seconds[layout])
        rate = args.particles * args.steps / median if args.particles else float("nan")
        lines.append(f"| {layout[0]} x {layout[1]} | {median:.3f} | "
                     f"{', '.join(f'{s:.3f}' for s in seconds[layout])} | {rate:.3g} | "
                     f"{first / median:.3f} |")
    lines += ["", f"final hashes over every run: {len(hashes)} distinct ({', '.join(h[:16] for h in sorted(hashes))})"]
    emit(lines, args.output)


if __name__ == "__main__":
    main()
