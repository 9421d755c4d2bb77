"""Shared helpers of tubeform's Python checks (run with /usr/bin/python3)."""
import glob
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor

import h5py
import numpy as np


def args():
    """(tubeform executable, mpirun, source dir) from the command line."""
    return sys.argv[1], sys.argv[2], sys.argv[3]


def out(name):
    """Absolute path of an output file in the test's working directory."""
    return os.path.join(os.getcwd(), name)


# Seconds mpirun gets to end its ranks after SIGTERM (it sends them SIGTERM,
# then SIGKILL a few seconds later) before it is killed itself.
KILL_GRACE = 20


def run(tf, mpirun, np_, opts, check=True, timeout=300, report_hang=False):
    """Runs tubeform on np_ ranks from the source directory (where scene files
    find options/solver.opts, as users run it); returns the CompletedProcess.
    A run still going after `timeout` seconds is killed with its ranks and ends
    the test, or with report_hang is returned with timed_out set (crashed()
    names it). Output paths given to it must be absolute (see out())."""
    # One rank runs as an MPI singleton: the same code path, without mpirun's
    # ~2 s wind-down after a non-zero exit.
    cmd = ([mpirun, "-n", str(np_)] if np_ > 1 else []) + [tf] + [str(o) for o in opts]
    # Each run its own Open MPI session directory below the test's: runs a check
    # starts at once (a thread pool) race in a shared one ("mkdir ... File exists",
    # ORTE_ERROR_LOG session_dir.c: a singleton of verification_dynamics failed so).
    env, session = dict(os.environ), None
    if env.get("OMPI_MCA_orte_tmpdir_base"):
        os.makedirs(env["OMPI_MCA_orte_tmpdir_base"], exist_ok=True)
        session = tempfile.mkdtemp(dir=env["OMPI_MCA_orte_tmpdir_base"])
        env["OMPI_MCA_orte_tmpdir_base"] = session
    t0 = time.time()
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=sys.argv[3], env=env)
    timed_out = False
    try:
        stdout, stderr = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        # A hang (a rank waiting for one that left): mpirun, sent SIGTERM, ends its
        # ranks (SIGTERM, then SIGKILL), so none is left behind; then SIGKILL.
        timed_out = True
        proc.terminate()
        try:
            stdout, stderr = proc.communicate(timeout=KILL_GRACE)
        except subprocess.TimeoutExpired:
            proc.kill()
            stdout, stderr = proc.communicate()
    if session:
        shutil.rmtree(session, ignore_errors=True)
    p = subprocess.CompletedProcess(cmd, proc.returncode, stdout, stderr)
    if os.environ.get("TF_RUN_LOG"):  # the suite's runs and their times, for choosing what a long test runs
        line = [os.path.basename(sys.argv[0]), f"{time.time() - t0:.2f}", str(np_), " ".join(cmd[cmd.index(tf) + 1:])]
        with open(os.environ["TF_RUN_LOG"], "a") as f:
            f.write("\t".join(line) + "\n")
    p.timed_out = timed_out  # crashed() counts it
    if (check and p.returncode != 0) or (timed_out and not report_hang):
        print(" ".join(cmd))
        print(p.stdout, p.stderr)
        raise SystemExit(f"tubeform did not finish within {timeout} s (killed)" if timed_out else
                         f"tubeform failed with exit code {p.returncode}")
    return p


def run_all(tf, mpirun, jobs, **kw):
    """Runs single-rank jobs (each a list of options) two at a time, the machine's two cores (a test that calls
    it is given both: PROCESSORS 2 in tests/CMakeLists.txt); returns their CompletedProcesses in the jobs' order.
    run()'s keywords apply to each; a failed one (check=True) ends the test as run() does."""
    with ThreadPoolExecutor(max_workers=2) as pool:
        return list(pool.map(lambda opts: run(tf, mpirun, 1, opts, **kw), jobs))


# What a crashed rank leaves in a run's output: PETSc's signal handler (it turns
# SIGSEGV, SIGFPE, ... into MPI_Abort, exit 59), mpirun's report of a rank
# killed by a signal, an MPI_Abort, main's abort after an error seen by one rank.
CRASH_MARKS = ("Caught signal", "exited on signal", "MPI_ABORT", "error on rank")


def crashed(p):
    """Why a run counts as a crash ("" if it does not): it hung (run() killed
    it), Python reports a signal as a negative exit code, mpirun and shells as
    128 + N; or a mark of CRASH_MARKS in its output."""
    if getattr(p, "timed_out", False):
        return "no exit within its timeout (a hang): killed"
    if p.returncode < 0:
        return f"killed by signal {-p.returncode}"
    if p.returncode >= 128:
        return f"exit {p.returncode}: signal {p.returncode - 128}"
    text = (p.stdout or "") + (p.stderr or "")
    marks = [m for m in CRASH_MARKS if m in text]
    return f"'{marks[0]}' in its output" if marks else ""


def allow_core_dumps():
    """Lets the runs started from here write core files (the soft core size
    limit raised to the hard one) and says where a crash of tubeform (run from
    the source directory) would leave them: (directory, name prefix), or None
    with the reason when no core file can appear there (cores piped to a
    program such as systemd-coredump, or a hard limit of 0)."""
    pattern = open("/proc/sys/kernel/core_pattern").read().strip()
    _, hard = resource.getrlimit(resource.RLIMIT_CORE)
    if pattern.startswith("|"):
        return None, f"core_pattern pipes cores to a program ({pattern.split()[0][1:]})"
    if hard == 0:
        return None, "the hard core size limit is 0"
    resource.setrlimit(resource.RLIMIT_CORE, (hard, hard))
    where = os.path.join(sys.argv[3], os.path.dirname(pattern))  # (an absolute pattern keeps its own directory)
    return (where, os.path.basename(pattern).split("%")[0] or "core"), ""


def core_dumps(where, since):
    """Core files written at `where` (from allow_core_dumps) since the time `since`."""
    return [f for f in glob.glob(os.path.join(where[0], where[1] + "*")) if os.path.getmtime(f) >= since]


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


def history_and_tools(path):
    """A result file's history columns, and under "tools" each tool's displacement at every field step."""
    with h5py.File(path, "r") as h:
        r = {c: h["/history"][c][:] for c in h["/history"]}
        r["tools"] = {t: h["/tools"][t]["displacement"][:] for t in h["/tools"]}
    return r


def ran_to_end(k, tf, mpirun, n, opts, path, label, p=None):
    """Runs tubeform on n ranks with opts writing `path`; checks (in k) that it ran to its end, named by `label`
    and the run's first error line; returns its history and tools (history_and_tools; its results up to a stop).
    `p`: that run made already (its CompletedProcess, run with check=False: run_all's side by side)."""
    if p is None:
        p = run(tf, mpirun, n, list(opts) + ["-output", path], check=False, timeout=600)
    why = [x for x in p.stdout.splitlines() + p.stderr.splitlines() if "error:" in x][:1]
    k.check(p.returncode == 0, f"{label}{' (2 ranks)' if n > 1 else ''}: ran to its end (exit {p.returncode}) "
            f"{''.join(why)}")
    return history_and_tools(path)


def checkpoint_at(tf, mpirun, np_, opts, ck, every, **kw):
    """Runs tubeform on np_ ranks with opts (its -output among them) up to increment `every`, writes its checkpoint
    there to `ck` and stops (-rmin_max_increments `every`, a run control a restart may change): the rest of the
    path, which the restart from `ck` computes, is not run twice. The stop is an error exit naming the option; any
    other end fails the test. Returns the CompletedProcess."""
    p = run(tf, mpirun, np_, list(opts) + ["-checkpoint", ck, "-checkpoint_every", every, "-rmin_max_increments", every],
            check=False, **kw)
    if p.returncode == 0 or "-rmin_max_increments" not in p.stdout + p.stderr:
        print(p.stdout, p.stderr)
        raise SystemExit(f"checkpoint_at {every}: exit {p.returncode}, not the stop at increment {every}")
    return p


def lower_die_steps(path, h):
    """The field steps' lambda in the result file `path` and the lower die's displacement at each ((steps, 1, 2);
    none where it has no lower die of its own), from its history and tools `h` (history_and_tools)."""
    with h5py.File(path, "r") as f:
        lam = f["/time"][:, 0]  # (each field step's lambda: the press's U = 2 lambda while it loads)
    lower = [t for t in h["tools"] if t.startswith("lower-")]
    return lam, h["tools"][lower[0]] if lower else np.zeros((0, 1, 2))


def self_checks(H, share=0.5, lower_rise=None):
    """A press's self-checks recomputed from its history (docs/theory.md, "Self-checks"; docs/output.md's
    columns), not read from its energy_error and internal_error columns. Returns (a, b, tool) by row:
      tool: the press's work from the reported load and stroke, share x the trapezoidal integral of load dU
            (the quarter model carries half the punch load: share 0.5);
      a:    (work put in - w_int - w_friction - w_kinetic - w_damped) / work put in, the work put in being tool
            plus what the loads at the nodes did (w_ext - w_tool: the paper's unloading, pending release forces),
            less the work of a lower die moving on its own (`lower_rise`: its rise at each row's stroke, against
            its force lower_fy);
      b:    (w_int - w_plastic - w_elastic) / w_int,
    each relative to the largest its reference has been up to that row. Row 0 (no work yet) gives 0."""
    U, P = H["stroke"], H["load"]
    dw = share * 0.5 * (P[1:] + P[:-1]) * np.diff(U)
    if lower_rise is not None:
        dw = dw - 0.5 * (H["lower_fy"][1:] + H["lower_fy"][:-1]) * np.diff(lower_rise)
    tool = np.concatenate([[0.0], np.cumsum(dw)])
    w_in = tool + H["w_ext"] - H["w_tool"]
    def peak(w):
        return np.maximum(np.maximum.accumulate(np.abs(w)), 1e-300)
    a = (w_in - H["w_int"] - H["w_friction"] - H["w_kinetic"] - H["w_damped"]) / peak(w_in)
    b = (H["w_int"] - H["w_plastic"] - H["w_elastic"]) / peak(H["w_int"])
    return a, b, tool


# How far the run's own self-check columns may differ from self_checks(): both are the same sums of the same
# numbers in another order, round-off of at most ~1e4 additions (8,200 increments) of 1.1e-16 of the largest work,
# 1e-12, times 100. A column that left out any term (the damped energy, the smallest, is 2e-9 of the work) or read
# another quantity misses by more.
COLUMN_TOL = 1e-10


def column_gap(H, a, b, tool):
    """The largest difference between the run's columns (energy_error, internal_error, w_tool relative to the
    largest tool work) and their recomputation by self_checks(), and which column it is in."""
    gaps = {"energy_error": np.abs(H["energy_error"] - a).max(),
            "internal_error": np.abs(H["internal_error"] - b).max(),
            "w_tool": np.abs(H["w_tool"] - tool).max() / max(np.abs(tool).max(), 1e-300)}
    which = max(gaps, key=gaps.get)
    return gaps[which], which


class Checks:
    """Collects pass/fail lines; exit code 1 if any failed, or if none was made
    (a test whose checks were all skipped verifies nothing)."""

    def __init__(self, name):
        self.name, self.failed, self.total = name, 0, 0

    def check(self, ok, what):
        self.total += 1
        self.failed += not ok
        print(("ok     " if ok else "FAILED ") + what)
        return ok

    def done(self):
        print(f"{self.name}: {self.total - self.failed} passed, {self.failed} failed")
        if self.total == 0:
            print(f"FAILED {self.name}: no check was made")
        sys.exit(1 if self.failed or self.total == 0 else 0)
