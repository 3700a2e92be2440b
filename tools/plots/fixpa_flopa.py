#!/usr/bin/python3
"""Fixed-point against floating-point reversal of a dam break (paper 1, Fig. 3).

Usage: /usr/bin/python3 tools/plots/fixpa_flopa.py FIXED_VERIFY_DIR FLOAT_VERIFY_DIR
           [--out DIR] [--tag TEXT]

Both directories are `revsph verify --out` experiments of the same case and length, the second
with `--arithmetic float`. Writes fixpa_flopa{TAG}.png into --out (default
FLOAT_VERIFY_DIR/analysis):
  - the fluid particles initially, at the turning point, and after forward + reversed run in
    fixed point (FixPA) and in floating point (FloPA), coloured by the distance from the initial
    position of the same particle;
  - the deviation of the reversed run from the forward one: for each backward snapshot, taken at
    step s and so at the forward-equivalent step 2 s_rev - s, the max and RMS over the fluid
    particles of |x_backward - x_forward| against the forward snapshot of that step.
Prints the deviations at the end of the backward run (the forward-equivalent time 0), which are
also the distances from the initial state. For the fixed run the raw position integers are
compared too: every deviation must be exactly 0, and the script exits with status 1 if not.
"""

import json
import re
import sys
from pathlib import Path

import h5py

from docstring_cli import parser_from_docstring
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402

DPI = 110
FLOOR = 1e-16  # m: stands for an exact zero on the logarithmic colour scale


def snapshots(directory):
    found = {}
    for path in Path(directory).glob("step_*.h5"):
        match = re.fullmatch(r"step_(\d+)\.h5", path.name)
        if match:
            found[int(match.group(1))] = path
    return found


def read(path, raw=False):
    with h5py.File(path) as f:
        result = {"time": float(f.attrs["time"]),
                  "position": f["particles/fluid/position"][:],
                  "velocity": f["particles/fluid/velocity"][:],
                  "walls": f["particles/wall/position"][:] if "particles/wall/position" in f
                  else np.zeros((0, 2))}
        if raw:
            result["raw"] = f["state/fluid/position"][:]
    return result


class Experiment:
    def __init__(self, directory):
        self.dir = Path(directory)
        self.forward = snapshots(self.dir / "forward" / "snapshots")
        self.backward = snapshots(self.dir / "backward" / "snapshots")
        if not self.forward or not self.backward:
            sys.exit(f"{self.dir}: needs forward/snapshots and backward/snapshots "
                     "(the output of revsph verify --out)")
        summary = self.dir / "summary.json"
        self.summary = json.loads(summary.read_text()) if summary.is_file() else {}
        self.reversal_step = self.summary.get("reversal_step", min(self.backward))
        self.arithmetic = self.summary.get("arithmetic", "?")
        self.first, self.turning = min(self.forward), max(self.forward)
        self.last = max(self.backward)

    def deviations(self, raw=False):
        """Rows (time since the reversal, max, RMS, raw positions equal) per backward snapshot
        that has a forward snapshot at its forward-equivalent step."""
        rows = []
        start = read(self.backward[min(self.backward)])["time"]
        for step in sorted(self.backward):
            twin = 2 * self.reversal_step - step
            if twin not in self.forward:
                continue
            b, f = read(self.backward[step], raw), read(self.forward[twin], raw)
            distance = np.linalg.norm(b["position"] - f["position"], axis=1)
            same = bool(np.array_equal(b["raw"], f["raw"])) if raw else None
            rows.append((b["time"] - start,
                         float(distance.max()), float(np.sqrt(np.mean(distance ** 2))), same))
        return rows


def configuration(ax, state, colour, title, norm=None, walls=True):
    p = state["position"]
    size = max(0.15, 5e3 / len(p))
    if walls and len(state["walls"]):
        ax.scatter(state["walls"][:, 0], state["walls"][:, 1], s=size, c="0.55", lw=0,
                   rasterized=True)
    mapped = {} if isinstance(colour, str) else {"cmap": "viridis", "norm": norm}
    artist = ax.scatter(p[:, 0], p[:, 1], s=size, c=colour, lw=0, rasterized=True, **mapped)
    ax.set_aspect("equal")
    ax.set_title(title, fontsize=9)
    ax.set_xlabel("x (m)", fontsize=8)
    ax.tick_params(labelsize=7)
    return artist


def main(argv=None):
    parser = parser_from_docstring(__doc__)
    parser.add_argument("fixed_dir", metavar="FIXED_VERIFY_DIR")
    parser.add_argument("float_dir", metavar="FLOAT_VERIFY_DIR")
    parser.add_argument("--out", help="output directory (default FLOAT_VERIFY_DIR/analysis)")
    parser.add_argument("--tag", default="", help="appended to the PNG file name")
    args = parser.parse_args(argv)

    fixed, flo = Experiment(args.fixed_dir), Experiment(args.float_dir)
    fixed_rows = fixed.deviations(raw=True)
    float_rows = flo.deviations()
    if not fixed_rows or not float_rows:
        sys.exit("no backward snapshot has a forward snapshot at its forward-equivalent step")

    initial = read(fixed.forward[fixed.first], raw=True)
    turning = read(fixed.forward[fixed.turning])
    fixed_back = read(fixed.backward[fixed.last], raw=True)
    float_initial = read(flo.forward[flo.first])
    float_back = read(flo.backward[flo.last])
    start_gap = np.abs(initial["position"] - float_initial["position"]).max()
    if start_gap > 0:
        # Float positions are not rounded to the fixed-point grid, so they differ in the last
        # bits; a larger difference means two different cases.
        print(f"note: the two experiments start {start_gap:.3g} m apart (largest coordinate "
              "difference); displacements are measured from each run's own initial state")
    fixed_disp = np.linalg.norm(fixed_back["position"] - initial["position"], axis=1)
    float_disp = np.linalg.norm(float_back["position"] - float_initial["position"], axis=1)
    float_speed = np.linalg.norm(float_back["velocity"], axis=1)

    fig = plt.figure(figsize=(13, 7.6), layout="constrained")
    grid = fig.add_gridspec(2, 3, height_ratios=[1, 1])
    panels = [fig.add_subplot(grid[0, i]) for i in range(3)]
    lower = fig.add_subplot(grid[1, 0])
    deviation_ax = fig.add_subplot(grid[1, 1:])

    t_rev = turning["time"]
    configuration(panels[0], initial, "tab:blue", f"initial state, t = {initial['time']:g} s")
    speed = np.linalg.norm(turning["velocity"], axis=1)
    artist = configuration(lower, turning, speed,
                           f"FixPA at the turning point t = {t_rev:g} s (colour: speed)")
    fig.colorbar(artist, ax=lower, shrink=0.8, label="speed (m/s)")

    norm = LogNorm(vmin=FLOOR, vmax=max(FLOOR * 10, float(float_disp.max())))
    configuration(panels[1], fixed_back, np.maximum(fixed_disp, FLOOR), "", norm=norm)
    returned = np.array_equal(fixed_back["raw"], initial["raw"])
    panels[1].set_title(f"(a) FixPA: forward {t_rev:g} s, reversed, back {t_rev:g} s\n"
                        f"max displacement {fixed_disp.max():.3g} m (raw integers "
                        f"{'identical' if returned else 'DIFFER'})", fontsize=9)
    artist = configuration(panels[2], float_back, np.maximum(float_disp, FLOOR), "", norm=norm)
    panels[2].set_title(f"(b) FloPA: the same in floating point\n"
                        f"max displacement {float_disp.max():.3g} m, RMS "
                        f"{np.sqrt(np.mean(float_disp ** 2)):.3g} m", fontsize=9)
    fig.colorbar(artist, ax=panels[1:3], shrink=0.8,
                 label=f"|x − x(0)| (m); {FLOOR:g} stands for 0")

    ax = deviation_ax
    t, dmax, drms = (np.array([r[i] for r in float_rows]) for i in range(3))
    positive = dmax > 0
    ax.semilogy(t[positive], dmax[positive], "o-", ms=3, color="tab:red", label="FloPA: max")
    ax.semilogy(t[drms > 0], drms[drms > 0], "s-", ms=3, color="tab:orange",
                label="FloPA: RMS")
    fixed_max = max(r[1] for r in fixed_rows)
    fixed_same = all(r[3] for r in fixed_rows)
    ax.text(0.98, 0.04,
            f"FixPA: max and RMS exactly 0 at all {len(fixed_rows)} backward snapshots\n"
            f"(raw position integers {'equal' if fixed_same else 'NOT equal'} to the forward ones)"
            if fixed_max == 0 and fixed_same else
            f"FixPA: max deviation {fixed_max:.3g} m: NOT reversible",
            transform=ax.transAxes, ha="right", va="bottom", fontsize=8,
            bbox=dict(fc="white", ec="0.7"))
    ax.set_xlabel(f"time since the velocity reversal (s); the forward-equivalent time is "
                  f"{t_rev:g} s minus this")
    ax.set_ylabel("|x_reversed − x_forward| (m)")
    ax.set_title("deviation of the reversed run from the forward run at the same "
                 "forward-equivalent time", fontsize=9)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8, loc="upper left")

    for p in panels + [lower]:
        p.set_ylabel("y (m)", fontsize=8)
    case = fixed.summary.get("case", fixed.dir.name)
    fig.suptitle(f"Fig. 3: {case}, {len(initial['position'])} fluid particles, "
                 f"velocities reversed at t = {t_rev:g} s and run back", fontsize=11)
    out = Path(args.out) if args.out else flo.dir / "analysis"
    out.mkdir(parents=True, exist_ok=True)
    png = out / f"fixpa_flopa{args.tag}.png"
    fig.savefig(png, dpi=DPI)
    plt.close(fig)

    final_fixed, final_float = fixed_rows[-1], float_rows[-1]
    print(f"{fixed.dir} ({fixed.arithmetic}): deviation at the end of the backward run: "
          f"max {final_fixed[1]:.6g} m, RMS {final_fixed[2]:.6g} m; raw positions "
          f"{'identical' if fixed_same else 'DIFFER'} at all {len(fixed_rows)} snapshots")
    print(f"{flo.dir} ({flo.arithmetic}): deviation at the end of the backward run: "
          f"max {final_float[1]:.6g} m, RMS {final_float[2]:.6g} m; "
          f"returned speeds up to {float_speed.max():.6g} m/s")
    print(f"wrote {png}")
    if fixed_max != 0 or not fixed_same:
        sys.exit(1)


if __name__ == "__main__":
    main()
