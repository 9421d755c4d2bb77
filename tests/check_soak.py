"""A short soak (tools/soak's own functions, tubeform_py.soaklib): three random tubes from a fixed seed on the fast
preset, strokes of 1 mm to 0.1 Ro, the third on 2 ranks, whole runs (springback and the error estimate). Seed 1
draws a Swift tube of R/t 17 at mu 0.47, a thick Ludwik wall of R/t 4 with n 0.08, and a thin one of R/t 55 at mu
0.57 (2 ranks). None may
  - crash: a non-zero exit without tubeform's one line, a signal, a core file, an MPI abort;
  - hang: each run gets -time_limit 60 s (the three take 3-15 s on a loaded 2-core machine) and is killed at
    soaklib.wall_limit(60) = 240 s;
  - write NaN (or Inf outside r_corner_x, r_corner_y) into /history;
  - be unflagged: finish without a 'tubeform: warning:' line while its energy balance is above the fast preset's
    -expect_load, or its error estimate above -expect_load or -expect_c_over_t. The expectations are read from
    options/preset-fast.opts (5 %, 0.05), not from the run; they are the only tolerances. The energy balance is
    taken twice: the run's printed self-check line (as tools/soak reads it) and its recomputation from the
    history's load, stroke and energy columns (tfcheck.self_checks, the largest after the first 10 increments, as
    the run's line): a line that under-reports the balance does not hide it.
A stop with one line is allowed (a user is told why); the test prints it.
"""
import os
import shutil
import sys

import h5py
import numpy as np

from tfcheck import Checks, args, out, self_checks

tf, mpirun, src = args()
sys.path.insert(0, os.path.join(src, "python"))  # the helper package (python/README.md)
from tubeform_py import soaklib  # noqa: E402

SEED, TIME_LIMIT = 1, 60
# The run's worst self-checks leave out its first increments (their work is too small to mean much): the
# history's rows 0 (the initial state) to 10.
FIRST_ROWS = 11

k = Checks("soak")
outdir = out("soak")
shutil.rmtree(outdir, ignore_errors=True)
os.makedirs(outdir)
cases = soaklib.draw(SEED, 3, presets={"fast": 1}, stroke=(1, 0.1))
for (name, c), np_ in zip(cases.items(), (1, 1, 2)):
    c["np"] = np_
    log = soaklib.run_case(name, c, outdir, exe=tf, mpirun=mpirun, src=src, time_limit=TIME_LIMIT)
    expect = soaklib.expectation("fast", src)
    h5 = os.path.join(outdir, name + ".h5")
    v = soaklib.classify(log, h5, expect)
    print(soaklib.row(name, c, v, expect))
    what = f"{name} ({soaklib.describe(c)})"
    k.check(v["kind"] not in ("crash", "hang"), f"{what}: no crash or hang ({v['kind']} {v['why']})")
    k.check(not v["nonfinite"], f"{name}: /history finite (not finite: {v['nonfinite'] or 'none'})")
    k.check(not v["unflagged"], f"{name}: nothing off the preset's expectation unflagged ({v['off'] or 'none off'}; "
            f"{len(v['warnings'])} warning(s))")
    if v["kind"] == "finished":
        with h5py.File(h5, "r") as f:
            H = {c_: f["/history"][c_][:] for c_ in f["/history"]}
        a = float(np.abs(self_checks(H)[0][FIRST_ROWS:]).max())
        k.check(a <= expect[0] or v["warnings"], f"{name}: energy balance recomputed from the history {100 * a:.3g} % "
                f"(printed {v['energy']} %) within {100 * expect[0]:g} % or warned")
    else:
        print(f"{name} stopped: {v['why']}")
k.done()
