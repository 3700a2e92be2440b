#!/usr/bin/python3
"""Paper 4's discontinuity test (Pavelka, Klika, Kincl 2024, §3.5, Figs. 3-7): density rho and
entropy density s across a jump in particle spacing (equal masses, S = the spacing in the left
part), one panel per particle volume, the particles within 5 h of the jump; one row per reading of
the right part's entropies S (the paper does not give them): its own spacing (s about 1
everywhere, the paper's stated aim), the left part's value continued, zero; and a fourth that
sets both parts alike: S = the mass volume m / sum m W (s = 1 read through it).

Usage: /usr/bin/python3 tools/plots/entropic_discontinuity.py IN.csv OUT.png

IN.csv is written by build/bin/revsph_entropic_discontinuity. Beside OUT.png, OUT.md: the
smallest and largest rho and s of each volume and reading in the panels (also printed), the
numbers models/entropic/README.md compares with the paper's Figs. 3-7.
"""

import csv
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

VOLUMES = ["mass", "entropic", "direct", "implicit", "mixed"]
READINGS = {"spacing": "right S = its spacing", "left_value": "right S = the left's 1e-4",
            "zero": "right S = 0", "mass_volume": "S = m / sum m W"}
FIGURE = {"mass": 3, "entropic": 4, "implicit": 5, "mixed": 6, "direct": 7}


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with open(sys.argv[1], newline="") as f:
        rows = list(csv.DictReader(f))
    fig, grid = plt.subplots(len(READINGS), len(VOLUMES), figsize=(17, 3.4 * len(READINGS)),
                             squeeze=False)
    for axes, (reading, label) in zip(grid, READINGS.items()):
        for ax, volume in zip(axes, VOLUMES):
            picked = [r for r in rows if r["volume"] == volume and r["right_entropy"] == reading]
            x = np.array([float(r["x"]) for r in picked])
            rho = np.array([float(r["density"]) for r in picked])
            s = np.array([float(r["entropy_density"]) for r in picked])
            shown = np.isfinite(rho) & np.isfinite(s)
            ax.plot(x[shown], rho[shown], ".-", color="tab:blue", markersize=3, linewidth=0.8,
                    label="density")
            ax.plot(x[shown], s[shown], ".-", color="tab:red", markersize=3, linewidth=0.8,
                    label="entropy density")
            ax.axvline(0.5, color="0.6", linestyle=":", linewidth=0.8)
            ax.set_title(f"{volume} volume (Fig. {FIGURE[volume]}), {label}", fontsize=9)
            ax.set_xlabel("x")
            ax.grid(True, alpha=0.3)
        axes[0].set_ylabel("rho, s")
    grid[0, 0].legend(fontsize=8)
    fig.suptitle("Discontinuity test (paper 4, §3.5): spacing 1e-4 | 0.5e-4, equal masses, "
                 "S = the left spacing on the left, h = 1e-3; rows: the right part's S "
                 "(last row: both parts')")
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=120)
    write_ranges(rows, Path(sys.argv[2]).with_suffix(".md"))


def extent(values):
    """'min | max' of the finite values, and how many are not finite (a zero volume's rho)."""
    finite = values[np.isfinite(values)]
    text = f"{finite.min():.4g} | {finite.max():.4g}"
    return text if len(finite) == len(values) else text + f" ({len(values) - len(finite)} not finite)"


def write_ranges(rows, path):
    lines = ["| reading of S | volume (figure) | rho min | rho max | s min | s max |",
             "|---|---|---|---|---|---|"]
    for reading, label in READINGS.items():
        for volume in VOLUMES:
            picked = [r for r in rows if r["volume"] == volume and r["right_entropy"] == reading]
            rho = np.array([float(r["density"]) for r in picked])
            s = np.array([float(r["entropy_density"]) for r in picked])
            lines.append(f"| {label} | {volume} (Fig. {FIGURE[volume]}) | {extent(rho)} | "
                         f"{extent(s)} |")
    text = "\n".join(lines) + "\n"
    path.write_text(text)
    print(text, end="")


if __name__ == "__main__":
    main()
