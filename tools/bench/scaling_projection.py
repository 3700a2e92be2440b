#!/usr/bin/python3
"""Projected strong and weak scaling of a distributed 3D run to 64 and 1 024 processes (issue 32).

Measured on this machine, then modelled beyond it. The inputs are summary.json files of `revsph
run` (tools/revsph/summary.cpp):
  --single       a one-process run of the 3D case with as many threads as the distributed run
                 has processes (every core busy in both, so that sharing the memory costs both
                 alike): the compute time per particle-step and core, t_c;
  --distributed  the same case and steps on P >= 2 processes, one thread each: its
                 "distribution" record gives the bytes sent per ghost and exchange, the exchanges
                 and the other MPI calls (reductions) per step, and the work a ghost adds, kappa:
                 the processes' compute time (stepping minus the mean time inside MPI, times P)
                 over t_c x particle-steps is 1 + kappa x ghost fraction.

The model (each assumption is printed with the record):
  * a case of N particles on P processes; each process owns n = N / P particles in a near-cubic
    region (recursive coordinate bisection of a bulk 3D domain) of side n^(1/3) particle spacings;
  * its ghosts fill a band of `--band` spacings around its inner faces (the reach plus the skin of
    a quarter of it, in particle spacings dr): with m = P^(1/3) regions along each axis a share
    f = 1 - 1/m of the faces is inner, and G = (n^(1/3) + 2 f band)^3 - n;
  * compute per step = t_c (n + kappa G), kappa measured (above): a ghost is built into the
    cell list and the pair list, its pairs with own particles are computed on both sides, and the
    distributed layer's own work (refreshes, migration checks) is counted in it;
  * the work is balanced (the imbalance seen on 2 processes is not carried over);
  * each exchange per step costs an all-to-all of the counts (one message per other process:
    (P - 1) latencies, OpenMPI's linear algorithm; removed where the plan knows the counts), and
    the values to each neighbour region (up to 26): 26 latencies + bytes / bandwidth;
  * each reduction costs 2 log2(P) latencies (recursive doubling);
  * no overlap of communication with computation (revsph waits for each exchange);
  * the network: InfiniBand HDR, 200 Gb/s = 25 GB/s per link, MPI latency 1 us between nodes
    (NVIDIA ConnectX-6 HDR: 200 Gb/s, sub-microsecond port latency; OSU micro-benchmark
    osu_latency on HDR clusters reports 1.0-1.1 us for small messages).

  /usr/bin/python3 tools/bench/scaling_projection.py --single ONE/summary.json \
      --distributed TWO/summary.json --band 3.75 --particles 1e8 --output FILE.md
"""

import argparse
import json
import math

from markdown_record import emit

LATENCY = 1.0e-6      # s per message (InfiniBand HDR, MPI small-message latency)
BANDWIDTH = 25.0e9    # bytes/s (200 Gb/s HDR link)
NEIGHBOURS = 26       # regions around a cubic region in 3D


def ghosts(n, band, processes):
    if processes == 1:
        return 0.0
    inner = 1.0 - processes ** (-1.0 / 3.0)
    return (n ** (1.0 / 3.0) + 2.0 * inner * band) ** 3 - n


def step_seconds(total, processes, measured):
    n = total / processes
    g = ghosts(n, measured["band"], processes)
    compute = measured["t_c"] * (n + measured["kappa"] * g)
    if processes == 1:
        return compute, 0.0, g / n
    neighbours = min(NEIGHBOURS, processes - 1)
    exchange = ((processes - 1) * LATENCY + neighbours * LATENCY
                + g * measured["bytes_per_ghost_exchange"] / BANDWIDTH)
    reduction = 2.0 * math.log2(processes) * LATENCY
    communication = (measured["exchanges"] * exchange
                     + measured["reductions"] * reduction)
    return compute, communication, g / n


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--single", required=True, help="summary.json of 1 process x 1 thread")
    parser.add_argument("--distributed", required=True,
                        help="summary.json of P processes x 1 thread (same case)")
    parser.add_argument("--band", type=float, required=True,
                        help="ghost band width in particle spacings (reach x 1.25 / dr)")
    parser.add_argument("--particles", type=float, default=1e8)
    parser.add_argument("--output")
    args = parser.parse_args()

    with open(args.single) as f:
        single = json.load(f)
    with open(args.distributed) as f:
        distributed = json.load(f)
    record = distributed["distribution"]
    particles_measured = sum(distributed["particles"].values())
    ghost_total = record["ghost_fraction"] * particles_measured
    exchanges = record["mpi_exchanges_per_step"]
    processes = record["processes"]
    if single["threads"] != processes or single["steps"] != distributed["steps"]:
        raise SystemExit("--single must have as many threads as --distributed has processes, "
                         "and the same steps")
    t_c = single["threads"] / single["stepping_particle_steps_per_second"]
    particle_steps = (distributed["stepping_particle_steps_per_second"]
                      * distributed["stepping_seconds"])
    compute = processes * (record["stepping_seconds"] - record["communication_seconds_mean"])
    kappa = max(0.0, (compute / (t_c * particle_steps) - 1.0) / record["ghost_fraction"])
    measured = {
        "t_c": t_c,
        "kappa": kappa,
        "band": args.band,
        "exchanges": exchanges,
        "reductions": record["mpi_calls_per_step"] - exchanges,
        # bytes per ghost in one exchange: the record's bytes a step / ghosts / exchanges a step
        "bytes_per_ghost_exchange": record["bytes_sent_per_step"] / ghost_total / exchanges,
    }
    total = args.particles
    lines = [
        f"# Projected scaling of the 3D case {single['case']} to {total:.0e} particles",
        "",
        "    " + " ".join(["/usr/bin/python3 tools/bench/scaling_projection.py",
                          "--single", args.single, "--distributed", args.distributed,
                          "--band", str(args.band), "--particles", f"{total:g}"]),
        "",
        "Measured here (inputs):",
        "",
        f"- compute: t_c = {t_c * 1e6:.3f} us per particle-step and core "
        f"({single['stepping_particle_steps_per_second']:.3g} particle-steps/s on 1 process x "
        f"{single['threads']} threads, {sum(single['particles'].values())} particles, "
        f"{single['steps']} steps, commit {single['build']['git_commit']});",
        f"- the work a ghost adds: kappa = {kappa:.2f} of an own particle's (the {processes} "
        f"processes computed {compute:.2f} s in all, {t_c * particle_steps:.2f} s at t_c);",
        f"- on {record['processes']} processes: ghost fraction {record['ghost_fraction']:.4f}, "
        f"{record['bytes_sent_per_step']:.4g} bytes sent a step in "
        f"{exchanges:.2f} exchanges ({measured['bytes_per_ghost_exchange']:.1f} bytes per ghost "
        f"and exchange), {measured['reductions']:.2f} reductions a step;",
        f"- ghost band {args.band} particle spacings (the reach plus a quarter of it).",
        "",
        "Assumed (see the script's docstring): InfiniBand HDR, latency "
        f"{LATENCY * 1e6:.1f} us, bandwidth {BANDWIDTH / 1e9:.0f} GB/s; near-cubic regions; "
        "the work balanced; no overlap of communication and computation; an all-to-all "
        "of the counts before each exchange costs one latency per process.",
        "",
    ]
    for title, sizes in (
            (f"Strong scaling, N = {total:.0e}", [(total, p) for p in
                                                  (1, 8, 64, 128, 256, 512, 1024)]),
            (f"Weak scaling, N / P = {total / 1024:.3g} (N = {total:.0e} at P = 1 024)",
             [(total / 1024 * p, p) for p in (1, 8, 64, 128, 256, 512, 1024)]),
            (f"Weak scaling, N / P = {total / 64:.3g} (N = {total:.0e} at P = 64)",
             [(total / 64 * p, p) for p in (1, 8, 64, 128, 256, 512, 1024)])):
        lines += [f"## {title}", "",
                  "| P | particles per process | ghosts / own | compute s/step | "
                  "communication s/step | efficiency | particle-steps/s |",
                  "|---|---|---|---|---|---|---|"]
        base_compute, _, _ = step_seconds(sizes[0][0], sizes[0][1], measured)
        for n_total, p in sizes:
            compute, communication, ratio = step_seconds(n_total, p, measured)
            seconds = compute + communication
            ideal = base_compute * (n_total / sizes[0][0]) / p
            lines.append(f"| {p} | {n_total / p:.3g} | {ratio:.3f} | {compute:.4g} | "
                         f"{communication:.3g} | {ideal / seconds:.2f} | "
                         f"{n_total / seconds:.3g} |")
        lines.append("")
    emit(lines, args.output)


if __name__ == "__main__":
    main()
