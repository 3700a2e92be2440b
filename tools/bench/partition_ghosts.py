"""How Zoltan's two partitions (recursive coordinate bisection, Hilbert curve) split real particle
arrangements among MPI processes: the largest share against the mean, the ghost fraction (ghosts
received over all processes / particles) and the bytes a step sends for them, at about 10^5, 10^6
and 4 10^6 particles of the 2D dam break and for the 3D twisting column (docs/design/
distributed.md, piece 6; issue 32's acceptance).

Usage: /usr/bin/python3 tools/bench/partition_ghosts.py [--revsph build/bin/revsph]
           [--tool build-mpi/bin/partition_ghosts] [--processes 2 4 8] [--out FILE.md]

Each arrangement is a case's initial state (`revsph run CASE --steps 1`, every particle set:
fluid, walls, dummies), its positions written as raw doubles and read by the MPI tool
tools/bench/partition/partition_ghosts.cpp under `mpiexec -n P --oversubscribe`. The reach is the
kernel's support radius, and the same with a 20 % skin (ghosts chosen once for several passes).
Bytes per step assume the exchange wcsph needs: after each drift a ghost's position, and after
the density pass its density: (D + 1) 8 bytes per ghost and step, twice per step for a
kick-drift-kick palindrome with two drifts.
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import h5py
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "plots"))
from revsph_runs import REPO, case_of, snapshots  # noqa: E402

DAMBREAK_DR = 0.005 * np.sqrt(80000.0 / np.array([1e5, 1e6, 4e6]))
WORKLOADS = [(f"dambreak, {n:.0e} fluid particles", "dambreak", dr)
             for n, dr in zip([1e5, 1e6, 4e6], DAMBREAK_DR)]
# The twisting column's resolution is its lattice spacing (and dr with it): the case's, the
# paper's (dr = 0.0496 m) and half of that, written as edited copies of the case file.
TWISTING = REPO / "models" / "shtc" / "cases" / "twisting-column.toml"
WORKLOADS += [("twisting column (the case)", TWISTING, 1),
              ("twisting column at the paper's dr", TWISTING, 2),
              ("twisting column at half the paper's dr", TWISTING, 4)]


def support_radius(case):
    d = case["discretisation"]
    if "support_radius_over_dr" in d:
        return d["support_radius_over_dr"] * d["dr"]
    return 2.0 * d["smoothing_length_over_dr"] * d["dr"]  # shtc: support 2 h


def arrangement(revsph, case, refinement, directory):
    """refinement: dr for a built-in case name; the lattice's refinement factor for a file."""
    out = Path(directory) / "run"
    command = [revsph, "run", str(case), "--steps", "1", "--out", str(out), "--force",
               "--set", "output.snapshot_every=1000000"]
    if isinstance(case, Path):
        text = case.read_text()
        text = text.replace("spacing = 0.125", f"spacing = {0.125 / refinement!r}")
        text = text.replace("dr = 0.099213", f"dr = {0.099213 / refinement!r}")
        edited = Path(directory) / case.name
        edited.write_text(text)
        command[2] = str(edited)
    elif refinement is not None:
        command += ["--set", f"discretisation.dr={refinement!r}"]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    first = snapshots(out)[0]
    with h5py.File(first) as f:
        dimension = int(f.attrs["dimension"])
        positions = np.concatenate([f[f"particles/{s}/position"][...] for s in f["particles"]
                                    if "position" in f[f"particles/{s}"]])
    path = Path(directory) / "positions.bin"
    np.ascontiguousarray(positions, dtype="<f8").tofile(path)
    return path, dimension, support_radius(case_of(out)), len(positions)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--revsph", default=str(REPO / "build" / "bin" / "revsph"))
    parser.add_argument("--tool", default=str(REPO / "build-mpi" / "bin" / "partition_ghosts"))
    parser.add_argument("--processes", type=int, nargs="+", default=[2, 4, 8])
    parser.add_argument("--only", type=int, nargs="+", help="workload numbers (0-based)")
    parser.add_argument("--out", default=None, help="markdown record to write")
    args = parser.parse_args()
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMP_NUM_THREADS="1")
    rows = []
    for number, (label, case, dr) in enumerate(WORKLOADS):
        if args.only is not None and number not in args.only:
            continue
        with tempfile.TemporaryDirectory() as directory:
            path, dimension, support, count = arrangement(args.revsph, case, dr, directory)
            for skin in (1.0, 1.2):
                for processes in args.processes:
                    result = subprocess.run(
                        ["mpiexec", "-n", str(processes), "--oversubscribe", args.tool, str(path),
                         str(dimension), repr(support * skin)],
                        check=True, capture_output=True, text=True, env=env)
                    for line in result.stdout.splitlines():
                        record = json.loads(line)
                        bytes_per_step = 2 * record["ghosts"] * (dimension + 1) * 8
                        rows.append((label, count, skin, record, bytes_per_step))
                        print(f"{label}: {count} particles, reach {skin:.1f} support, "
                              f"P = {processes}, {record['method']}: largest share "
                              f"{record['largest_share_over_mean']:.3f} of the mean, ghost "
                              f"fraction {record['ghost_fraction']:.4f} (largest ghosts/owned "
                              f"{record['largest_ghosts_over_owned']:.4f}), "
                              f"{bytes_per_step / 1e6:.3f} MB/step, balance "
                              f"{record['balance_seconds']:.3f} s", flush=True)
    if args.out:
        lines = ["| arrangement | particles | reach (support) | P | method | largest share / mean "
                 "| ghost fraction | largest ghosts / owned | MB per step | balance (s) |",
                 "|---|---|---|---|---|---|---|---|---|---|"]
        for label, count, skin, r, b in rows:
            lines.append(f"| {label} | {count} | {skin:.1f} | {r['processes']} | {r['method']} | "
                         f"{r['largest_share_over_mean']:.3f} | {r['ghost_fraction']:.4f} | "
                         f"{r['largest_ghosts_over_owned']:.4f} | {b / 1e6:.3f} | "
                         f"{r['balance_seconds']:.3f} |")
        Path(args.out).write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
