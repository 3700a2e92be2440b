#!/usr/bin/python3
"""Stepping throughput of a case on P processes x T threads, for the distributed run (issue 32).

Runs `mpirun -np P revsph run CASE --steps N --threads T` for each layout and reads its
summary.json: the stepping time alone (set-up and snapshot writes excluded), the final hash and,
on more than one process, the "distribution" record (seconds inside MPI, bytes sent, ghosts,
rebalances). Every layout runs in turn, --repeats rounds, alternating, and the median is kept
(the machines are shared and noisy: read the ratios, measured in one run).

  /usr/bin/python3 tools/bench/processes_vs_threads.py --revsph build-mpi/bin/revsph \
      --case dambreak --steps 200 --layouts 1x2 2x1 --repeats 3 --output tools/bench/results/X.md
"""

import argparse
import os
import statistics
import tempfile

from markdown_record import emit, hashes_line
from mpi_run import mpi_run_summary


def run(revsph, case, steps, processes, threads, sets, directory):
    arguments = [case, "--steps", str(steps), "--threads", str(threads)]
    for s in sets:
        arguments += ["--set", s]
    return mpi_run_summary(["-np", str(processes), "--oversubscribe", "--bind-to", "none"],
                           revsph, arguments, os.path.join(directory, f"{processes}x{threads}"),
                           {"OMP_NUM_THREADS": str(threads)})


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--revsph", required=True)
    parser.add_argument("--case", required=True)
    parser.add_argument("--steps", type=int, default=200)
    parser.add_argument("--layouts", nargs="+", default=["1x2", "2x1"],
                        help="PROCESSESxTHREADS each")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--set", action="append", default=[], dest="sets")
    parser.add_argument("--output")
    args = parser.parse_args()

    layouts = [tuple(int(x) for x in layout.split("x")) for layout in args.layouts]
    rates = {layout: [] for layout in layouts}
    last = {}
    hashes = set()
    with tempfile.TemporaryDirectory() as directory:
        for _ in range(args.repeats):
            for layout in layouts:
                summary = run(args.revsph, args.case, args.steps, *layout, args.sets, directory)
                rates[layout].append(summary["stepping_particle_steps_per_second"])
                hashes.add(summary["final_hash"])
                last[layout] = summary
    command = ["tools/bench/processes_vs_threads.py", "--case", args.case, "--steps",
               str(args.steps), "--layouts", *args.layouts, "--repeats", str(args.repeats)]
    for s in args.sets:
        command += ["--set", s]
    particles = sum(last[layouts[0]]["particles"].values())
    lines = [f"# {args.case}: {args.steps} steps, processes x threads",
             "",
             f"    /usr/bin/python3 {' '.join(command)}",
             "",
             f"{particles} particles. Rates: moving particle-steps per second of stepping "
             "(summary.json's stepping_particle_steps_per_second); in MPI: the smallest and "
             "largest process's seconds inside MPI calls over the steps (the difference is "
             "mostly waiting), from the last round.",
             "",
             "| layout | median particle-steps/s | all | rate / first layout | in MPI (s) | "
             "stepping (s) | ghost fraction | bytes sent / step | MPI calls / step | "
             "work imbalance | rebalances |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    first = statistics.median(rates[layouts[0]])
    for layout in layouts:
        median = statistics.median(rates[layout])
        d = last[layout].get("distribution", {})
        in_mpi = (f"{d['communication_seconds_min']:.3f}-{d['communication_seconds_max']:.3f}"
                  if layout[0] > 1 else "-")
        lines.append(
            f"| {layout[0]} x {layout[1]} | {median:.3g} | "
            f"{', '.join(f'{r:.3g}' for r in rates[layout])} | {median / first:.3f} | {in_mpi} | "
            f"{last[layout]['stepping_seconds']:.2f} | {d.get('ghost_fraction', 0):.4f} | "
            f"{d.get('bytes_sent_per_step', 0):.4g} | {d.get('mpi_calls_per_step', 0):.1f} | "
            f"{d.get('estimated_work_imbalance', 1):.3f} | {d.get('rebalances', 0)} |")
    lines += ["", hashes_line(hashes, last[layouts[0]])]
    emit(lines, args.output)


if __name__ == "__main__":
    main()
