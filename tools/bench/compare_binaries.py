#!/usr/bin/python3
"""Throughput of two revsph binaries side by side, on the same workloads, in one run.

The machines are shared and their speed drifts by 2x between hours, so a change is measured
against the previous binary in one go: every (workload, threads) configuration runs both binaries,
alternating A, B, A, B, ... for --repeats rounds, and the ratio B / A of the median rates is the
figure to read. The rate is revsph's own `stepping_particle_steps_per_second` (moving particles x
steps / wall time of the time steps, without setup and snapshot writing) from summary.json.

  /usr/bin/python3 tools/bench/compare_binaries.py --baseline OLD/revsph --candidate build/bin/revsph \
      --case dambreak --steps 400 --threads 1 2 --repeats 3 --output tools/bench/results/X.md

Extra `--set key=value` arguments are passed to every run (e.g. a smaller dr).
"""

import argparse
import json
import os
import statistics
import subprocess
import tempfile
import time

from markdown_record import emit


def rate(binary, case, steps, threads, sets, work):
    out = os.path.join(work, "run")
    command = [binary, "run", case, "--steps", str(steps), "--threads", str(threads), "--out",
               out, "--force", "--set", "output.snapshot_every=100000000"]
    for s in sets:
        command += ["--set", s]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    return summary["stepping_particle_steps_per_second"], summary["final_hash"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--baseline", required=True, help="the previous binary (A)")
    parser.add_argument("--candidate", required=True, help="the new binary (B)")
    parser.add_argument("--case", action="append", required=True, help="case name or file")
    parser.add_argument("--steps", type=int, default=400)
    parser.add_argument("--threads", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--set", action="append", default=[], dest="sets")
    parser.add_argument("--output", help="also write the table as Markdown to this file")
    args = parser.parse_args()

    rows = []
    with tempfile.TemporaryDirectory(prefix="revsph-compare-") as work:
        for case in args.case:
            for threads in args.threads:
                rates = {"A": [], "B": []}
                hashes = {"A": set(), "B": set()}
                for _ in range(args.repeats):
                    for label, binary in (("A", args.baseline), ("B", args.candidate)):
                        r, h = rate(binary, case, args.steps, threads, args.sets, work)
                        rates[label].append(r)
                        hashes[label].add(h)
                a = statistics.median(rates["A"])
                b = statistics.median(rates["B"])
                rows.append((case, threads, a, min(rates["A"]), max(rates["A"]), b,
                             min(rates["B"]), max(rates["B"]), b / a,
                             "same" if hashes["A"] == hashes["B"] else "different"))
                print(f"{case} {threads} thread(s): A {a:.3e}  B {b:.3e}  B/A {b / a:.3f}",
                      flush=True)

    lines = [f"Run {time.strftime('%Y-%m-%d %H:%M')} UTC: {args.steps} steps, {args.repeats} "
             f"alternating rounds, median particle-steps/s (min-max).",
             f"A = `{args.baseline}`, B = `{args.candidate}`"
             + (f", `--set {' '.join(args.sets)}`" if args.sets else "") + ".", "",
             "| case | threads | A | B | B / A | final hash A vs B |", "|---|---|---|---|---|---|"]
    for case, threads, a, a_lo, a_hi, b, b_lo, b_hi, ratio, same in rows:
        lines.append(f"| {case} | {threads} | {a:.3e} ({a_lo:.2e}-{a_hi:.2e}) | {b:.3e} "
                     f"({b_lo:.2e}-{b_hi:.2e}) | {ratio:.3f} | {same} |")
    emit(lines, args.output)


if __name__ == "__main__":
    main()
