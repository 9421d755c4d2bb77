"""Two runs of one commit give the same result, bit for bit, at 2 ranks.

The default squaring scene (inertia at 1 mm/s, friction) pressed to
U = 1.5 mm twice on 2 ranks: every history column must be bitwise equal.
Reference: the run itself. What can fail: any order of floating-point
operations that depends on timing. MUMPS's distributed factorization is one
(dynamic scheduling): with -pc_type lu -pc_factor_mat_solver_type mumps,
three pairs of such runs differed from increment 37, 307 and 285 (measured
when the redundant sequential factorization became the default); the default
solver (options/solver.opts) must not.
"""
import h5py
import numpy as np

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
k = Checks("determinism")
H = []
for rep in (1, 2):
    f = out(f"determinism_{rep}.h5")
    run(tf, mpirun, 2, ["-options_file", f"{src}/options/squaring.opts", "-stroke", 1.5, "-unload", "none",
                        "-output", f, "-output_every", 100000])
    with h5py.File(f, "r") as h:
        H.append({c: h["/history"][c][:] for c in h["/history"]})
a, b = H
na, nb = len(a["stroke"]) - 1, len(b["stroke"]) - 1
k.check(na == nb, f"same number of increments ({na}, {nb})")
n = min(len(a["stroke"]), len(b["stroke"]))
differ = [c for c in a if not np.array_equal(a[c][:n], b[c][:n])]
k.check(not differ, "every history column bitwise equal" + (": " + ", ".join(differ) if differ else ""))
k.done()
