"""Two runs of one commit give the same result, bit for bit, at 2 ranks.

The default squaring scene (inertia at 1 mm/s, friction) pressed to
U = 1.5 mm twice on 2 ranks, without the error estimate (whose companions
would take the second rank: docs/accuracy.md), every history column must be bitwise equal.
Reference: the run itself. What can fail: any order of floating-point
operations that depends on timing. MUMPS's distributed factorization is one
(dynamic scheduling): with -pc_type lu -pc_factor_mat_solver_type mumps,
three pairs of such runs differed from increment 37, 307 and 285 (measured
when the redundant sequential factorization became the default); the default
solver (options/solver.opts) must not.

The same with -factorization klu (KLU where every rank factors the whole
matrix): its pair bitwise equal too, the "linear solver:" line naming KLU
(planted: the option ignored -> MUMPS named, FAILED), and its loads at
U = 0.5, 1, 1.5 mm within 1e-4 (relative) of MUMPS's: the two solve the same
systems and differ in round-off (1e-13 measured), which could at most move
an event within the r_min location tolerance (1e-2 of a step: about 1e-4 of
the load).
"""
import h5py
import numpy as np

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
k = Checks("determinism")

def pair(factorization):
    """Two 2-rank runs with this factorization: their histories."""
    H = []
    for rep in (1, 2):
        f = out(f"determinism_{factorization}_{rep}.h5")
        said = run(tf, mpirun, 2, ["-options_file", f"{src}/options/squaring.opts", "-stroke", 1.5, "-unload", "none",
                                   "-output", f, "-output_every", 100000, "-factorization", factorization, "-monitor",
                                   "-error_estimate", 0])
        line = [x for x in said.stdout.splitlines() if "linear solver:" in x]
        k.check(line and factorization.upper() + " LU" in line[0], f"{factorization}: the solver line names it: {line}")
        with h5py.File(f, "r") as h:
            H.append({c: h["/history"][c][:] for c in h["/history"]})
    a, b = H
    na, nb = len(a["stroke"]) - 1, len(b["stroke"]) - 1
    k.check(na == nb, f"{factorization}: same number of increments ({na}, {nb})")
    n = min(len(a["stroke"]), len(b["stroke"]))
    differ = [c for c in a if not np.array_equal(a[c][:n], b[c][:n])]
    k.check(not differ, f"{factorization}: every history column bitwise equal" + (": " + ", ".join(differ) if differ else ""))
    return a


mumps, klu = pair("mumps"), pair("klu")
for u in (0.5, 1.0, 1.5):
    pm, pk = (np.interp(u, h["stroke"], h["load"]) for h in (mumps, klu))
    k.check(abs(pk - pm) <= 1e-4 * abs(pm), f"U = {u}: KLU's load {pk:.9g} within 1e-4 of MUMPS's {pm:.9g}")
k.done()
