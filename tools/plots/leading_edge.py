#!/usr/bin/python3
"""Surge-front position of a dam break against experiments (paper 1, Fig. 4).

Usage: /usr/bin/python3 tools/plots/leading_edge.py RUN_DIR [--out DIR] [--tag TEXT]
           [--length L] [--gravity G] [--refdata DIR]

RUN_DIR is the output of `revsph verify --out` (its forward/snapshots are used; the backward
half retraces them) or of `revsph run` (snapshots/). Writes leading_edge{TAG}.png and
leading_edge{TAG}.csv (T, X of every snapshot) into --out (default RUN_DIR/analysis) and prints
the RMS difference from each reference data set.

Scaling as in the paper: X = x_le / L against T = t sqrt(g / L), L the initial column width and
g gravity, both read from the case text stored in the snapshots (with their --set overrides);
--length and --gravity replace them (defaults 1.0 m and 9.8 m/s^2 if the case text cannot be
read). The reference files give t sqrt(2 g / L) as their primary time column; it is divided by
sqrt(2) here.

Leading edge. A particle stands for the lattice cell of width dr around it, so the fluid edge is
half a spacing beyond the outermost particle centre; that makes X = 1 at t = 0 as in the
experiments. Two variants are computed:
  raw:    x_le = max(x) + dr/2 over all fluid particles;
  robust: (plotted and scored) sort the fluid particles by x and, going outwards from the wall,
          stop at the first gap wider than the kernel support radius h: x_le = the last x before
          that gap + dr/2. A particle farther than h ahead of all the others (in x) does not
          interact with the bulk through the SPH sums at all; it is a droplet in ballistic
          flight, not the front of the surge that an experiment would film. Gaps smaller than h
          are kept, so a thin but connected tongue of fluid still counts.
The two agree until spray leaves the tip; the printed numbers give both.

RMS: simulation X linearly interpolated in T at every reference point with T <= 2 that lies in
the simulated time range; the number of points used is printed with it. The experiments' release
is not instantaneous; no time shift is applied.
"""

import math
import sys
import tomllib
from pathlib import Path

import h5py

from docstring_cli import parser_from_docstring
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

DPI = 110
T_MAX_SCORED = 2.0
REFDATA = Path("/work/shared/refdata")
REFERENCES = (
    ("dambreak_front_martin_moyce1952.csv", "Martin & Moyce 1952 (exp.)", "s", "tab:red"),
    ("dambreak_front_koshizuka_oka1996.csv", "Koshizuka & Oka 1996", "^", "tab:green"),
)


def text_attr(value):
    return value.decode("utf-8") if isinstance(value, bytes) else str(value)


def snapshot_files(run_dir):
    run_dir = Path(run_dir)
    for sub in ("forward/snapshots", "snapshots"):
        files = sorted((run_dir / sub).glob("step_*.h5"))
        if files:
            return files
    sys.exit(f"{run_dir}: no forward/snapshots/step_*.h5 or snapshots/step_*.h5")


def apply_override(case, override):
    """`--set key=value` as revsph applies it: dotted keys, `name[i]` indexes an array of tables."""
    key, _, value = override.partition("=")
    parsed = tomllib.loads("v = " + value)["v"]
    node = case
    parts = key.split(".")
    for i, part in enumerate(parts):
        name, _, index = part.partition("[")
        last = i == len(parts) - 1
        if index:
            node = node.setdefault(name, [])[int(index.rstrip("]"))]
            if last:
                return
        elif last:
            node[name] = parsed
        else:
            node = node.setdefault(name, {})


def case_parameters(snapshot):
    """(L, g, dr, h) from the snapshot's case text and overrides."""
    with h5py.File(snapshot) as f:
        case = tomllib.loads(text_attr(f.attrs["case_text"]))
        for override in f.attrs.get("overrides", []):
            apply_override(case, text_attr(override))
    physics, discretisation = case.get("physics", {}), case["discretisation"]
    dr = float(discretisation["dr"])
    h = float(discretisation["support_radius_over_dr"]) * dr
    fluid = [b for b in case["particles"] if b.get("kind") == "fluid"]
    length = max(b["max"][0] for b in fluid) - min(b["min"][0] for b in fluid)
    return length, float(physics.get("gravity", 0.0)), dr, h


def fronts(x, dr, h):
    """(raw, robust) leading edge from the fluid x coordinates; see the module docstring."""
    xs = np.sort(x)
    gaps = np.flatnonzero(np.diff(xs) > h)
    robust = xs[gaps[0]] if gaps.size else xs[-1]
    return xs[-1] + dr / 2, robust + dr / 2


def read_series(files, dr, h):
    times, raw, robust = [], [], []
    for path in files:
        with h5py.File(path) as f:
            times.append(float(f.attrs["time"]))
            a, b = fronts(f["particles/fluid/position"][:, 0], dr, h)
        raw.append(a)
        robust.append(b)
    return np.array(times), np.array(raw), np.array(robust)


def read_reference(path):
    """(T = t sqrt(g/L), X) from the primary t sqrt(2g/L) column."""
    lines = [line for line in Path(path).read_text().splitlines()
             if line.strip() and not line.startswith("#")]
    header = lines[0].split(",")
    rows = np.array([[float(v) for v in line.split(",")] for line in lines[1:]])
    t = rows[:, header.index("t_sqrt_2g_over_L")] / math.sqrt(2.0)
    derived = rows[:, header.index("t_sqrt_g_over_L")]
    # The derived column is rounded to 3 decimals; a larger disagreement means a misread file.
    assert np.all(np.abs(t - derived) < 1.5e-3), path
    return t, rows[:, header.index("X")]


def rms_difference(T, X, t_ref, x_ref):
    use = (t_ref <= T_MAX_SCORED) & (t_ref >= T[0]) & (t_ref <= T[-1])
    if not use.any():
        return math.nan, 0
    d = np.interp(t_ref[use], T, X) - x_ref[use]
    return float(np.sqrt(np.mean(d * d))), int(use.sum())


def main(argv=None):
    parser = parser_from_docstring(__doc__)
    parser.add_argument("run_dir", metavar="RUN_DIR")
    parser.add_argument("--out", help="output directory (default RUN_DIR/analysis)")
    parser.add_argument("--tag", default="", help="appended to the output file names")
    parser.add_argument("--length", type=float, help="column width L (m); default from the case")
    parser.add_argument("--gravity", type=float, help="g (m/s^2); default from the case")
    parser.add_argument("--refdata", default=str(REFDATA), help=f"default {REFDATA}")
    args = parser.parse_args(argv)

    files = snapshot_files(args.run_dir)
    try:
        length, gravity, dr, h = case_parameters(files[0])
    except (KeyError, ValueError, IndexError, tomllib.TOMLDecodeError) as error:
        print(f"note: case text not usable ({error!r}); L = 1, g = 9.8, dr from the particles")
        length, gravity = 1.0, 9.8
        with h5py.File(files[0]) as f:
            dr = 2 * float(np.min(f["particles/fluid/position"][:, 0]))
        h = 3 * dr
    length = args.length or length
    gravity = args.gravity or gravity
    if not gravity > 0:
        sys.exit(f"{files[0]}: gravity is {gravity}; give --gravity")

    t, raw, robust = read_series(files, dr, h)
    T = t * math.sqrt(gravity / length)
    X_raw, X = raw / length, robust / length

    out = Path(args.out) if args.out else Path(args.run_dir) / "analysis"
    out.mkdir(parents=True, exist_ok=True)
    np.savetxt(out / f"leading_edge{args.tag}.csv", np.column_stack([t, T, X, X_raw]),
               delimiter=",", header="t,T,X_robust,X_raw", comments="", fmt="%.9g")

    fig = plt.figure(figsize=(12.5, 5.4))
    grid = fig.add_gridspec(2, 2, width_ratios=[1.1, 1])
    ax, ax2, ax3 = (fig.add_subplot(grid[:, 0]), fig.add_subplot(grid[0, 1]),
                    fig.add_subplot(grid[1, 1]))
    ax.plot(T, X, "-", color="tab:blue", lw=2, label="SYM (this run), robust front")
    ax.plot(T, X_raw, ":", color="tab:blue", lw=1, label="SYM, max x + dr/2 (raw)")
    print(f"{args.run_dir}: L = {length:g} m, g = {gravity:g} m/s^2, dr = {dr:g} m, h = {h:g} m, "
          f"{len(files)} snapshots, T up to {T[-1]:.3f}")
    for name, label, marker, colour in REFERENCES:
        t_ref, x_ref = read_reference(Path(args.refdata) / name)
        rms, n = rms_difference(T, X, t_ref, x_ref)
        rms_raw, _ = rms_difference(T, X_raw, t_ref, x_ref)
        print(f"  {label}: RMS(X_sim - X_ref) over T <= {T_MAX_SCORED:g}: {rms:.4f} "
              f"({n} points; raw front {rms_raw:.4f})")
        ax.plot(t_ref, x_ref, marker, color=colour, mfc="none", ms=7,
                label=f"{label}: RMS {rms:.3f} over {n} pts (T ≤ {T_MAX_SCORED:g})")
    ax.axvline(T_MAX_SCORED, color="0.7", lw=0.8, ls="--")
    ax.set_xlabel("T = t √(g / L)")
    ax.set_ylabel("X = x_le / L")
    ax.set_xlim(0, max(3.2, min(T[-1], 4.0)) if T[-1] > 0 else 1)
    ax.set_ylim(0.9, None)
    ax.set_title(f"Fig. 4: surge front, L = {length:g} m, dr = {dr:g} m", fontsize=10)
    ax.legend(fontsize=7.5, loc="upper left")
    ax.grid(alpha=0.3)

    # Show the scored snapshot where the two definitions differ most (else the last scored one),
    # whole and zoomed on the tip, so the choice can be judged by eye.
    scored = np.flatnonzero(T <= T_MAX_SCORED)
    scored = scored if scored.size else np.array([0])
    gap = raw[scored] - robust[scored]
    k = int(scored[np.argmax(gap)] if gap.max() > 0 else scored[-1])
    with h5py.File(files[k]) as f:
        p = f["particles/fluid/position"][:]
    ax2.scatter(p[:, 0], p[:, 1], s=max(0.2, 4e3 / len(p)), c="tab:blue", lw=0, rasterized=True)
    left, right = robust[k] - 0.12 * length, raw[k] + 0.03 * length
    window = (p[:, 0] >= left) & (p[:, 0] <= right)
    top = 1.15 * max(p[window, 1].max() if window.any() else 0.0, 4 * dr)
    ax2.add_patch(plt.Rectangle((left, 0), right - left, top, fill=False, ec="k", lw=0.8))
    ax2.set_aspect("equal")
    ax2.set_xlim(0, 4 * length)
    ax2.set_ylim(0, 1.05 * max(p[:, 1].max(), 0.5 * length))
    ax2.set_ylabel("y (m)")
    ax2.set_title(f"fluid at t = {t[k]:.3g} s (T = {T[k]:.2f}); box: zoom below", fontsize=10)
    ax3.scatter(p[window, 0], p[window, 1], s=6, c="tab:blue", lw=0, rasterized=True)
    ax3.axvline(robust[k], color="k", lw=1, label=f"robust front x = {robust[k]:.4f} m")
    ax3.axvline(raw[k], color="tab:red", lw=1, ls=":", label=f"raw front x = {raw[k]:.4f} m")
    ax3.set_xlim(left, right)
    ax3.set_ylim(0, top)
    ax3.set_xlabel("x (m)")
    ax3.set_ylabel("y (m)")
    ax3.legend(fontsize=7.5, loc="upper right")
    differ = int(np.count_nonzero(raw[scored] > robust[scored]))
    print(f"  robust front behind the raw one in {differ} of {scored.size} snapshots with "
          f"T <= {T_MAX_SCORED:g}, by up to {gap.max():.4g} m")
    fig.tight_layout()
    png = out / f"leading_edge{args.tag}.png"
    fig.savefig(png, dpi=DPI)
    plt.close(fig)
    print(f"wrote {png}, {out / f'leading_edge{args.tag}.csv'}")


if __name__ == "__main__":
    main()
