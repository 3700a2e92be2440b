#!/usr/bin/python3
"""The fountain's jet speed against eq. (31) over one common window, with an error bar from block
means (paper 3 sec. III.C, Fig. 8): every run of the jet series averaged over the same interval of
time, so that resolutions are compared on the same footing, and the scatter of 25 ms block means
about their mean as the uncertainty of that average.

Usage: /usr/bin/python3 tools/plots/superfluid_fountain_blocks.py [--jet CSV] [--out CSV]
           [--start T] [--end T] [--block T]

Reads the per-interval jet series that tools/plots/superfluid_fountain.py writes (--jet, default
docs/figures/superfluid_fountain_jet.csv: run, t_start, t_end, v_jet, v_ideal, cell_temperature)
and writes (--out, default docs/figures/superfluid_fountain_blocks.csv) one row per run that
covers the window [--start, --end] (default [0.2, 0.2924] s: the N = 6 run's last snapshot
interval ends at 0.29240 s), an interval counting when it starts at or after --start and its
midpoint lies before --end: the mean jet speed over the window's intervals, eq. (31) at the
cell's state averaged over the same intervals, the deficit below it and below eq. (31) at T0, s0,
rho0 (W / (T0 s0 rho0 d), the authors' v_theory), in percent; the window cut into blocks of
--block seconds (default 0.025; the last block takes what is left when it is at least half a
block long, else it joins the one before), the standard deviation of the blocks' deficits
(percentage points) and the standard error of the mean, that deviation over sqrt(blocks).

A run's power and N come from its name (fountain-nN-wW...).
"""

import csv
import re
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from docstring_cli import parser_from_docstring  # noqa: E402
from revsph_runs import REPO, write_dict_rows  # noqa: E402

# The reference state of eq. (31) at T0 (Table I), the capillary's width: as superfluid_fountain.py.
T0, S0, RHO0, D_CAPILLARY = 1.65, 335.0, 145.2, 1.55e-3


def read_series(path):
    """{run: (t_start, t_end, v_jet, v_ideal)} as arrays, in the file's order."""
    series = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            series.setdefault(row["run"], []).append(
                [float(row[k]) for k in ("t_start", "t_end", "v_jet", "v_ideal")])
    return {run: tuple(np.array(rows).T) for run, rows in series.items()}


def blocks(t_start, t_end, start, end, block):
    """Index arrays of the intervals that start at or after `start` (as superfluid_fountain.py
    averages) and whose midpoints lie before `end` (runs' snapshot grids differ by a fraction of
    an interval), cut into blocks of `block` seconds by their start time; a last block shorter
    than half a block joins the one before."""
    middle = 0.5 * (t_start + t_end)
    inside = np.flatnonzero((t_start >= start - 1e-9) & (middle <= end))
    if inside.size == 0:
        return []
    label = np.floor((t_start[inside] - t_start[inside[0]]) / block + 1e-9).astype(int)
    groups = [inside[label == k] for k in np.unique(label)]
    last = groups[-1]
    if len(groups) > 1 and t_end[last[-1]] - t_start[last[0]] < 0.5 * block:
        groups[-2:] = [np.concatenate(groups[-2:])]
    return groups


def deficit(t_start, t_end, v_jet, v_ideal, index, reference):
    """Percent below eq. (31) over the intervals `index`: 1 - (jet volume) / (eq. 31's), eq. (31)
    at the cell's state (v_ideal per interval) or, with `reference`, that constant speed."""
    dt = t_end[index] - t_start[index]
    jet = np.sum(v_jet[index] * dt)
    ideal = np.sum((v_ideal[index] if reference is None else reference) * dt)
    return 100.0 * (1.0 - jet / ideal), jet / np.sum(dt), ideal / np.sum(dt)


def summarise(run, columns, start, end, block):
    """The row of one run, or None if its series does not reach the window's end (within half
    an interval)."""
    t_start, t_end, v_jet, v_ideal = columns
    if t_end[-1] < end - 0.5 * (t_end[-1] - t_start[-1]) or t_start[0] > start:
        return None
    match = re.match(r"fountain-n(\d+)-w(\d+)", run)
    n, power = int(match.group(1)), float(match.group(2))
    reference = power / (T0 * S0 * RHO0 * D_CAPILLARY)
    groups = blocks(t_start, t_end, start, end, block)
    whole = np.concatenate(groups)
    cell, mean_jet, mean_ideal = deficit(*columns, whole, None)
    at_t0 = deficit(*columns, whole, reference)[0]
    per_block = np.array([[deficit(*columns, g, None)[0], deficit(*columns, g, reference)[0]]
                          for g in groups])
    spread = per_block.std(axis=0, ddof=1) if len(groups) > 1 else np.full(2, np.nan)
    error = spread / np.sqrt(len(groups))
    return dict(run=run, N=n, power_W_per_m=power, t_from=t_start[whole[0]], t_to=t_end[whole[-1]],
                mean_jet_speed=mean_jet, eq31_speed=mean_ideal, deficit_percent=cell,
                eq31_speed_T0=reference, deficit_T0_percent=at_t0, blocks=len(groups),
                block_std_points=spread[0], block_error_points=error[0],
                block_std_T0_points=spread[1], block_error_T0_points=error[1],
                block_deficits=" ".join(f"{d:.2f}" for d in per_block[:, 0]))


def main():
    parser = parser_from_docstring(__doc__)
    parser.add_argument("--jet", default=str(REPO / "docs" / "figures" / "superfluid_fountain_jet.csv"))
    parser.add_argument("--out", default=str(REPO / "docs" / "figures" / "superfluid_fountain_blocks.csv"))
    parser.add_argument("--start", type=float, default=0.2)
    parser.add_argument("--end", type=float, default=0.2924)
    parser.add_argument("--block", type=float, default=0.025)
    args = parser.parse_args()
    rows = [r for r in (summarise(run, columns, args.start, args.end, args.block)
                        for run, columns in read_series(args.jet).items()) if r is not None]
    write_dict_rows(args.out, rows)
    for r in rows:
        print(f"{r['run']}: {r['mean_jet_speed']:.4f} m/s over [{r['t_from']:.3f}, "
              f"{r['t_to']:.4f}] s; {r['deficit_percent']:.2f} +- {r['block_error_points']:.2f} "
              f"% below eq. (31) (cell), {r['deficit_T0_percent']:.2f} +- "
              f"{r['block_error_T0_points']:.2f} % (T0); {r['blocks']} blocks: "
              f"{r['block_deficits']}")
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
