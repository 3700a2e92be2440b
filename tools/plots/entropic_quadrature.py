#!/usr/bin/python3
"""Paper 4's quadrature test (Pavelka, Klika, Kincl 2024, §3.4, Fig. 2): relative error of
sum_a V_a f(x_a) against the exact integral over [0,1]^2, against N, for the mass/entropic volume
(M/E) and the implicit one (IMP), one panel per function of eq. (30).

Usage: /usr/bin/python3 tools/plots/entropic_quadrature.py IN.csv OUT.png

IN.csv is written by build/bin/revsph_entropic_quadrature. The dotted line in each panel is the
lattice's bias |sum_a V_a - 1| of the mass volume (the quadrature of f = 1), the value every error
tends to at fixed h / dr.
"""

import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

STYLE = {
    "mass": ("tab:blue", "o", "M/E (mass, entropic)"),
    "implicit": ("tab:orange", "s", "IMP (implicit)"),
}


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def series(rows, volume, function, name):
    chosen = [r for r in rows if r["volume"] == volume and r["function"] == function]
    chosen.sort(key=lambda r: int(r["N"]))
    return np.array([int(r["N"]) for r in chosen]), np.array([float(r[name]) for r in chosen])


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    rows = read_rows(argv[1])
    functions = sorted({r["function"] for r in rows})
    fig, axes = plt.subplots(1, len(functions), figsize=(4.2 * len(functions), 3.6), sharey=True)
    for ax, function in zip(np.atleast_1d(axes), functions):
        for volume, (colour, marker, label) in STYLE.items():
            n, error = series(rows, volume, function, "relative_error")
            ax.loglog(n, error, marker=marker, color=colour, label=label)
        n, volume_sum = series(rows, "mass", function, "volume_sum")
        ax.loglog(n, np.abs(volume_sum - 1.0), ":", color="0.4", label=r"bias $|\sum V - 1|$")
        ax.set_title(function)
        ax.set_xlabel("N")
        ax.grid(True, which="both", alpha=0.3)
    np.atleast_1d(axes)[0].set_ylabel(r"relative error $\epsilon$")
    np.atleast_1d(axes)[0].legend(fontsize=8)
    fig.suptitle("Quadrature with particle volumes (paper 4, Fig. 2)", fontsize=10)
    fig.tight_layout()
    fig.savefig(argv[2], dpi=150)


if __name__ == "__main__":
    main(sys.argv)
