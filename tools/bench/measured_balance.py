#!/usr/bin/python3
"""What cutting the regions on measured computing times gains (issue 32; measured_cost.hpp).

Runs `mpirun -np 2 --bind-to core revsph run CASE --steps N --threads 1` with the regions cut on
the estimated work alone (REVSPH_BALANCE_BY_TIME=0) and with the measured times as well (the
default), alternating, --repeats rounds each; with --busy-core, a busy loop pinned to core 0
(`taskset`) takes half of process 0's core for the whole measurement: a noisy neighbour, as on a
shared node. Prints, per setting, the median stepping rate, the processes' seconds inside MPI
(the difference is mostly waiting), the own particles of each process and the rebalances.

  /usr/bin/python3 tools/bench/measured_balance.py --revsph build-mpi/bin/revsph \
      --case dambreak --steps 800 --repeats 2 --busy-core --output tools/bench/results/X.md
"""

import argparse
import os
import statistics
import subprocess
import tempfile

from markdown_record import emit, hashes_line
from mpi_run import mpi_run_summary

SETTINGS = {"estimate alone": "0", "estimate and measured times": "on"}


def run(revsph, case, steps, by_time, directory):
    return mpi_run_summary(["-np", "2", "--bind-to", "core", "--map-by", "core"], revsph,
                           [case, "--steps", str(steps), "--threads", "1"],
                           os.path.join(directory, f"by-time-{by_time}"),
                           {"OMP_NUM_THREADS": "1", "REVSPH_BALANCE_BY_TIME": by_time})


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--revsph", required=True)
    parser.add_argument("--case", default="dambreak")
    parser.add_argument("--steps", type=int, default=800)
    parser.add_argument("--repeats", type=int, default=2)
    parser.add_argument("--busy-core", action="store_true")
    parser.add_argument("--output")
    args = parser.parse_args()

    busy = (subprocess.Popen(["taskset", "-c", "0", "sh", "-c", "while :; do :; done"])
            if args.busy_core else None)
    rates = {name: [] for name in SETTINGS}
    last, hashes = {}, set()
    try:
        with tempfile.TemporaryDirectory() as directory:
            for _ in range(args.repeats):
                for name, by_time in SETTINGS.items():
                    summary = run(args.revsph, args.case, args.steps, by_time, directory)
                    rates[name].append(summary["stepping_particle_steps_per_second"])
                    hashes.add(summary["final_hash"])
                    last[name] = summary
    finally:
        if busy:
            busy.kill()
    command = ["tools/bench/measured_balance.py", "--case", args.case, "--steps",
               str(args.steps), "--repeats", str(args.repeats)] + (
                   ["--busy-core"] if args.busy_core else [])
    first = statistics.median(rates[next(iter(SETTINGS))])
    lines = [f"# {args.case} on 2 processes x 1 thread, {args.steps} steps: regions cut on the "
             "estimated work alone, or on measured computing times as well",
             "",
             f"    /usr/bin/python3 {' '.join(command)}",
             "",
             ("A busy loop pinned to core 0 shared process 0's core throughout. "
              if args.busy_core else "Nothing else ran on purpose. ") +
             "Rates: moving particle-steps per second of stepping; in MPI, own particles: the "
             "smaller and larger process's (last round).",
             "",
             "| regions cut on | median particle-steps/s | all | rate / first | in MPI (s) | "
             "stepping (s) | own particles | rebalances (on measured time) |",
             "|---|---|---|---|---|---|---|---|"]
    for name in SETTINGS:
        d = last[name]["distribution"]
        median = statistics.median(rates[name])
        lines.append(
            f"| {name} | {median:.3g} | {', '.join(f'{r:.3g}' for r in rates[name])} | "
            f"{median / first:.3f} | {d['communication_seconds_min']:.2f}-"
            f"{d['communication_seconds_max']:.2f} | {last[name]['stepping_seconds']:.2f} | "
            f"{d['own_particles_min']}-{d['own_particles_max']} | {d['rebalances']} "
            f"({d.get('rebalances_by_measured_time', 0)}) |")
    lines += ["", hashes_line(hashes, last[next(iter(SETTINGS))])]
    emit(lines, args.output)


if __name__ == "__main__":
    main()
