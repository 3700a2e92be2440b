#!/usr/bin/python3
"""The fluid of the worked example `shear-layer.toml`: the doubly periodic shear layer of Bell,
Colella & Glaz (1989, J. Comput. Phys. 85, 257, §5) on a square lattice, written as a point file
(docs/point-files.md).

    /usr/bin/python3 docs/examples/periodic-shear-layer/make_points.py --out shear_layer.csv

On the unit square, u = U tanh((y - 1/4) / delta) for y <= 1/2 and U tanh((3/4 - y) / delta)
above, v = epsilon U sin(2 pi x): two layers of opposite shear whose perturbation rolls each up
into a vortex. Positions are written with 17 digits, so that the case's particles sit where the
file says, bit for bit.
"""

import argparse
import math


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default="shear_layer.csv")
    parser.add_argument("--cells", type=int, default=40, help="particles per side")
    parser.add_argument("--speed", type=float, default=1.0, help="U (m/s)")
    parser.add_argument("--thickness", type=float, default=1.0 / 30.0, help="delta (m)")
    parser.add_argument("--perturbation", type=float, default=0.05, help="epsilon")
    args = parser.parse_args()
    dr = 1.0 / args.cells
    rows = ["x [m], y [m], velocity_x [m/s], velocity_y [m/s]"]
    for j in range(args.cells):
        for i in range(args.cells):
            x, y = (i + 0.5) * dr, (j + 0.5) * dr
            layer = (y - 0.25) if y <= 0.5 else (0.75 - y)
            u = args.speed * math.tanh(layer / args.thickness)
            v = args.perturbation * args.speed * math.sin(2.0 * math.pi * x)
            rows.append(f"{x!r}, {y!r}, {u!r}, {v!r}")
    with open(args.out, "w") as out:
        out.write("# a doubly periodic shear layer: docs/examples/periodic-shear-layer/make_points.py\n")
        out.write("\n".join(rows) + "\n")
    print(f"{args.out}: {len(rows) - 1} particles")


if __name__ == "__main__":
    main()
