"""Shared helpers of tubeform's Python checks (run with /usr/bin/python3)."""
import os
import subprocess
import sys

import h5py
import numpy as np


def args():
    """(tubeform executable, mpirun, source dir) from the command line."""
    return sys.argv[1], sys.argv[2], sys.argv[3]


def out(name):
    """Absolute path of an output file in the test's working directory."""
    return os.path.join(os.getcwd(), name)


def run(tf, mpirun, np_, opts, check=True, timeout=300):
    """Runs tubeform on np_ ranks from the source directory (where scene files
    find options/solver.opts, as users run it); returns the CompletedProcess.
    Output paths given to it must be absolute (see out())."""
    # One rank runs as an MPI singleton: the same code path, without mpirun's
    # ~2 s wind-down after a non-zero exit.
    cmd = ([mpirun, "-n", str(np_)] if np_ > 1 else []) + [tf] + [str(o) for o in opts]
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, cwd=sys.argv[3])
    if check and p.returncode != 0:
        print(" ".join(cmd))
        print(p.stdout, p.stderr)
        raise SystemExit(f"tubeform failed with exit code {p.returncode}")
    return p


def load(path):
    """Mesh, last displacement, last cell fields and the history of a result file."""
    with h5py.File(path, "r") as h:
        out = {
            "X": h["/geometry/vertices"][:],
            "cells": h["/viz/topology/cells"][:],
            "U": h["/vertex_fields/displacement_u"][-1],
            "history": {k: h["/history"][k][:] for k in h["/history"]},
        }
        for name in h["/cell_fields"]:
            out[name[:-2] if name.endswith("_c") else name] = h["/cell_fields"][name][-1]
    return out


class Checks:
    """Collects pass/fail lines; exit code 1 if any failed, or if none was made
    (a test whose checks were all skipped verifies nothing)."""

    def __init__(self, name):
        self.name, self.failed, self.total = name, 0, 0

    def check(self, ok, what):
        self.total += 1
        self.failed += not ok
        print(("ok     " if ok else "FAILED ") + what)

    def done(self):
        print(f"{self.name}: {self.total - self.failed} passed, {self.failed} failed")
        if self.total == 0:
            print(f"FAILED {self.name}: no check was made")
        sys.exit(1 if self.failed or self.total == 0 else 0)
