"""A subset of the stability suite at the extremes (scripts/extremes.py; the
whole grid: scripts/tradeoff --extremes): no friction, an incompressible
material, the coarsest mesh and the loosest strain limit, on 2 ranks with the
default preset. Each run must finish with finite results (history and fields)
and self-checks (a), (b) within 5 % (scripts/extremes.py gives the reason),
and a stopped run must have said why in one line per rank.
"""
import os
import sys

from tfcheck import Checks, args

tf, mpirun, src = args()
sys.path.insert(0, os.path.join(src, "scripts"))
import extremes  # noqa: E402

k = Checks("extremes")
outdir = os.path.join(os.getcwd(), "extremes")
os.makedirs(outdir, exist_ok=True)
for name, extra in extremes.CASES:
    if name not in ("mu 0", "nu 0.499", "mesh 1x8", "deps 0.05"):
        continue
    r = extremes.run_case(name, extra, outdir, exe=tf, mpirun=mpirun)
    ok, why = extremes.acceptable(r)
    k.check(ok and r["status"] == "done", f"{name}: {r['status']} in {r['wall']:.0f} s, finite {r['finite']}, "
            f"(a) {r.get('a', float('nan')):.2%}, (b) {r.get('b', float('nan')):.2%} {why}")
k.done()
