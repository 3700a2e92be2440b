#!/usr/bin/python3
"""Figures of `revsph entropy` (paper 1, Fig. 6): entropy.png and histogram.png.

Usage: /usr/bin/python3 tools/plots/entropy.py OUT_DIR

OUT_DIR holds entropy.csv and histograms.csv written by `revsph entropy`; the PNGs go next to
them. entropy.png: the reduced Boltzmann entropy S(t) of every snapshot with the equilibrium
entropies S_eq(theta_fit at the turning point) (eq. 20) and S_eq(E(t)) (eq. 21) (Fig. 6 right),
and, for a verify experiment, S against the forward-equivalent time, where the backward half
retraces the forward one. histogram.png: the speed histogram at the turning point (the last
snapshot of a plain run) against the fitted Maxwell-Boltzmann density (Fig. 6 left).
"""

import csv
import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

FORWARD = "tab:blue"
BACKWARD = "tab:orange"
EQUILIBRIUM = "0.35"


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def column(rows, name):
    return np.array([float(r[name]) for r in rows])


def finite(x, y):
    """Drop points that are not finite: S_eq(E) is -inf while every particle is at rest."""
    keep = np.isfinite(x) & np.isfinite(y)
    return x[keep], y[keep]


def maxwell_boltzmann(v, theta, dimension):
    """Eq. (19) with theta = kT/m, and its 3D analogue."""
    if dimension == 2:
        return v / theta * np.exp(-v * v / (2 * theta))
    return 4 * math.pi * (2 * math.pi * theta) ** -1.5 * v * v * np.exp(-v * v / (2 * theta))


def entropy_figure(rows, out):
    phases = [p for p in ("run", "forward", "backward") if any(r["phase"] == p for r in rows)]
    reversal = "backward" in phases
    by_phase = {p: [r for r in rows if r["phase"] == p] for p in phases}
    turning = by_phase["forward"][-1] if reversal else rows[-1]
    theta_turning = float(turning["theta_fit"])
    s_eq_turning = float(turning["S_eq_theta"])

    fig, axes = plt.subplots(1, 2 if reversal else 1, figsize=(11 if reversal else 6.5, 4.2),
                             squeeze=False)
    ax = axes[0][0]
    colours = {"run": FORWARD, "forward": FORWARD, "backward": BACKWARD}
    for phase in phases:
        part = by_phase[phase]
        t = column(part, "time")
        ax.plot(*finite(t, column(part, "S_reduced")), "o-", ms=3, color=colours[phase],
                label=f"S (histogram), {phase}")
    t_all = column(rows, "time")
    ax.plot(*finite(t_all, column(rows, "S_eq_energy")), "--", color=EQUILIBRIUM, lw=1.2,
            label="S_eq(E(t)), eq. (21)")
    if math.isfinite(s_eq_turning):
        ax.axhline(s_eq_turning, color="tab:green", ls=":", lw=1.5,
                   label=f"S_eq(θ_fit = {theta_turning:.3g} m²/s²), eq. (20)")
    if reversal:
        ax.axvline(float(turning["time"]), color="0.6", lw=0.8)
        ax.annotate("velocities reversed", (float(turning["time"]), 0.02),
                    xycoords=("data", "axes fraction"), ha="center", fontsize=8, color="0.4",
                    bbox=dict(fc="white", ec="none", pad=1))
    ax.set_xlabel("time t (s)")
    ax.set_ylabel("reduced Boltzmann entropy S")
    ax.set_title("Boltzmann entropy of the particle speeds")
    ax.legend(fontsize=8, loc="lower right" if reversal else "best")
    ax.grid(alpha=0.3)

    if reversal:
        ax = axes[0][1]
        forward, backward = by_phase["forward"], by_phase["backward"]
        ax.plot(*finite(column(forward, "forward_equivalent_time"),
                        column(forward, "S_reduced")),
                "-", color=FORWARD, lw=2, label="forward")
        ax.plot(*finite(column(backward, "forward_equivalent_time"),
                        column(backward, "S_reduced")),
                "x", color=BACKWARD, ms=6, label="backward (reversed velocities)")
        ax.set_xlabel("forward-equivalent time  t_rev − (t − t_rev) for the backward half (s)")
        ax.set_ylabel("S")
        ax.set_title("the backward half retraces the forward one")
        ax.legend(fontsize=8, loc="lower right")
        ax.grid(alpha=0.3)

    fig.tight_layout()
    fig.savefig(out / "entropy.png", dpi=100)
    plt.close(fig)


def histogram_figure(rows, out):
    labels = {r["snapshot"] for r in rows}
    label = "turning_point" if "turning_point" in labels else "final"
    part = [r for r in rows if r["snapshot"] == label]
    low, high = column(part, "v_low"), column(part, "v_high")
    density = column(part, "density")
    theta = float(part[0]["theta_fit"])
    dimension = int(part[0]["dimension"])
    time = float(part[0]["time"])

    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    ax.stairs(density, np.append(low, high[-1]), fill=True, color=FORWARD, alpha=0.6,
              label=f"histogram, {len(part)} bins")
    if math.isfinite(theta) and theta > 0:
        v = np.linspace(0.0, high[-1], 400)
        ax.plot(v, maxwell_boltzmann(v, theta, dimension), color="tab:orange", lw=2,
                label=f"Maxwell–Boltzmann, θ_fit = {theta:.3g} m²/s²")
    where = "at the turning point" if label == "turning_point" else "of the last snapshot"
    ax.set_title(f"speed distribution {where}, t = {time:g} s ({dimension}D)")
    ax.set_xlabel("speed v (m/s)")
    ax.set_ylabel("probability density f(v) (s/m)")
    ax.set_xlim(0.0, high[-1])
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out / "histogram.png", dpi=100)
    plt.close(fig)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = Path(sys.argv[1])
    entropy_figure(read_rows(out / "entropy.csv"), out)
    histogram_figure(read_rows(out / "histograms.csv"), out)
    print(f"wrote {out / 'entropy.png'}, {out / 'histogram.png'}")


if __name__ == "__main__":
    main()
