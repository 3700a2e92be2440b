#!/usr/bin/python3
"""A point file (docs/point-files.md) from one particle set of a snapshot: its positions and the
fields you name, with their units, as an HDF5 file that a [[particles]] block of shape "points"
reads. Edit the arrays (h5py, numpy) and start a new case from them:

    /usr/bin/python3 tools/points/points_from_snapshot.py out/run/snapshots/step_000001000.h5 \\
        --set fluid --fields velocity mass --out fluid.h5

The fields are the snapshot's physical views (/particles/SET/NAME, with their unit attribute):
a field the set's set-up fills may be given (revsph says which when one is not). Positions
are written exactly as the snapshot holds them, so that the new case's particles sit there.
"""

import argparse
import sys

import h5py


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("snapshot", help="a revsph snapshot (.h5)")
    parser.add_argument("--set", default="fluid", help="the particle set (default: fluid)")
    parser.add_argument("--fields", nargs="*", default=[],
                        help="fields to carry besides the positions (e.g. velocity mass)")
    parser.add_argument("--out", required=True, help="the point file to write (.h5)")
    args = parser.parse_args()
    with h5py.File(args.snapshot, "r") as snapshot:
        group = snapshot.get(f"particles/{args.set}")
        if group is None:
            sets = ", ".join(snapshot["particles"].keys())
            sys.exit(f"points_from_snapshot: {args.snapshot} has no set {args.set} ({sets})")
        with h5py.File(args.out, "w") as points:
            for name in ["position"] + args.fields:
                if name not in group:
                    fields = ", ".join(group.keys())
                    sys.exit(f"points_from_snapshot: set {args.set} has no field {name} "
                             f"({fields})")
                dataset = points.create_dataset(name, data=group[name][...])
                dataset.attrs["unit"] = group[name].attrs["unit"]
            count = len(group["position"])
    print(f"{args.out}: {count} particles of set {args.set}, position " + " ".join(args.fields))


if __name__ == "__main__":
    main()
