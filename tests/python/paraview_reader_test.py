"""ParaView itself opens a run of each model: its XDMF reader (pvpython) sees every snapshot time,
every particle set with its point count, and every field with the values h5py reads from the
snapshot; a 2D vector arrives as a 3-component vector (z = 0), so that glyphs and the Calculator
work on it without a Calculator of their own (issue 33).

Run by CTest only where pvpython is installed (Debian: apt-get install paraview python3-paraview);
usage: pvpython --force-offscreen-rendering paraview_reader_test.py REVSPH_BINARY
"""

import json
import os
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np
from paraview import servermanager
from paraview.simple import XDMFReader
from vtk.util.numpy_support import vtk_to_numpy

# One run of each model: (case, steps, snapshot_every).
RUNS = [("dambreak-small", 600, 200), ("twisting-column-small", 20, 10), ("box-small", 20, 10),
        ("droplet-small", 20, 10), ("rayleigh-taylor-small", 20, 10)]


def check_run(revsph, work, case, steps, every):
    out = os.path.join(work, case)
    subprocess.run([revsph, "run", case, "--steps", str(steps), "--threads", "1", "--set",
                    f"output.snapshot_every={every}", "--out", out],
                   check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    reader = XDMFReader(FileNames=[os.path.join(out, "run.xdmf")])
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues)
    expected = [step * summary["dt"] for step in range(0, steps + 1, every)]
    assert len(times) == len(expected), (case, times)
    assert all(abs(a - b) < 1e-12 for a, b in zip(times, expected)), (case, times)
    reader.UpdatePipeline(times[-1])
    data = servermanager.Fetch(reader)
    counts, compared, padded = {}, 0, 0
    last = os.path.join(out, "snapshots", f"step_{steps:09d}.h5")
    with h5py.File(last, "r") as snapshot:
        dimension = int(snapshot.attrs["dimension"])
        for b in range(data.GetNumberOfBlocks()):
            block = data.GetBlock(b)
            name = data.GetMetaData(b).Get(data.NAME()).split("[")[0]
            counts[name] = block.GetNumberOfPoints()
            fields = snapshot[f"particles/{name}"]
            point_data = block.GetPointData()
            for i in range(point_data.GetNumberOfArrays()):
                array = point_data.GetArray(i)
                stored = fields[array.GetName()][...]
                seen = vtk_to_numpy(array)
                if stored.ndim == 2 and dimension == 2 and stored.shape[1] == 2:
                    assert seen.shape == (len(stored), 3), (case, name, array.GetName(),
                                                            seen.shape)
                    assert np.all(seen[:, 2] == 0.0), (case, name, array.GetName())
                    seen = seen[:, :2]
                    padded += 1
                assert np.array_equal(seen.reshape(stored.shape), stored), \
                    (case, name, array.GetName())
                compared += 1
    non_empty = {n: c for n, c in summary["particles"].items() if c > 0}
    assert counts == non_empty, (case, counts, summary["particles"])
    if dimension == 2:
        assert padded > 0, (case, "no 2D vector field seen")
    print(f"paraview reader: {case}: {len(times)} times, counts {counts}, {compared} fields "
          f"identical to the file ({padded} 2D vectors as 3 components)")


def main():
    revsph = sys.argv[1]
    work = tempfile.mkdtemp(prefix="revsph-paraview-test-")
    try:
        for case, steps, every in RUNS:
            check_run(revsph, work, case, steps, every)
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
