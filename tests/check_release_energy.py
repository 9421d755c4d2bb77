"""Contact forces the tool stops carrying are unloaded, not dropped
(docs/theory.md, "Releases"): the thin tube (aluminum 18.5/0.5) at mu 0.35 on
the default preset, 4 x 96, loading only. Its nodes at the edge of the flank
contact graze the tool: held for a step, some end it in tension and are
released. A released force that is dropped stays in the body as an
out-of-balance force the method never corrects, and its work leaks out of the
energy balance increment after increment (before the fix: 2.2 % at 400 trial
increments, 4.7 % at 1000, 13 % at 3000, and P(3 mm) 21.2, 22.4, 32.0 N/mm).

- (a) energy balance (press work from the reported load against internal
  work + friction + inertia work) within 1 % with 400 and with 1500 trial
  increments: the default case balances within 0.9 % at 400; a leak of
  released forces reached 2.2 % at 400 and grows with the increments;
- the balance error falls with the step (1500 below 400): a first-order
  method's error does, a leak per release does not;
- the load at U = 2 and 3 mm within 1 % between 400 and 1500 increments (a
  leak moved P(3) by 6 % between 400 and 1000; the load converges in the
  steps to well within 1 % where nothing leaks);
- 1 vs 2 ranks, 400 increments, up to U = 3 mm (before the wall collapses):
  load within 1e-6 and C/t within 7e-8 of the largest value (measured with
  MUMPS 7.4e-9 and 6.5e-10 on OpenBLAS Haswell, 1.7e-8 and 7.0e-10 on
  SkylakeX: at most 100 times; with PETSc's LU 3.5e-8 and 1.4e-9): pending
  forces live on owned nodes and are summed once.
These are the paper's forward increments (-equilibrium_tol 0), the only ones
that carry released forces as pending loads. With the default equilibrium
iterations a release is balanced inside its step: the same case at the
preset's own increments keeps (a) within 1 % and the out-of-balance of every
committed state within the criterion R_max <= 0.005 q_avg (the accepted
iterate's own reactions are checked for pulled nodes, so no node is left to
be released at the commit; before that check the committed state read up to
0.0069 q and this bound was 0.01 q). Measured 0.00499 q.
"""
import h5py
import numpy as np

from tfcheck import Checks, args, out, run, run_all

tf, mpirun, src = args()
k = Checks("release_energy")

CASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-default.opts",
        "-tube_ro", 18.5, "-tube_t", 0.5, "-friction_mu", 0.35, "-mesh_ntheta", 96, "-unload", "none",
        "-output_every", 100000, "-output_stroke", 0, "-error_estimate", 0]


def opts(np_, increments, paper=True):
    return CASE + ["-output", out(f"release_np{np_}_{increments}.h5")] + (["-equilibrium_tol", 0, "-increments",
                                                                           increments] if paper else [])


def read(np_, increments):
    with h5py.File(out(f"release_np{np_}_{increments}.h5"), "r") as h:
        return {c: h["/history"][c][:] for c in ("stroke", "load", "c_over_t", "energy_error", "r_max", "q_avg")}


def at(H, U):
    return float(np.interp(U, H["stroke"], H["load"]))


# The single-rank runs two at a time (the longest first), then the 2-rank one.
run_all(tf, mpirun, [opts(1, 1500), opts(1, 400), opts(1, 0, paper=False)], timeout=600)
run(tf, mpirun, 2, opts(2, 400), timeout=600)
coarse, fine, two = read(1, 400), read(1, 1500), read(2, 400)
err = {}
for n, H in ((400, coarse), (1500, fine)):
    err[n] = np.abs(H["energy_error"][H["stroke"] > 0.1]).max()
    k.check(err[n] < 0.01, f"{n} trial increments: (a) energy balance within {err[n]:.2%} < 1 %")
k.check(err[1500] < err[400], f"(a) falls with the step: {err[400]:.2%} at 400, {err[1500]:.2%} at 1500")
for U in (2.0, 3.0):
    d = abs(at(fine, U) / at(coarse, U) - 1)
    k.check(d < 0.01, f"P({U:g} mm) {at(coarse, U):.3f} at 400, {at(fine, U):.3f} at 1500: {d:.2%} < 1 %")
# Compared at the 1-rank run's strokes up to U = 3 mm: past it the wall
# between the flanks collapses (C/t 0.08 -> 0.4), an unstable path on which
# the order of summation shows (2 ranks: 6.6e-4 of C/t's largest value at
# 4.2 mm, measured when this check was written), so no tolerance there would
# be a statement about the parallel code rather than about the collapse.
m = coarse["stroke"] <= 3.0
for c, tol in (("load", 1e-6), ("c_over_t", 7e-8)):
    other = np.interp(coarse["stroke"][m], two["stroke"], two[c])
    d = np.abs(coarse[c][m] - other).max() / np.abs(coarse[c][m]).max()
    k.check(d < tol, f"1 vs 2 ranks to U = 3 mm: {c} within {d:.1e} < {tol:g} of its largest value")
eq = read(1, 0)
e = np.abs(eq["energy_error"][eq["stroke"] > 0.1]).max()
on = eq["q_avg"] > 0
r = (eq["r_max"][on] / eq["q_avg"][on]).max()
k.check(e < 0.01 and r <= 0.005 * (1 + 1e-12), f"equilibrium increments: (a) within {e:.2%} < 1 %, R_max / q_avg at "
        f"most {r:.5f} (0.005)")
k.done()
