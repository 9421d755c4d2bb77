"""Stops that write what was computed, then a subset of the stability suite at the extremes
(python/tubeform_py/extremes.py; the whole grid: tools/tradeoff --extremes): no friction, an incompressible
material, the coarsest mesh and the loosest strain limit, on 2 ranks with the
default preset, and a tube that yields at a strain of 2e-4 (E/sy 5000: the
preset's -rmin_deps_yield bounds its steps; without it the internal-work check
read 9.5 %) and one that yields at 2e-2 (E/sy 50: almost elastic, it snaps
in the paper's load-controlled springback; a re-solved step taken past its
rotation bound there read 16.8 % before every re-solved step had to meet its
limits). Each run must finish with finite results (history and fields)
and self-checks (a), (b) within 5 % (python/tubeform_py/extremes.py gives the reason),
and a stopped run must have said why in one line per rank.
"""
import os
import sys
from concurrent.futures import ThreadPoolExecutor

import h5py
import numpy as np

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
# Its 2-rank jobs run two or three at a time (below): each mpirun would bind its first rank to core 0 and its second
# to core 1, all the runs then on one core; unbound, the kernel spreads them (as scripts/sweep's jobs).
os.environ["OMPI_MCA_hwloc_base_binding_policy"] = "none"
sys.path.insert(0, os.path.join(src, "python"))  # the helper package (python/README.md)
from tubeform_py import extremes  # noqa: E402

k = Checks("extremes")
# Each case's -time_limit here: a guard against hangs, not the study's 5-minute target (a speed
# target belongs to tools/tradeoff --extremes, not to a test on a shared machine). nu 0.499 took
# 180-300 s on 2 ranks beside another test, and stopped at 300 s once with a third job running.
HANG_GUARD = 900

# A run stopped by its increment budget, its time limit or its energy error: non-zero exit, one
# error line per job naming the option, the result file in place (no
# .partial) with the stop flagged and finite histories.
# The energy stop on the paper's forward increments (-equilibrium_tol 0), whose drift passes 1e-3 on the fast
# preset (equilibrium iterations keep it near 1e-4).
# The three side by side: each stops within a second or two and then waits ~2 s in mpirun's wind-down after its
# error exit (a -time_limit stop still writes its state there: 2 field steps even at 0.01 s).
STOPS = (("-rmin_max_increments", 30, 31, []), ("-time_limit", 0.5, None, []),
         ("-max_energy_error", 0.001, None, ["-equilibrium_tol", 0]))
with ThreadPoolExecutor(max_workers=3) as pool:
    stopped = list(pool.map(lambda c: run(tf, mpirun, 2, ["-options_file", f"{src}/options/squaring.opts",
                                                          "-options_file", f"{src}/options/preset-fast.opts", c[0],
                                                          c[1], "-output", out(f"stop{c[0]}.h5")] + c[3],
                                          check=False), STOPS))
for (option, value, rows, extra), p in zip(STOPS, stopped):
    f = out(f"stop{option}.h5")
    lines = [l for l in (p.stdout + p.stderr).splitlines() if l.startswith("tubeform: error")]
    k.check(p.returncode != 0 and len(lines) == 1 and option in lines[0],
            f"{option} {value}: exit {p.returncode}, {len(lines)} error line(s) naming the option")
    ok = os.path.exists(f) and not os.path.exists(f + ".partial")
    if ok:
        with h5py.File(f, "r") as h:
            n = h["/history/stroke"].shape[0]
            ok = h["/history"].attrs["stopped"] == 1 and all(np.isfinite(h["/history"][c][:]).all() for c in h["/history"])
            ok = ok and (rows is None or n == rows) and h["/vertex_fields/displacement_u"].shape[0] >= 2
    k.check(ok, f"{option} {value}: results written up to the stop, flagged stopped, finite")
outdir = os.path.join(os.getcwd(), "extremes")
os.makedirs(outdir, exist_ok=True)
SUBSET = ("mu 0", "nu 0.499", "mesh 1x8", "deps 0.05", "E/sy 5000", "E/sy 50")
chosen = [(name, extra) for name, extra in extremes.CASES if name in SUBSET]
k.check(len(chosen) == len(SUBSET), f"{len(chosen)} of the {len(SUBSET)} subset cases found in tubeform_py.extremes "
        f"(missing: {sorted(set(SUBSET) - {n for n, _ in chosen})})")
# Two cases at a time, the longest first (E/sy 5000 ~20 s, E/sy 50 ~15 s, nu 0.499 ~10 s alone): each case's run
# takes one rank and its estimate's companions the other, which then waits idle for the run (src/driver/beside.cpp),
# so two cases' runs share the two cores.
LONGEST_FIRST = ("E/sy 5000", "E/sy 50", "nu 0.499", "deps 0.05", "mu 0", "mesh 1x8")
order = sorted(chosen, key=lambda c: LONGEST_FIRST.index(c[0]))
with ThreadPoolExecutor(max_workers=2) as pool:
    ran = dict(zip([n for n, _ in order], pool.map(
        lambda c: extremes.run_case(*c, outdir, exe=tf, mpirun=mpirun, time_limit=HANG_GUARD), order)))
for name, extra in chosen:
    r = ran[name]
    ok, why = extremes.acceptable(r)
    k.check(ok and r["status"] == "done", f"{name}: {r['status']} in {r['wall']:.0f} s, finite {r['finite']}, "
            f"(a) {r.get('a', float('nan')):.2%}, (b) {r.get('b', float('nan')):.2%} {why}")
k.done()
