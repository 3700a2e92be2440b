#!/usr/bin/python3
"""Merged particles in the natural-convection runs (entropic_cavity.py's cavity and
Rayleigh-Benard runs): in every snapshot of each run (and its continued segments RUN-2, ...),
the pairs of particles closer than a tenth of the lattice spacing dr. On a lattice at rest no
two particles are closer than dr; two gas particles that drift together feel no force stopping
them at the same temperature and density (the kernel's gradient vanishes at r = 0), and a pair
that has merged moves as one particle of twice the mass.

Usage: /usr/bin/python3 tools/plots/entropic_close_pairs.py [--make-runs] [--runs DIR]
           [--out DIR] [--revsph PATH] [--threads N] [--only NAME ...]

--make-runs makes the missing runs as entropic_cavity.py does (the same names and commands;
their costs are listed there). Writes into --out (default docs/figures):
  entropic_close_pairs.csv  run, step, time, gas particles, gas-gas pairs and gas-wall pairs
                            (dummy and thermal particles) closer than 0.1 dr, gas particles in
                            such pairs, the smallest gas-gas distance over dr; one row per
                            snapshot.
  entropic_close_pairs.md   the same at each run's last snapshot, with the run's mean Nusselt
                            number over its last quarter (entropic_cavity.py's, to check that a
                            rerun is the run the README cites) (also printed).
"""

import sys
from pathlib import Path

import h5py
import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, str(Path(__file__).resolve().parent))
from entropic_cavity import RUNS, nusselt_series, segments  # noqa: E402
from revsph_runs import case_of, chosen_runs_main, snapshots  # noqa: E402

CLOSE = 0.1  # a pair closer than this many dr has merged (a lattice at rest has none below 1)
WALLS = ("dummy", "thermal")  # the fixed particles in the kernel sums


def close_pairs(gas, walls, distance):
    """Counts of the pairs closer than `distance`: gas-gas, gas-wall, the gas particles in either,
    and the smallest gas-gas distance. gas (N, D), walls (M, D) positions."""
    tree = cKDTree(gas)
    pairs = tree.query_pairs(distance, output_type="ndarray")
    in_pairs = set(pairs.ravel().tolist())
    wall_pairs = 0
    if len(walls):
        near = cKDTree(walls).query_ball_tree(tree, distance)
        wall_pairs = sum(len(found) for found in near)
        in_pairs.update(i for found in near for i in found)
    nearest = tree.query(gas, k=2)[0][:, 1]
    return len(pairs), wall_pairs, len(in_pairs), float(nearest.min())


def snapshot_row(path, dr):
    with h5py.File(path) as f:
        sets = f["particles"]
        gas = sets["gas"]["position"][:]
        walls = [sets[name]["position"][:] for name in WALLS if name in sets]
        walls = np.concatenate(walls) if walls else np.empty((0, gas.shape[1]))
        step, time = int(f.attrs["step"]), float(f.attrs["time"])
    gas_pairs, wall_pairs, in_pairs, nearest = close_pairs(gas, walls, CLOSE * dr)
    return step, time, len(gas), gas_pairs, wall_pairs, in_pairs, nearest / dr


def count_runs(runs, out, report, names):
    lines = ["run,step,time,gas_particles,gas_gas_pairs,gas_wall_pairs,gas_in_pairs,"
             "nearest_gas_over_dr"]
    for name in names:
        run = runs / name
        dr = case_of(run)["discretisation"]["dr"]
        seen = set()
        row = None
        for segment in segments(run):
            for path in snapshots(segment):
                row = snapshot_row(path, dr)
                if row[0] in seen:  # a continued segment starts at its parent's last snapshot
                    continue
                seen.add(row[0])
                lines.append(f"{name},{row[0]},{row[1]:.6g},{row[2]},{row[3]},{row[4]},{row[5]},"
                             f"{row[6]:.4g}")
        mean = 0.5 * sum(nusselt_series(run)[3:])
        report.append((f"{name}: t, gas-gas and gas-wall pairs closer than {CLOSE} dr, gas "
                       "particles in them, of, nearest gas pair / dr (last snapshot); mean Nu",
                       f"t = {row[1]:.4g}: {row[3]}, {row[4]}, {row[5]} of {row[2]}, "
                       f"{row[6]:.3g}; Nu {mean:.4f}"))
    (out / "entropic_close_pairs.csv").write_text("\n".join(lines) + "\n")


def main():
    return chosen_runs_main(__doc__, "out/entropic", RUNS, lambda name: RUNS[name], count_runs,
                            "entropic_close_pairs.md")


if __name__ == "__main__":
    sys.exit(main())
