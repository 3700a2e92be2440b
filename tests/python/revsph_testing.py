"""Shared by the Python system tests: the command line they take, the environment revsph runs in,
reading snapshot attributes, and the state hash reimplemented from its definition in
verify/state_hash.cpp (an independent check of revsph's own)."""

import hashlib
import os
import re
import shutil
import struct
import sys
import tempfile
import unittest

import numpy as np


def run_unittests(module_globals, work_prefix):
    """The main() of a test script: `script.py REVSPH_BINARY [unittest arguments]` (or REVSPH in
    the environment). Sets the script's REVSPH and WORK (a scratch directory, removed afterwards)
    and exits with the tests' status."""
    argv = sys.argv[1:]
    if argv and not argv[0].startswith("-"):
        revsph = os.path.abspath(argv.pop(0))
    else:
        revsph = os.environ.get("REVSPH")
    if not revsph or not os.access(revsph, os.X_OK):
        sys.exit(f"usage: {os.path.basename(sys.argv[0])} REVSPH_BINARY (or set REVSPH)")
    work = tempfile.mkdtemp(prefix=work_prefix)
    module_globals["REVSPH"] = revsph
    module_globals["WORK"] = work
    try:
        program = unittest.main(argv=[sys.argv[0]] + argv, exit=False, verbosity=2)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    sys.exit(0 if program.result.wasSuccessful() else 1)


def environment():
    """revsph's environment: waiting OpenMP threads sleep instead of spinning, so runs keep their
    pace on a loaded machine."""
    env = dict(os.environ)
    env.setdefault("OMP_WAIT_POLICY", "PASSIVE")
    return env


def text_attr(value):
    return value.decode("utf-8") if isinstance(value, bytes) else str(value)


def snapshot_step(path):
    """The step of snapshots/step_NNNNNNNNN.h5, or None for any other file name."""
    match = re.fullmatch(r"step_(\d{9})\.h5", os.path.basename(path))
    return int(match.group(1)) if match else None


def python_state_hash(h5):
    """verify/state_hash.cpp, byte for byte: for each field of field_order, length-prefixed set
    name and variable name, then components, count, scale exponent, raw kind (0 fixed point,
    1 IEEE double), all as int64 little endian, then the raw int64 values component-major."""
    sha = hashlib.sha256()

    def add_integer(value):
        sha.update(struct.pack("<q", int(value)))

    def add_string(text):
        data = text.encode("utf-8")
        add_integer(len(data))
        sha.update(data)

    for entry in h5.attrs["field_order"]:
        set_and_name = text_attr(entry)
        particle_set, name = set_and_name.split("/", 1)
        dataset = h5["/state/" + set_and_name]
        components = int(dataset.attrs["components"])
        raw_kind = text_attr(dataset.attrs["raw_kind"])
        assert raw_kind in ("fixed_point", "ieee_double"), raw_kind
        rows = np.asarray(dataset[()])
        assert rows.dtype == np.int64, rows.dtype
        count = rows.shape[0]
        add_string(particle_set)
        add_string(name)
        add_integer(components)
        add_integer(count)
        add_integer(int(dataset.attrs["scale_exponent"]))
        add_integer(0 if raw_kind == "fixed_point" else 1)
        sha.update(np.ascontiguousarray(rows.reshape(count, components).T, dtype="<i8").tobytes())
    return sha.hexdigest()
