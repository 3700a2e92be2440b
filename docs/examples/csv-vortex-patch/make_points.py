#!/usr/bin/python3
"""The fluid of the worked example `vortex-patch.toml`: a disc of water on a square lattice with
a solid-body rotation, written as a point file (docs/point-files.md).

    /usr/bin/python3 docs/examples/csv-vortex-patch/make_points.py --out vortex_patch.csv

A disc of radius R about (x0, y0) on a square lattice of spacing dr (the case's
discretisation.dr), each particle with the velocity v = omega (-(y - y0), x - x0). Positions are
written with 17 digits, so that the case's particles sit where the file says, bit for bit.
"""

import argparse


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default="vortex_patch.csv")
    parser.add_argument("--dr", type=float, default=0.02, help="lattice spacing (m)")
    parser.add_argument("--radius", type=float, default=0.4, help="disc radius R (m)")
    parser.add_argument("--centre", type=float, nargs=2, default=[2.0, 1.5], help="x0 y0 (m)")
    parser.add_argument("--omega", type=float, default=1.0, help="angular velocity (1/s)")
    args = parser.parse_args()
    cells = int(args.radius / args.dr) + 1
    rows = ["x [m], y [m], velocity_x [m/s], velocity_y [m/s]"]
    for i in range(-cells, cells):
        for j in range(-cells, cells):
            dx, dy = (i + 0.5) * args.dr, (j + 0.5) * args.dr
            if dx * dx + dy * dy < args.radius ** 2:
                x, y = args.centre[0] + dx, args.centre[1] + dy
                rows.append(f"{x!r}, {y!r}, {-args.omega * dy!r}, {args.omega * dx!r}")
    with open(args.out, "w") as out:
        out.write("# a rotating disc of water: docs/examples/csv-vortex-patch/make_points.py\n")
        out.write("\n".join(rows) + "\n")
    print(f"{args.out}: {len(rows) - 1} particles")


if __name__ == "__main__":
    main()
