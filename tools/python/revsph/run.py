"""The objects of the revsph reader (see the package's docstring)."""

import csv
import json
import os
import re

import h5py
import numpy as np

_STEP_FILE = re.compile(r"^step_(\d+)\.h5$")
_HEADER_CELL = re.compile(r"^(?P<name>[^\[]*?)\s*(\[(?P<unit>[^\]]*)\])?$")


class Field:
    """One field of one particle set in one snapshot: `values` an (N,) or (N, C) array,
    `unit` its unit, `components` the names of its C components ([] for a scalar), in the
    order of the array's columns (a tensor's row-major: xx, xy, yx, yy)."""

    def __init__(self, name, values, unit, components):
        self.name, self.values, self.unit, self.components = name, values, unit, components

    def __repr__(self):
        return f"Field({self.name!r}, shape {self.values.shape}, unit {self.unit!r})"


class Snapshot:
    """A snapshot file of a run: its step, simulated time, particle sets and fields (the
    physical views of /particles, in SI units), and the exact state (/state) if wanted."""

    def __init__(self, path):
        self.path = path
        with h5py.File(path, "r") as f:
            self.step = int(f.attrs["step"])
            self.time = float(f.attrs["time"])
            self.dimension = int(f.attrs["dimension"])
            self.state_hash = _text(f.attrs["state_hash"])
            self._fields = {name: sorted(group.keys()) for name, group in f["particles"].items()}

    @property
    def sets(self):
        """The particle sets' names."""
        return sorted(self._fields)

    def fields(self, particle_set):
        """The names of a set's fields."""
        if particle_set not in self._fields:
            raise KeyError(f"{self.path}: no particle set {particle_set!r} (sets: "
                           f"{', '.join(self.sets)})")
        return list(self._fields[particle_set])

    def field(self, particle_set, name):
        """A Field: the set's physical view `name` as a NumPy array with its unit."""
        if name not in self.fields(particle_set):
            raise KeyError(f"{self.path}: set {particle_set!r} has no field {name!r} (fields: "
                           f"{', '.join(self.fields(particle_set))})")
        with h5py.File(self.path, "r") as f:
            dataset = f[f"particles/{particle_set}/{name}"]
            values = dataset[...]
            unit = _text(dataset.attrs.get("unit", ""))
            names = dataset.attrs.get("component_names")
        components = [_text(n) for n in names] if names is not None else \
            _component_names(self.dimension, 1 if values.ndim == 1 else values.shape[1])
        return Field(name, values, unit, components)

    def __repr__(self):
        return f"Snapshot(step {self.step}, t = {self.time} s, {os.path.basename(self.path)})"


class Table:
    """energy.csv or diagnostics.csv: columns by name as float arrays (`table["kinetic"]`),
    `table.step` as integers, `table.unit(name)` each column's unit ("" where the file gives
    none)."""

    def __init__(self, path, columns, units):
        self.path, self._columns, self._units = path, columns, units
        self.step = columns["step"].astype(np.int64)

    @property
    def columns(self):
        return list(self._columns)

    def __getitem__(self, name):
        if name not in self._columns:
            raise KeyError(f"{self.path}: no column {name!r} (columns: "
                           f"{', '.join(self._columns)})")
        return self._columns[name]

    def unit(self, name):
        self[name]
        return self._units[name]

    def __len__(self):
        return len(self.step)


class NotARunError(ValueError):
    """open_run was given a folder that `revsph run` did not write."""


class Run:
    """A run folder written by `revsph run`: summary.json, energy.csv, diagnostics.csv and the
    snapshots. A run continued from another folder's snapshot (`revsph run --from OTHER/...
    --out THIS`) is stitched to it: snapshots() begins with OTHER's up to that snapshot."""

    def __init__(self, folder):
        self.folder = os.fspath(folder)
        if not os.path.isdir(self.folder):
            raise FileNotFoundError(f"{self.folder}: no such run folder")
        # Every run writes energy.csv at its start (the mark revsph's own --from looks for).
        if not os.path.isfile(os.path.join(self.folder, "energy.csv")):
            forward = os.path.join(self.folder, "forward", "energy.csv")
            hint = ("; a verify --out folder holds two runs: open its forward/ and backward/"
                    if os.path.isfile(forward) else
                    "; open a folder that `revsph run --out FOLDER` wrote")
            raise NotARunError(f"{self.folder}: not a run folder (no energy.csv){hint}")
        path = os.path.join(self.folder, "summary.json")
        self.summary = None
        if os.path.isfile(path):
            with open(path) as f:
                self.summary = json.load(f)

    def own_snapshot_paths(self):
        """This folder's snapshot files, by step."""
        folder = os.path.join(self.folder, "snapshots")
        found = []
        for name in os.listdir(folder) if os.path.isdir(folder) else []:
            match = _STEP_FILE.match(name)
            if match:
                found.append((int(match.group(1)), os.path.join(folder, name)))
        return [path for _, path in sorted(found)]

    def snapshot_paths(self):
        """The run's snapshot files in step order, the runs it continues first; within a
        folder the series run.xdmf lists (a continued segment's off-cadence end is left out)."""
        paths, seen = [], set()
        run = self
        while run is not None and os.path.realpath(run.folder) not in seen:
            seen.add(os.path.realpath(run.folder))
            own = run._series_paths()
            if paths:
                # The later run began at its first snapshot: the earlier run's up to there.
                own = [p for p in own if _step_of(p) < _step_of(paths[0])]
            paths = own + paths
            run = run._parent()
        return paths

    def snapshots(self):
        """Snapshot objects, step by step (restarts stitched)."""
        return [Snapshot(path) for path in self.snapshot_paths()]

    def energy(self):
        """energy.csv as a Table."""
        return read_table(os.path.join(self.folder, "energy.csv"))

    def diagnostics(self):
        """diagnostics.csv as a Table, or None for a model without diagnostics."""
        path = os.path.join(self.folder, "diagnostics.csv")
        return read_table(path) if os.path.isfile(path) else None

    def _series_paths(self):
        xdmf = os.path.join(self.folder, "run.xdmf")
        if not os.path.isfile(xdmf):
            return self.own_snapshot_paths()
        with open(xdmf) as f:
            listed = dict.fromkeys(re.findall(r"(snapshots/step_\d+\.h5):", f.read()))
        return [os.path.join(self.folder, name) for name in listed]

    def _parent(self):
        source = (self.summary or {}).get("from_snapshot")
        if not source:
            return None
        # Absolute since 2026-11; before, as given on the command line (relative to where the
        # run was started: most often the folder's parent).
        candidates = [source, os.path.join(self.folder, source),
                      os.path.join(os.path.dirname(os.path.abspath(self.folder)), source)]
        for candidate in candidates:
            folder = os.path.dirname(os.path.dirname(os.path.abspath(candidate)))
            if os.path.isfile(candidate) and os.path.isfile(os.path.join(folder, "energy.csv")):
                if os.path.realpath(folder) != os.path.realpath(self.folder):
                    return Run(folder)
        return None

    def __repr__(self):
        return f"Run({self.folder!r})"


def open_run(folder):
    """The run in `folder` (what `revsph run --out FOLDER` wrote); NotARunError if it holds
    none, FileNotFoundError if it does not exist."""
    return Run(folder)


def read_table(path):
    """A revsph CSV (energy.csv, diagnostics.csv) as a Table; header cells are `name [unit]`."""
    with open(path, newline="") as f:
        rows = [row for row in csv.reader(f) if row]
    if not rows:
        raise ValueError(f"{path}: empty")
    names, units = [], {}
    for cell in rows[0]:
        match = _HEADER_CELL.match(cell.strip())
        names.append(match.group("name"))
        units[match.group("name")] = match.group("unit") or ""
    values = np.array([[float(v) for v in row] for row in rows[1:]], dtype=float)
    values = values.reshape(len(rows) - 1, len(names))
    return Table(path, {name: values[:, c] for c, name in enumerate(names)}, units)


def _component_names(dimension, count):
    # The rule of core/field_components.hpp, for files written before component_names.
    axes = "xyz"
    if count == 1:
        return []
    if count == dimension:
        return list(axes[:dimension])
    if count == dimension * dimension:
        return [axes[i] + axes[j] for i in range(dimension) for j in range(dimension)]
    return [str(c) for c in range(count)]


def _step_of(path):
    return int(_STEP_FILE.match(os.path.basename(path)).group(1))


def _text(value):
    return value.decode() if isinstance(value, bytes) else str(value)
