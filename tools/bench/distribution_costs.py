#!/usr/bin/python3
"""What a distributed run sends and holds, measured by `revsph run` itself (issue 32): for each
arrangement and process count, summary.json's "distribution" record over a few steps: ghost
fraction, bytes sent a step, MPI calls and exchanges a step, the own particles of the smallest
and largest process, the estimated work imbalance and the seconds inside MPI.

Each arrangement is `NAME=CASE[,KEY=VALUE...]` (the values as `--set` takes them), e.g.
  dambreak-1e6=dambreak,discretisation.dr=0.0014

  /usr/bin/python3 tools/bench/distribution_costs.py --revsph build-mpi/bin/revsph \
      --arrangement dambreak-1e5=dambreak,discretisation.dr=0.0045 --processes 2 4 --steps 20 \
      --output tools/bench/results/X.md
"""

import argparse
import json
import os
import subprocess
import tempfile

from markdown_record import emit


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--revsph", required=True)
    parser.add_argument("--arrangement", action="append", required=True)
    parser.add_argument("--processes", type=int, nargs="+", default=[2, 4])
    parser.add_argument("--steps", type=int, default=20)
    parser.add_argument("--output")
    args = parser.parse_args()

    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMP_NUM_THREADS="1")
    rows = []
    commit = ""
    with tempfile.TemporaryDirectory() as directory:
        for arrangement in args.arrangement:
            name, spec = arrangement.split("=", 1)
            case, *sets = spec.split(",")
            for processes in args.processes:
                out = os.path.join(directory, f"{name}-{processes}")
                command = ["mpirun", "-np", str(processes), "--oversubscribe", "--bind-to",
                           "none", args.revsph, "run", case, "--steps", str(args.steps),
                           "--threads", "1", "--out", out, "--force"]
                for s in sets:
                    command += ["--set", s]
                subprocess.run(command, env=env, capture_output=True, text=True, check=True)
                with open(os.path.join(out, "summary.json")) as f:
                    summary = json.load(f)
                commit = summary["build"]["git_commit"]
                d = summary["distribution"]
                particles = sum(summary["particles"].values())
                rows.append(
                    f"| {name} | {summary['dimension']}D | {particles} | {processes} | "
                    f"{d['ghost_fraction']:.4f} | {d['bytes_sent_per_step'] / 1e6:.3f} | "
                    f"{d['bytes_sent_per_step'] / max(1.0, d['ghost_fraction'] * particles):.1f} | "
                    f"{d['mpi_calls_per_step']:.1f} | {d['mpi_exchanges_per_step']:.1f} | "
                    f"{d['own_particles_min']}-{d['own_particles_max']} | "
                    f"{d['estimated_work_imbalance']:.3f} | "
                    f"{d['communication_seconds_min']:.2f}-{d['communication_seconds_max']:.2f} "
                    f"of {d['stepping_seconds']:.2f} | {summary['final_hash'][:16]} |")
    lines = ["# What a distributed run sends and holds",
             "",
             "    /usr/bin/python3 tools/bench/distribution_costs.py " + " ".join(
                 [f"--arrangement {a}" for a in args.arrangement]
                 + ["--processes"] + [str(p) for p in args.processes]
                 + ["--steps", str(args.steps)]),
             "",
             f"Commit {commit}; {args.steps} steps of each, one thread per process "
             "(`mpirun --oversubscribe` on this 2-core machine: the seconds inside MPI include "
             "the oversubscription's waiting beyond 2 processes). Bytes per ghost: bytes sent a "
             "step / ghosts held by all processes.",
             "",
             "| arrangement | dim | particles | P | ghost fraction | MB sent / step | "
             "bytes / ghost / step | MPI calls / step | exchanges / step | own particles | "
             "work imbalance | in MPI (s) | final hash |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|"] + rows
    emit(lines, args.output)


if __name__ == "__main__":
    main()
