"""One `mpirun ... revsph run` of a benchmark, read back through its summary.json."""

import json
import os
import subprocess


def mpi_run_summary(mpirun_options, revsph, run_arguments, out, environment):
    """Runs `mpirun OPTIONS REVSPH run ARGUMENTS --out OUT --force` as root may (OpenMPI's two
    confirmations), passing each variable of `environment` to every process; returns the run's
    summary.json."""
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               **environment)
    exported = [item for name in environment for item in ("-x", name)]
    command = (["mpirun", *mpirun_options, *exported, revsph, "run", *run_arguments,
                "--out", out, "--force"])
    subprocess.run(command, env=env, capture_output=True, text=True, check=True)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)
