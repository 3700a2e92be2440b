#!/usr/bin/python3
"""Error bars of the natural-convection Nusselt numbers (models/entropic/README.md, "Paper against
revsph"), from the series entropic_cavity.py writes (entropic_cavity.csv: run, time, Nu of the
hot wall, Nu of the cold wall, each the slope of the wall's heat over a window of 1/30 of the
run).

Usage: /usr/bin/python3 tools/plots/entropic_nusselt_error.py OUT.md CSV ...

For each run of each CSV, over the last quarter of the run (the window of the README's means):
the mean of the two walls' series, its standard error (the standard deviation of the series
over the square root of the number of independent windows in the quarter, 7.5, since the
series' windows overlap), and half the difference of the two walls' means (a steady cavity
passes the same heat through both walls; what they differ by is how far from steady, or from
conserving the heat, the run is). The error bar is the larger of the two. These means are of
the windowed series and may differ in the last digit from entropic_cavity.py's, which takes the
heats at the quarter's two ends.
"""

import csv
import sys
from collections import defaultdict

import numpy as np

INDEPENDENT_WINDOWS = 30 / 4  # the series' windows are 1/30 of the run; the quarter holds 7.5


def error_rows(path):
    series = defaultdict(list)
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            series[row["run"]].append((float(row["time"]), float(row["nusselt_hot"]),
                                       float(row["nusselt_cold"])))
    for run, values in series.items():
        t, hot, cold = (np.array(column) for column in zip(*values))
        last = t >= 0.75 * t[-1]
        mean = 0.5 * (hot[last] + cold[last])
        standard_error = float(np.std(mean) / np.sqrt(INDEPENDENT_WINDOWS))
        walls = 0.5 * abs(float(np.mean(hot[last]) - np.mean(cold[last])))
        yield run, float(np.mean(mean)), standard_error, walls, max(standard_error, walls)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    lines = ["| source | run | mean Nu, last quarter | standard error | half the walls' "
             "difference | error bar |", "|---|---|---|---|---|---|"]
    for path in sys.argv[2:]:
        for run, mean, standard_error, walls, bar in error_rows(path):
            lines.append(f"| {path} | {run} | {mean:.4f} | {standard_error:.4f} | {walls:.4f} "
                         f"| {bar:.4f} ({bar / mean:.1%}) |")
    text = "\n".join(lines) + "\n"
    with open(sys.argv[1], "w") as f:
        f.write(text)
    print(text, end="")


if __name__ == "__main__":
    main()
