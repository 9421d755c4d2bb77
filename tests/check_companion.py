"""A finished run is never lost to its error estimate. The estimate's companion
run comes after the run's results are final (written, closed and renamed
into place: the HDF5 file, its .xmf, the CSV); whatever the companion meets
then, they stay as they are. tests/test_companion.cpp runs tubeform's driver
with a companion that fails as MODE says (the squaring case on the fast
preset to a 0.5 mm stroke), on 1 and 2 ranks:
  - an input error (an inverted element of its coarser mesh, a second pass's
    die check) or a library error (HDF5, MUMPS) on every rank: exit 0, one
    line "no error estimate: its companion run failed (<why>)", no error line,
    the results in place and complete without error_* attributes;
  - a stop signal: exit 1, one line saying the companion was interrupted and
    the results are complete; they are;
  - an error on rank 1 alone while rank 0 waits in a collective call of the
    companion (2 ranks): the job is aborted after the ranks' wait (10 s) with
    one line naming rank 1, the companion and the complete results; they are
    in place and complete;
  - a companion that ends: the estimate added to the finished file (error_load
    there), and nothing else in it changed: every /history column and every
    other attribute equal to those of the run whose companion failed.
In every case nothing is left beside the results (no .partial, no
.estimate.partial, no companion file). Before the change, an error of the
first kind was passed on before the results were closed: the run stayed
.partial without /history, the CSV too.
"""
import os
import sys
from concurrent.futures import ThreadPoolExecutor

import h5py
import numpy as np

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
program = sys.argv[4]
k = Checks("companion")
CASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-stroke", "0.5", "-progress", "0"]


def launch(np_, mode):
    """Runs the case with its companion failing as `mode` says, on fresh paths."""
    name = f"companion_{mode}_np{np_}"
    f, csv = out(name + ".h5"), out(name + ".csv")
    xmf = f[:-3] + ".xmf"
    for p in (f, csv, xmf):
        for q in (p, p + ".partial", p + ".estimate.partial"):
            if os.path.exists(q):
                os.remove(q)
    return run(program, mpirun, np_, [mode] + CASE + ["-output", f, "-history_csv", csv], check=False, timeout=120,
               report_hang=True)


def attempt(np_, mode, p=None):
    """Checks a run of launch() (run here unless given)."""
    name = f"companion_{mode}_np{np_}"
    f, csv = out(name + ".h5"), out(name + ".csv")
    xmf = f[:-3] + ".xmf"
    p = p or launch(np_, mode)
    text = p.stdout + p.stderr
    errors = [l for l in text.splitlines() if l.startswith("tubeform: error")]
    none = [l for l in text.splitlines() if l.startswith("tubeform: no error estimate")]
    left = sorted(q for q in os.listdir(out(".")) if q.startswith(name) and (q.endswith("partial") or
                                                                              "companion.h5" in q))
    placed = all(os.path.isfile(q) for q in (f, csv, xmf))
    hist, attrs = {}, {}
    if placed:
        with h5py.File(f, "r") as h:
            hist = {c: h["/history"][c][:] for c in h["/history"]}
            attrs = {a: h["/history"].attrs[a] for a in h["/history"].attrs}
    complete = placed and attrs.get("stopped") == 0 and hist["stroke"].max() >= 0.5 - 1e-9
    estimated = "error_load" in attrs
    if mode in ("input", "lib"):
        ok = p.returncode == 0 and not errors and len(none) == 1 and complete and not estimated
        said = none
    elif mode == "signal":
        ok = (p.returncode == 1 and len(errors) == 1 and "during the companion run" in errors[0]
              and "complete" in errors[0] and complete and not estimated)
        said = errors
    elif mode == "alone":
        ok = (p.returncode == 2 and len(errors) == 1 and errors[0].startswith("tubeform: error on rank 1:")
              and "companion" in errors[0] and "complete" in errors[0] and complete and not estimated)
        said = errors
    else:
        ok = p.returncode == 0 and not errors and not none and complete and estimated and attrs["error_load"] > 0
        said = [l for l in text.splitlines() if "estimated error" in l]
    hang = " (a hang: killed)" if p.timed_out else ""
    k.check(ok and not left and not p.timed_out,
            f"np={np_} companion {mode}: exit {p.returncode}{hang}, results {'in place' if placed else 'NOT in place'}"
            f"{', complete' if complete else ''}{', with an estimate' if estimated else ''}"
            f"{', left ' + str(left) if left else ''}; {said[:1]}")
    return hist, attrs


# "alone" waits the ranks' 10 s for each other (its rank 0 in the companion's collective call, on one core): it runs
# from the start beside the others, which take the other core. Unbound from cores: mpirun would bind every job's
# first rank to core 0.
os.environ["OMPI_MCA_hwloc_base_binding_policy"] = "none"
beside = ThreadPoolExecutor(max_workers=1)
alone = beside.submit(launch, 2, "alone")
for np_ in (1, 2):
    failed = attempt(np_, "input")
    attempt(np_, "lib")
    attempt(np_, "signal")
    if np_ == 2:
        attempt(np_, "alone", alone.result())
    hist, attrs = attempt(np_, "rows")
    if hist and failed[0]:
        columns = {c for c in hist if c.startswith("error_")}
        same = all(np.array_equal(hist[c], failed[0][c], equal_nan=True) for c in hist if c not in columns) and \
            hist.keys() - columns == failed[0].keys()
        by_estimate = lambda a: a.startswith("error_") or a == "target_met"  # noqa: E731 (what the estimate adds)
        others = {a: v for a, v in attrs.items() if not by_estimate(a)}
        same_attrs = others.keys() == failed[1].keys() and all(
            np.array_equal(others[a], failed[1][a]) for a in others if a != "stop_reason")
        added = sorted(a for a in attrs if by_estimate(a))
        k.check(same and same_attrs and added and columns == {"error_load", "error_c_over_t"},
                f"np={np_}: the estimate added {len(added)} attributes ({', '.join(added[:3])}, ...) and the columns "
                f"{sorted(columns)}, and changed nothing else ({len(hist) - len(columns)} history columns, "
                f"{len(others)} other attributes as without it)")
        # Row by row: the steps' companion 1 % above the mesh's, which is the run: every loading row's estimate
        # is 1 % of its load (kStepShare 1; the first row, unloaded, 0); a release's rows carry the estimate of the
        # loaded state they release (the attribute error_loaded_load).
        if "error_load" in hist:
            stage = hist["stage"] % 2 == 0
            load = stage & (hist["load"] != 0)
            e = hist["error_load"]
            k.check(np.allclose(e[load], 0.01, rtol=1e-9) and (~stage).any() and
                    np.allclose(e[~stage], attrs.get("error_loaded_load", -1), rtol=1e-12),
                    f"np={np_}: error_load is 1 % on each of {load.sum()} loading rows, the loaded state's on "
                    f"{(~stage).sum()} release rows (range {e.min():.6g}-{e.max():.6g})")
k.done()
