#!/usr/bin/python3
"""The order of convergence of an error against the resolution, with its standard error: the
least-squares slope of log(error) against log(1 / N) per group of a results CSV (a figure
script's), and the local slopes between neighbouring N.

Usage: /usr/bin/python3 tools/plots/convergence_slope.py CSV --group COLUMN --resolution COLUMN
           --error COLUMN [--out CSV]

Writes (--out, default: CSV with `_slopes` before its suffix) one row per value of --group: the
number of points, the N they span, the slope, its standard error (from the fit's residuals,
n - 2 degrees of freedom; none with two points) and the local slopes in order of N. Example:
`convergence_slope.py docs/figures/superfluid_cavity.csv --group Re --resolution N --error
linf_error` (Fig. 4 of paper 3).
"""

import csv
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from docstring_cli import parser_from_docstring  # noqa: E402


def slope_with_error(resolution, error):
    """(slope, standard error) of log(error) against log(1 / resolution); NaN error for two
    points."""
    x, y = -np.log(np.asarray(resolution, float)), np.log(np.asarray(error, float))
    if len(x) < 3:
        return (y[-1] - y[0]) / (x[-1] - x[0]), float("nan")
    (slope, _), covariance = np.polyfit(x, y, 1, cov=True)
    return slope, float(np.sqrt(covariance[0, 0]))


def main():
    parser = parser_from_docstring(__doc__)
    parser.add_argument("csv")
    parser.add_argument("--group", required=True)
    parser.add_argument("--resolution", required=True)
    parser.add_argument("--error", required=True)
    parser.add_argument("--out")
    args = parser.parse_args()
    source = Path(args.csv)
    out = Path(args.out or source.with_name(source.stem + "_slopes" + source.suffix))
    groups = {}
    with open(source, newline="") as f:
        for row in csv.DictReader(f):
            groups.setdefault(row[args.group], []).append(
                (float(row[args.resolution]), float(row[args.error])))
    with open(out, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow([args.group, "points", "resolutions", "slope", "slope_standard_error",
                         "local_slopes"])
        for name, points in groups.items():
            points.sort()
            n, e = zip(*points)
            slope, error = slope_with_error(n, e)
            local = [slope_with_error(n[i:i + 2], e[i:i + 2])[0] for i in range(len(n) - 1)]
            writer.writerow([name, len(n), " ".join(f"{v:g}" for v in n), f"{slope:.4g}",
                             f"{error:.3g}", " ".join(f"{v:.3g}" for v in local)])
            print(f"{args.group} {name}: slope {slope:.3f} ± {error:.3f} over N = "
                  f"{n[0]:g}-{n[-1]:g}; local {', '.join(f'{v:.2f}' for v in local)}")
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
