"""Errors that one rank sees alone end the run on every rank
with one line, exit code 1 and no hang, on 2 ranks (and 1):
  - a Gmsh mesh whose physical curve holds a segment that is no side of a cell
    (tests/fuzz/regressions/gmsh/boundary_segment_not_a_cell_side.msh: the
    4 x 8 thick cylinder with one 'outer' segment from node 8 to node 10,
    skipping 9). Only rank 0 reads the mesh; SerialMesh::validate refuses it
    before any work, naming the file and the curve. (Before: rank 0 failed
    while labelling it and returned, the other rank waited in
    DMPlexDistribute for ever.)
  - the ParaView index (.xmf) that cannot be written while the .h5 can: a
    directory stands where the .xmf goes. Rank 0 writes the .xmf after the
    run; the failure is told to every rank before it is raised, and the
    results stay in place. (Before: rank 0 returned with the error, the other
    waited in MPI_Bcast for ever.)
Each run gets TIMEOUT seconds: a hang is killed with its ranks and fails.

Whether an error is every rank's is decided by the ranks agreeing, not by its
error code (core/job_end.hpp; tests/test_agree.cpp, with a wait of AGREE
seconds): an input error that every rank raises is one line from rank 0, exit
1; the same error code raised by rank 1 alone while rank 0 waits in a
collective call (a rank-local PetscCheck(..., PETSC_ERR_USER_INPUT, ...)) is
one line from rank 1 naming itself and the job aborted after AGREE seconds,
not a hang (decided by the code, rank 1 would have left quietly, taken it for
every rank's, and rank 0 would wait for ever); raised by rank 1 after the
last collective call, it is one line from rank 1 and exit 1 on every rank,
without an abort. An error whose unwinding meets a second one (a destructor
closing a result file on the full disk that stopped the run: its close fails
too) is reported by its own text, not the second's.
"""
import os
import shutil
import sys
import time
from concurrent.futures import ThreadPoolExecutor

from tfcheck import Checks, args, crashed, out, run

tf, mpirun, src = args()
k = Checks("rank_errors")
TIMEOUT = 60  # s: these runs end in about 2 s (mpirun's wind-down of a failed job included)
MESH = os.path.join(src, "tests", "fuzz", "regressions", "gmsh", "boundary_segment_not_a_cell_side.msh")
SMALL = ["-options_file", f"{src}/options/pressure.opts", "-mesh_nt", 2, "-mesh_ntheta", 6, "-increments", 1]


def attempt(np_, opts):
    return run(tf, mpirun, np_, opts, check=False, timeout=TIMEOUT, report_hang=True)


def refused(np_, p, needles, what):
    """Checks a case's run p that must end with one error line holding every needle, exit 1, no crash or hang."""
    lines = [l for l in (p.stdout + p.stderr).splitlines() if l.startswith("tubeform: error")]
    crash = crashed(p)
    ok = p.returncode == 1 and not crash and len(lines) == 1 and all(n in lines[0] for n in needles)
    k.check(ok, f"np={np_} {what}: exit {p.returncode}{', ' + crash if crash else ''}, {len(lines)} error line(s): "
            f"{lines[:1]}")


# The four runs side by side (each a second's work or less, the 2-rank ones then ~2 s in mpirun's wind-down after
# the error exit), each its own files (its own -history_csv: options/pressure.opts names one for all).
for np_ in (2, 1):
    h5, xmf = out(f"xmf_np{np_}.h5"), out(f"xmf_np{np_}.xmf")
    for f in (h5, h5 + ".partial"):
        if os.path.exists(f):
            os.remove(f)
    shutil.rmtree(xmf, ignore_errors=True)
    os.mkdir(xmf)  # the .xmf cannot be written; its directory (the .h5's) can
with ThreadPoolExecutor(max_workers=4) as pool:
    ends = {(what, np_): pool.submit(attempt, np_, opts) for np_ in (2, 1) for what, opts in (
        ("badmesh", ["-options_file", f"{src}/options/pressure.opts", "-mesh_file", MESH, "-output",
                     out(f"badmesh_np{np_}.h5")]),
        ("xmf", SMALL + ["-output", out(f"xmf_np{np_}.h5"), "-history_csv", out(f"xmf_np{np_}.csv")]))}
for np_ in (2, 1):
    refused(np_, ends["badmesh", np_].result(),
            ["-mesh_file", "boundary_segment_not_a_cell_side.msh", "'outer'", "not a side of any cell"],
            "a boundary segment that is no cell side")
    k.check(not os.path.exists(out(f"badmesh_np{np_}.h5")) and not os.path.exists(out(f"badmesh_np{np_}.h5.partial")),
            f"np={np_} bad mesh: refused before any result file")

    h5 = out(f"xmf_np{np_}.h5")
    refused(np_, ends["xmf", np_].result(), [h5, ".xmf", "cannot be written"], "the .xmf cannot be written")
    k.check(os.path.isfile(h5) and not os.path.exists(h5 + ".partial"),
            f"np={np_} .xmf failed: the results are in place ({os.path.basename(h5)}), no .partial left")
AGREE = 3  # s a rank with an error waits for the others (tubeform waits 10: kAgreeSeconds)
agree = sys.argv[4]
MODES = [("every", 1, "tubeform: error: -test_value 3: must be below 2", False),
         ("alone", 2, "tubeform: error on rank 1: -test_file x: only rank 1 read it and "
                      "refused it (the other ranks did not stop with it within 3 s", True),
         ("late", 1, "tubeform: error on rank 1: -test_file x: only rank 1 read it and refused it", False),
         ("cleanup", 1, "tubeform: error: -output x.h5: 0 MB free on its file system", False),
         ("none", 0, None, False)]


def timed(mode):
    t0 = time.time()
    p = run(agree, mpirun, 2, [mode, AGREE], check=False, timeout=TIMEOUT, report_hang=True)
    return p, time.time() - t0


# The five modes side by side: each waits (AGREE s, or mpirun's ~2 s wind-down after an error exit) more than it
# computes.
with ThreadPoolExecutor(max_workers=len(MODES)) as pool:
    ended = list(pool.map(timed, [m[0] for m in MODES]))
for (mode, code, line, aborts), (p, took) in zip(MODES, ended):
    lines = [l for l in (p.stdout + p.stderr).splitlines() if l.startswith("tubeform: error")]
    aborted = "MPI_ABORT" in p.stdout + p.stderr
    # Exit code 2 comes only from EndJob's MPI_Abort (it returns 0 or 1 otherwise): it shows the abort.
    # Open MPI's own "MPI_ABORT was invoked" notice is not required: mpirun may end before it forwards it.
    ok = (not p.timed_out and p.returncode == code and (aborts or not aborted) and
          (lines == [] if line is None else len(lines) == 1 and lines[0].startswith(line)))
    if aborts:
        ok = ok and took >= AGREE  # it waited for the others before it gave up
    k.check(ok, f"agreement, {mode}: exit {p.returncode}{' (a hang: killed)' if p.timed_out else ''}, "
            f"{'aborted, ' if aborted else ''}{took:.1f} s, {len(lines)} error line(s): {lines[:1]}")
k.done()
