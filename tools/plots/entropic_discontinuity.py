#!/usr/bin/python3
"""Paper 4's discontinuity test (Pavelka, Klika, Kincl 2024, §3.5, Figs. 3-7): density rho and
entropy density s across a jump in particle spacing (equal masses, S = local spacing), one panel
per particle volume, the particles within 5 h of the jump.

Usage: /usr/bin/python3 tools/plots/entropic_discontinuity.py IN.csv OUT.png

IN.csv is written by build/bin/revsph_entropic_discontinuity.
"""

import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

VOLUMES = ["mass", "entropic", "direct", "implicit", "mixed"]
FIGURE = {"mass": 3, "entropic": 4, "implicit": 5, "mixed": 6, "direct": 7}


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with open(sys.argv[1], newline="") as f:
        rows = list(csv.DictReader(f))
    fig, axes = plt.subplots(1, len(VOLUMES), figsize=(17, 3.6), sharey=True)
    for ax, volume in zip(axes, VOLUMES):
        picked = [r for r in rows if r["volume"] == volume]
        x = np.array([float(r["x"]) for r in picked])
        rho = np.array([float(r["density"]) for r in picked])
        s = np.array([float(r["entropy_density"]) for r in picked])
        ax.plot(x, rho, ".-", color="tab:blue", markersize=3, linewidth=0.8, label="density")
        ax.plot(x, s, ".-", color="tab:red", markersize=3, linewidth=0.8, label="entropy density")
        ax.axvline(0.5, color="0.6", linestyle=":", linewidth=0.8)
        ax.set_title(f"{volume} volume (paper's Fig. {FIGURE[volume]})")
        ax.set_xlabel("x")
        ax.grid(True, alpha=0.3)
    axes[0].set_ylabel("rho, s")
    axes[0].legend(fontsize=8)
    fig.suptitle("Discontinuity test (paper 4, §3.5): spacing 1e-4 | 0.5e-4, equal masses, "
                 "S = spacing, h = 1e-3")
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=120)


if __name__ == "__main__":
    main()
