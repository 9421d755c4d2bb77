"""The pressure scene on 1 and 2 ranks gives the same result.

MUMPS factorizes in a different order on 2 ranks, so the results agree to
round-off (~1e-14 seen), not bitwise; the tolerance 1e-10 relative leaves
four orders of margin while catching any missing or double-counted
contribution at the partition boundary (which would be O(1e-2) or more).
Vertex order in the files differs between rank counts: nodes are matched by
their initial coordinates.
"""
import numpy as np

from tfcheck import Checks, args, load, out, run

tf, mpirun, src = args()
k = Checks("parallel")
res = {}
for n in (1, 2):
    out_ = f"par_np{n}.h5"
    run(tf, mpirun, n, ["-options_file", f"{src}/options/pressure.opts", "-increments", 4, "-output", out(out_), "-history_csv", out(f"par_np{n}.csv")])
    d = load(out_)
    order = np.lexsort((d["X"][:, 1].round(10), d["X"][:, 0].round(10)))
    corder = np.lexsort((d["X"][d["cells"]].mean(1)[:, 1].round(10), d["X"][d["cells"]].mean(1)[:, 0].round(10)))
    res[n] = (d["X"][order], d["U"][order], d["sigma_xx"][corder], d["history"])
x1, u1, s1, h1 = res[1]
x2, u2, s2, h2 = res[2]
k.check(np.array_equal(x1, x2), "same nodes on 1 and 2 ranks")
du = np.abs(u1 - u2).max() / np.abs(u1).max()
ds = np.abs(s1 - s2).max() / np.abs(s1).max()
k.check(du < 1e-10, f"displacement agrees: {du:.2e} relative")
k.check(ds < 1e-10, f"cell stress agrees: {ds:.2e} relative")
for col in ("stroke", "load", "w_ext", "w_int", "w_elastic", "x_max", "y_max"):
    a, b = h1[col], h2[col]
    rel = np.abs(a - b).max() / max(np.abs(a).max(), 1e-300)
    k.check(rel < 1e-10, f"history column {col} agrees: {rel:.2e} relative")
k.done()
