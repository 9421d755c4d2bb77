"""Running tubeform from the study scripts (tools/tradeoff, converge, bench)
and reading the numbers they compare out of a result history."""
import csv
import os
import contextlib
import re
import shutil
import subprocess
import tempfile
import time

import h5py
import numpy as np

root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # python/tubeform_py/..


def runs_env(base):
    """`base` (a mapping of environment variables) with scripts/runs.env's settings where it has none: the
    environment of tubeform's runs that scripts/env.sh and the tests set too."""
    out = dict(base)
    with open(os.path.join(root, "scripts", "runs.env")) as f:
        for line in f:
            words = line.split()
            if not words or words[0].startswith("#"):
                continue
            name, value = words[0].split("=", 1)
            if len(words) == 3 and words[1] == "unless" and os.path.exists(words[2]):
                continue
            out.setdefault(name, value)
    return out


env = runs_env(os.environ)
EXE = os.path.join(root, "build", "tubeform")
LOAD_AT, CT_AT = (1.0, 2.0, 3.0, 4.2), (2.0, 3.0, 4.2)


def option(opts, name, default=None):
    """The last value of option `name` (with its dash) in a list of options or
    an options string (a result's `options` attribute); `default` if absent."""
    parts = opts.split() if isinstance(opts, str) else list(opts)
    val = default
    for i, p in enumerate(parts[:-1]):
        if p == name:
            val = parts[i + 1]
    return val


# Densities (t/mm^3) for a CalculiX case's -material custom: inertia at 1 mm/s only regularizes the steps.
CCX_DENSITY = {75000.0: 2.7e-9, 210000.0: 7.85e-9}  # aluminum, steel


def calculix_reference(name):
    """A CalculiX reference of tests/reference/calculix/: tubeform's options for its scene (from the header's
    case line), its loading rows (stroke, load, c_over_t, stage), its sprung-back C/t and its final stroke."""
    path = os.path.join(root, "tests", "reference", "calculix", f"{name}.csv")
    case = next(l for l in open(path) if l.startswith("# case:"))
    v = dict(re.findall(r"(\w+) ([-\w.+]+)", case[len("# case:"):]))
    opts = ["-tube_ro", v["Ro"], "-tube_t", v["t"], "-material", "custom", "-material_e", v["E"], "-material_nu",
            v["nu"], "-material_sy", v["sy"], "-material_k", v["K"], "-material_n", v["n"], "-material_density",
            CCX_DENSITY.get(float(v["E"]), 7.85e-9), "-friction_mu", v["mu"], "-die_r_apex", v["r_apex"], "-stroke",
            v["stroke"], "-unload", v["unload"]]
    rows = list(csv.DictReader(l for l in open(path) if not l.startswith("#")))
    col = {c: np.array([float(r[c]) for r in rows]) for c in ("stroke", "load", "c_over_t", "stage")}
    load = col["stage"] == 0
    return [str(o) for o in opts], {c: x[load] for c, x in col.items()}, sprung_back(path, col), float(v["stroke"])


def sprung_back(path, col):
    """C/t after springback of a CalculiX reference: its last row where its withdrawal finished ('finished': True
    in the header), else from a coarser mesh that did withdraw, named in the note ("sprung back on ...: C/t X",
    nan without one). Where the note also gives that mesh's loaded C/t ("from loaded Y") the springback's change
    Y - X is carried over to this mesh's own loaded C/t: the change is an elastic recovery that moves little with
    the mesh (docs/accuracy.md, "Against CalculiX"), the loaded C/t a lot (a run whose withdrawal stopped ends on
    a loaded or part-withdrawn row: not springback)."""
    head = "".join(l for l in open(path) if l.startswith("#"))
    if "'finished': True" in head and col["stage"][-1] == 1:
        return float(col["c_over_t"][-1])
    m = re.search(r"sprung back on [^:]*: C/t ([0-9.]+)(?: from loaded ([0-9.]+))?", head)
    if not m:
        return float("nan")
    if m.group(2) is None:
        return float(m.group(1))
    loaded = col["c_over_t"][col["stage"] == 0][-1]
    return float(loaded - (float(m.group(2)) - float(m.group(1))))


@contextlib.contextmanager
def session_env():
    """The runs' environment with an Open MPI session directory of its own, removed afterwards: runs that start
    and end at once in a shared one race (one's clean-up removes the directory the other is creating its own in:
    "ORTE_ERROR_LOG ... session_dir.c", exit 1; or, for single-rank runs, "mca_sharedfp_sm ... unable to open file
    for mmap")."""
    session = tempfile.mkdtemp(prefix="tf-mpi-")
    try:
        yield dict(env, OMPI_MCA_orte_tmpdir_base=session)
    finally:
        shutil.rmtree(session, ignore_errors=True)


class RunFailed(RuntimeError):
    pass


def run(case, extra, out, np_=1, exe=EXE, log_view=False):
    """One run of `case` (an options file) with `extra` options, history and final
    fields to `out`; returns (wall seconds, increments, factorizations, stdout)."""
    # A single rank unbound: mpirun binds a job's first rank to the first core, so two single-rank jobs of a study
    # side by side would share that core and leave the other idle, each taking twice its time.
    bind = ["--bind-to", "none"] if np_ == 1 else []
    cmd = ["mpirun", "-q"] + bind + ["-n", str(np_), exe, "-options_file", case, "-output", out] + extra
    if log_view:
        cmd += ["-log_view", ":" + out[:-3] + "_log.txt"]
    t0 = time.time()
    with session_env() as run_env:
        p = subprocess.run(cmd, cwd=root, env=run_env, capture_output=True, text=True)
    wall = time.time() - t0
    if p.returncode != 0:
        raise RunFailed(f"{' '.join(cmd)} failed:\n{p.stdout[-2000:]}{p.stderr[-2000:]}")
    m = re.search(r"done, (\d+) increments, (\d+) factorizations", p.stdout)
    return wall, int(m.group(1)), int(m.group(2)), p.stdout


COLUMNS = ("stroke", "load", "c_over_t", "x_max", "y_max", "stage", "energy_error", "internal_error", "friction_iters")


def deviation(x_max, y_max):
    """The paper's deviation ratio min(C1, C2) / max(C1, C2) (<= 1: how far from symmetric, whichever half-extent
    is the larger) from C1 = x_max and C2 = y_max. The history's deviation_ratio is C1 / C2 itself (docs/theory.md,
    "Metrics"): above 1 where the tube is wider across the press than along it."""
    x, y = np.asarray(x_max, dtype=float), np.asarray(y_max, dtype=float)
    return np.minimum(x, y) / np.maximum(x, y)


def history(path):
    """The loading rows of a run's history; 'spring' is C/t after springback (nan without one)."""
    with h5py.File(path, "r") as h:
        H = {c: h["/history"][c][:] for c in COLUMNS}
        spring = h["/history"].attrs.get("unloaded_c_over_t", float("nan"))
    keep = H["stage"] == 0
    H = {c: v[keep] for c, v in H.items()}
    H["spring"] = float(spring)
    return H


def at(H, col, U):
    """Column `col` at stroke U (linear between rows); nan where the loading stops short of U."""
    return float(np.interp(U, H["stroke"], H[col])) if H["stroke"][-1] >= U - 1e-9 else float("nan")


def metrics(H):
    """The compared numbers: P at LOAD_AT, C/t at CT_AT, C1/C2 = x_max / y_max at the end of loading, C/t after
    springback."""
    return ([at(H, "load", u) for u in LOAD_AT], [at(H, "c_over_t", u) for u in CT_AT],
            float(H["x_max"][-1] / H["y_max"][-1]), H["spring"])


def staircase(H, window=0.2, step=0.02, start=0.0):
    """The largest departure of the load-stroke curve from a quadratic fitted to
    it over any `window` mm of the loading (least squares over the rows in the
    window, windows every `step` mm), relative to the largest load in that
    window, and the stroke where the window starts. A smooth curve gives the
    quadratic's truncation error only (< 1e-3 for these curves); a staircase
    (load steps as nodes reach a tool) shows as its step height."""
    U, P = H["stroke"], H["load"]
    worst, where = 0.0, float("nan")
    for a in np.arange(start, U[-1] - window + 1e-9, step):
        k = (U >= a) & (U <= a + window)
        if k.sum() < 4:
            continue
        c = np.polyfit(U[k], P[k], 2)
        dev = np.abs(P[k] - np.polyval(c, U[k])).max() / np.abs(P[k]).max()
        if dev > worst:
            worst, where = float(dev), float(a)
    return worst, where
