"""Reading revsph runs from Python: a run folder's snapshots (restarts stitched), each field as a
NumPy array with its unit and component names, and the energy and diagnostics tables with their
units. Installed with the project (`cmake --install`); needs numpy and h5py.

    import revsph
    run = revsph.open_run("out/dambreak-small")
    for snapshot in run.snapshots():
        velocity = snapshot.field("fluid", "velocity")
        print(snapshot.step, snapshot.time, velocity.unit, velocity.components,
              velocity.values.shape)
    energy = run.energy()
    print(energy.unit("kinetic"), energy["kinetic"][-1])

docs/python.md says more.
"""

from .run import Field, NotARunError, Run, Snapshot, Table, open_run, read_table

__all__ = ["Field", "NotARunError", "Run", "Snapshot", "Table", "open_run", "read_table"]
