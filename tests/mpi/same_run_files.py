"""Two run folders hold the same results (the distributed lane, docs/design/distributed.md): byte
for byte the same energy.csv, diagnostics.csv (if any) and run.xdmf, and snapshot files with the
same datasets, bit for bit, and the same attributes (but the build's git commit).

usage: /usr/bin/python3 same_run_files.py ONE_PROCESS_RUN OTHER_RUN
Prints what differs and exits 1, or prints a summary and exits 0."""

import sys
from pathlib import Path

import h5py


def objects(f):
    names = []
    f.visit(names.append)
    return set(names)


def same_snapshot(a_path, b_path):
    differences = []
    with h5py.File(a_path) as a, h5py.File(b_path) as b:
        if objects(a) != objects(b):
            return [f"{b_path.name}: objects {sorted(objects(a) ^ objects(b))}"]
        for name in sorted(objects(a)):
            x, y = a[name], b[name]
            if isinstance(x, h5py.Dataset):
                u, v = x[()], y[()]
                if u.dtype != v.dtype or u.shape != v.shape or u.tobytes() != v.tobytes():
                    differences.append(f"{b_path.name}: dataset {name}")
            for key in x.attrs:
                if str(x.attrs[key]) != str(y.attrs.get(key)):
                    differences.append(f"{b_path.name}: {name} attribute {key}")
        for key in a.attrs:
            if key != "git_commit" and str(a.attrs[key]) != str(b.attrs.get(key)):
                differences.append(f"{b_path.name}: attribute {key}")
    return differences


def main():
    one, other = Path(sys.argv[1]), Path(sys.argv[2])
    differences = []
    for name in ("energy.csv", "diagnostics.csv", "run.xdmf"):
        if (one / name).exists() or (other / name).exists():
            if not (other / name).exists() or (one / name).read_bytes() != (other / name).read_bytes():
                differences.append(name)
    snapshots = sorted(p.name for p in (one / "snapshots").glob("step_*.h5"))
    if snapshots != sorted(p.name for p in (other / "snapshots").glob("step_*.h5")):
        differences.append("the snapshot files")
    else:
        for name in snapshots:
            differences += same_snapshot(one / "snapshots" / name, other / "snapshots" / name)
    if not snapshots:
        differences.append("no snapshots")
    for line in differences:
        print(f"differs: {line}")
    if differences:
        return 1
    print(f"the same: energy.csv, run.xdmf and {len(snapshots)} snapshots")
    return 0


if __name__ == "__main__":
    sys.exit(main())
