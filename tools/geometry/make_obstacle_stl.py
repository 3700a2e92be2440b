#!/usr/bin/python3
"""A closed STL surface of an obstacle, for a [[particles]] block of shape "stl"
(docs/point-files.md): an axis-aligned box, or a vertical cylinder closed by its two caps,
with outward-facing triangles, written as ASCII STL with the standard library alone.

    /usr/bin/python3 tools/geometry/make_obstacle_stl.py --box 0.6 0.075 0.0 0.7 0.175 0.15 \\
        --out obstacle.stl
    /usr/bin/python3 tools/geometry/make_obstacle_stl.py --cylinder 0.65 0.125 0.05 0.0 0.2 \\
        --segments 32 --out pillar.stl
"""

import argparse
import math


def box(x0, y0, z0, x1, y1, z1):
    """12 triangles, each counter-clockwise seen from outside."""
    c = [(x, y, z) for z in (z0, z1) for y in (y0, y1) for x in (x0, x1)]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    return [(c[a], c[b], c[d]) for a, b, _, d in quads] + \
           [(c[b], c[e], c[d]) for _, b, e, d in quads]


def cylinder(cx, cy, radius, z0, z1, segments):
    """A vertical prism of `segments` sides about (cx, cy), from z0 to z1, with both caps."""
    ring = [(cx + radius * math.cos(2 * math.pi * k / segments),
             cy + radius * math.sin(2 * math.pi * k / segments)) for k in range(segments)]
    triangles = []
    for k in range(segments):
        (xa, ya), (xb, yb) = ring[k], ring[(k + 1) % segments]
        triangles += [((xa, ya, z0), (xb, yb, z0), (xb, yb, z1)),
                      ((xa, ya, z0), (xb, yb, z1), (xa, ya, z1)),
                      ((cx, cy, z1), (xa, ya, z1), (xb, yb, z1)),
                      ((cx, cy, z0), (xb, yb, z0), (xa, ya, z0))]
    return triangles


def normal(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    length = math.sqrt(sum(x * x for x in n)) or 1.0
    return [x / length for x in n]


def write_stl(path, triangles, name="obstacle"):
    with open(path, "w") as out:
        out.write(f"solid {name}\n")
        for t in triangles:
            out.write("  facet normal {:.9g} {:.9g} {:.9g}\n    outer loop\n".format(*normal(*t)))
            for vertex in t:
                out.write("      vertex {!r} {!r} {!r}\n".format(*vertex))
            out.write("    endloop\n  endfacet\n")
        out.write(f"endsolid {name}\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    shape = parser.add_mutually_exclusive_group(required=True)
    shape.add_argument("--box", type=float, nargs=6, metavar=("X0", "Y0", "Z0", "X1", "Y1", "Z1"))
    shape.add_argument("--cylinder", type=float, nargs=5,
                       metavar=("CX", "CY", "RADIUS", "Z0", "Z1"))
    parser.add_argument("--segments", type=int, default=32, help="a cylinder's sides")
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    triangles = box(*args.box) if args.box else cylinder(*args.cylinder, args.segments)
    write_stl(args.out, triangles)
    print(f"{args.out}: {len(triangles)} triangles")


if __name__ == "__main__":
    main()
