#!/usr/bin/python3
"""Paper 1, Table 2 (Gresho vortex, App. A) and Fig. 7: the error norm of eq. (11) for four particle
arrangements and three kinds of filtering, beside the paper's values.

Usage: /usr/bin/python3 tools/plots/gresho_table.py [--runs DIR] [--out DIR] [--revsph BIN]
                                                     [--threads N] [--dr DR]

Eight runs of the built-in `gresho` case (Table 3 parameters, t in [0, 1]) go to
RUNS/gresho-<arrangement>-<passive|active>/; a run whose summary.json says completed is reused.
"No filter" and "passive filter" come from the same passive run (the filter there only reports
the filtered field, the flow is untouched): the maxima over t of `velocity_error` and
`filtered_velocity_error` (eq. 11 is a maximum over t in [0, 1]). "Active filter" is the maximum
of `velocity_error` of the run whose velocities the filter replaces every M = 30 steps.

Writes OUT/gresho_table.md and .csv (ours, the paper's, relative difference) and
OUT/gresho_vogel_isc.png (Fig. 7: speed at t = 0 and t = 1 for Vogel + ISC, passive run).
"""

import argparse
import csv
import json
import os
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]

ARRANGEMENTS = [
    ("square", "square", []),
    ("hexagonal", "hexagonal", ['particles[0].lattice="hexagonal"']),
    ("Vogel", "vogel", ['particles[0].lattice="vogel"']),
    ("Vogel + ISC", "vogel-isc",
     ['particles[0].lattice="vogel"', "initial_state_correction.enabled=true"]),
]
# Table 2 of the paper (percent): no filter, passive filter, active filter.
PAPER = {
    "square": (28.16, 12.20, 53.07),
    "hexagonal": (27.84, 11.77, 55.79),
    "Vogel": (29.85, 13.31, 78.06),
    "Vogel + ISC": (28.19, 11.26, 55.25),
}
COLUMNS = ("no filter", "passive filter", "active filter")


def completed(run_dir):
    summary = run_dir / "summary.json"
    if not summary.exists():
        return None
    data = json.loads(summary.read_text())
    return data if data.get("completed") else None


def ensure_run(args, name, overrides, mode):
    run_dir = Path(args.runs) / f"gresho-{name}-{mode}"
    data = completed(run_dir)
    if data is not None:
        print(f"reusing {run_dir}")
        return data
    command = [args.revsph, "run", "gresho", "--out", str(run_dir), "--force",
               "--threads", str(args.threads), "--set", f'filter.mode="{mode}"']
    if args.dr:
        command += ["--set", f"discretisation.dr={args.dr}"]
    for override in overrides:
        command += ["--set", override]
    print("$ " + " ".join(command), flush=True)
    environment = dict(os.environ, OMP_WAIT_POLICY="PASSIVE")
    subprocess.run(command, check=True, env=environment, stdout=subprocess.DEVNULL)
    data = completed(run_dir)
    if data is None:
        sys.exit(f"gresho_table: {run_dir} did not complete")
    return data


def relative_difference(ours, paper):
    return (ours - paper) / paper


def velocity_figure(run_dir, path):
    import h5py
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    snapshots = sorted((run_dir / "snapshots").glob("step_*.h5"))
    if len(snapshots) < 2:
        return
    figure, axes = plt.subplots(1, 2, figsize=(8.0, 3.7), constrained_layout=True)
    for axis, file in zip(axes, (snapshots[0], snapshots[-1])):
        with h5py.File(file, "r") as f:
            x = f["particles/fluid/position"][:]
            u = f["particles/fluid/velocity"][:]
            t = float(f.attrs["time"])
        speed = np.hypot(u[:, 0], u[:, 1])
        image = axis.scatter(x[:, 0], x[:, 1], c=speed, s=1.6, cmap="viridis", vmin=0, vmax=1.0,
                             linewidths=0)
        axis.set_aspect("equal")
        axis.set_title(f"Vogel spiral + ISC, t = {t:.2f}")
        axis.set_xlim(-0.52, 0.52)
        axis.set_ylim(-0.52, 0.52)
    figure.colorbar(image, ax=axes, label="speed |u|", shrink=0.85)
    figure.savefig(path, dpi=70)
    plt.close(figure)
    print(f"wrote {path}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--runs", default=str(REPO / "out" / "paper1"))
    parser.add_argument("--out", default=str(REPO / "docs" / "figures"))
    parser.add_argument("--revsph", default=str(REPO / "build" / "bin" / "revsph"))
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--dr", help="override dr (default: the case's Table 3 value 0.01)")
    args = parser.parse_args()
    Path(args.runs).mkdir(parents=True, exist_ok=True)
    Path(args.out).mkdir(parents=True, exist_ok=True)

    rows = []
    for label, name, overrides in ARRANGEMENTS:
        passive = ensure_run(args, name, overrides, "passive")
        active = ensure_run(args, name, overrides, "active")
        ours = (100 * passive["diagnostics"]["max_velocity_error"],
                100 * passive["diagnostics"]["max_filtered_velocity_error"],
                100 * active["diagnostics"]["max_velocity_error"])
        energy = (passive["energy"]["max_relative_error"], active["energy"]["max_relative_error"])
        rows.append((label, ours, PAPER[label], energy))

    lines = ["| arrangement | " + " | ".join(f"{c}: revsph / paper (diff)" for c in COLUMNS) +
             " | max energy error passive / active |",
             "|---|---|---|---|---|"]
    for label, ours, paper, energy in rows:
        cells = [f"{o:.2f}% / {p:.2f}% ({100 * relative_difference(o, p):+.0f}%)"
                 for o, p in zip(ours, paper)]
        lines.append(f"| {label} | " + " | ".join(cells) + f" | {energy[0]:.1e} / {energy[1]:.1e} |")
    table = "\n".join(lines)
    print(table)
    (Path(args.out) / "gresho_table.md").write_text(
        "Error norm (11) of the Gresho vortex, max over t in [0, 1] (paper 1, Table 2)\n\n" +
        table + "\n")
    with open(Path(args.out) / "gresho_table.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["arrangement", "filter", "revsph_percent", "paper_percent",
                         "relative_difference"])
        for label, ours, paper, _ in rows:
            for column, o, p in zip(COLUMNS, ours, paper):
                writer.writerow([label, column, f"{o:.4f}", f"{p:.2f}",
                                 f"{relative_difference(o, p):.4f}"])
    velocity_figure(Path(args.runs) / "gresho-vogel-isc-passive",
                    Path(args.out) / "gresho_vogel_isc.png")


if __name__ == "__main__":
    main()
