"""Squaring, aluminum 17.5/1.5, mu = 0.05 (options/squaring.opts, inertia at
1 mm/s), with the paper's springback. Every check compares quantities
computed independently of each other (docs/theory.md, "Self-checks").

A. The default increments (equilibrium iterations, R_max <= 0.005 q), on 1
   and 2 ranks:
  - (a) energy balance: the press's work from the reported punch load,
    1/2 integral of load dU for the quarter, against internal work (stresses)
    + friction dissipation (contact slips) + inertia work (kinetic energy +
    the energy backward Euler damps, from the accelerations), within 0.5 % at
    every increment (measured 0.15 %; friction alone is 4.9 % of the work, so
    a lost term would fail). (a) and (b) are recomputed here from the load,
    stroke and w_* columns (tfcheck.self_checks; in the paper's unloading the
    work of the reversed loads at the nodes is w_ext - w_tool), not read from
    the run's energy_error and internal_error; those columns and w_tool must
    equal the recomputation within 1e-10 (tfcheck.COLUMN_TOL: the same sums
    in another order; measured 2e-16), so a wrong column cannot hide a
    balance, nor a right balance a wrong column;
  - (b) internal work against plastic dissipation + stored elastic energy
    within 0.5 % (measured 0.40 % at 300 trial increments: first order in the
    step, 0.61 % at 150 and 0.20 % at 600; the midpoint update takes the work
    in the constitutive frame);
  - (c) the damped energy below 1e-6 of the work at the end and the kinetic
    energy below 1e-6 of the work at every increment (measured 1.1e-8 and
    3.6e-7 at the first increment, where the punch starts at full speed): at
    a press speed the tube moves quasi-statically (a snap shows 4e-3);
  - equilibrium: every increment's largest out-of-balance force R_max within
    0.005 q_avg (the criterion, checked from the history's own columns);
    no contact node ends a step in tension, and no release drops a force,
    beyond 0.005 q_avg (contact forces below that are zero at this
    tolerance: measured 4.4e-4 q and 4.9e-3 q); penetration below 1e-4 mm
    (measured 8.9e-6 mm on the apex fillet: the constraint is linear in a
    step accepted with a residual, and its error is the slip squared over
    the fillet radius);
  - no compromise: every step's iterations settled and every loading state
    consistent with its solution;
  - 1 vs 2 ranks (each deterministic: parallel_determinism_np2): load, C1,
    C2, C/t and external work at the same strokes within 1.3e-8 relative up
    to U = 2.6 mm (100 x the largest measured before equilibrium, 1.3e-10 on
    OpenBLAS Haswell; with it 1.6e-13), and 3e-5 beyond, where the wall
    collapses and the path amplifies round-off (a perturbation of 1.3e-13 in
    E moves load and C/t by up to 3.3e-6 there; ten times that). A missing or
    doubled contribution at the partition boundary would show at 1e-2.
B. The paper's forward increments (-equilibrium_tol 0, every onset located
   by r1: 8,200 increments), 1 rank: (a) within 0.5 % (measured 0.23 %), (b)
   within 0.3 % (0.13 %), no penetration beyond 1e-6 mm (1.0e-7), no tension
   and no released force beyond 1e-6 of the largest load (9.9e-5 and 6.2e-6
   N/mm against 3e-4). Consistency, not verification: -rmin_yield inside
   converges to that path (the code's own result, not an independent
   reference): at 1,000 trial increments load within 0.5 % and C/t within
   0.01, at 300 at least twice as far; on 2 ranks at 300 within 2.7e-7.
   B's runs on 1 rank factor with KLU (-factorization klu): what B checks is
   the method's path, which does not depend on the LU (KLU's and MUMPS's
   paper runs agree within 1.1e-6 of the largest load along the stroke,
   8,214 and 8,218 increments: round-off moves where a few onsets land;
   their printed self-checks and results are the same), and its 49,000
   factorizations of 1,310 dofs are most of the test's time, where KLU's
   per-call cost is lower than MUMPS's (docs/performance.md,
   "Factorization"; the first 1.5 mm of the paper run with -log_view: 0.63 x
   MUMPS's time). The 2-rank runs and C (MUMPS's determinant) keep MUMPS.
C. mu = 0: the problem is symmetric about the 45-degree line while no node
   touches the apex fillet. The symmetric path is a solution until the
   tangent stiffness loses its definiteness on the symmetric branch: the
   sign of its determinant (MUMPS, -redundant_mat_mumps_icntl_33 1) flips at
   a bifurcation. Before the first flip (after the first increment) C1/C2 = 1
   within 1e-8 (measured 1e-10: round-off grows only after the flip); the
   flip itself must come before the deviation passes 1e-6, i.e. the
   asymmetry is the bifurcation located independently by the determinant,
   not a drift of the method; beyond it the deviation is reported.
Two tests run it (tests/CMakeLists.txt), by the part given after the source directory: `ranks`, A and B's 2-rank
comparison (the runs on 2 ranks: both of the machine's cores), and `paper`, the rest of B and C (one rank: its
8,200-increment run would leave the second core idle); with neither, all of it.
"""
import sys

import h5py
import numpy as np

from tfcheck import COLUMN_TOL, Checks, args, column_gap, out, run, run_all, self_checks

tf, mpirun, src = args()
part = sys.argv[4] if len(sys.argv) > 4 else "all"
k = Checks(f"squaring ({part})")
RANKS, PAPER_PART = part in ("ranks", "all"), part in ("paper", "all")


def opts(name, extra):
    return ["-options_file", f"{src}/options/squaring.opts", "-error_estimate", 0, "-output", out(name),
            "-output_every", 100000] + extra


def read(name):
    with h5py.File(out(name), "r") as h:
        return {c: h["/history"][c][:] for c in h["/history"]}


def history(n, name, extra):
    run(tf, mpirun, n, opts(name, extra), timeout=900)
    return read(name)


PAPER = ["-equilibrium_tol", 0]
KLU = ["-factorization", "klu"]  # B's 1-rank runs (docstring: the path does not depend on the LU)


def inside(n):
    """-rmin_yield inside on the paper's increments, n trial increments, loading only."""
    return PAPER + ["-rmin_yield", "inside", "-increments", n, "-unload", "none"]


grid = np.linspace(0.2, 4.2, 41)


def energy_checks(h, label, b_tol):
    w = np.maximum(np.abs(h["w_ext"]), 1e-300)
    a, b, tool = self_checks(h)
    e, at = np.abs(a).max(), np.abs(a).argmax()
    k.check(e < 5e-3, f"{label}: (a) press work from the reported load and stroke = internal + friction + inertia "
            f"work within {e:.2e} (5e-3), recomputed from the history (worst at U = {h['stroke'][at]:.3f})")
    i = np.abs(b).max()
    k.check(i < b_tol, f"{label}: (b) internal work = plastic + elastic energy within {i:.2e} ({b_tol:g}), "
            f"recomputed")
    gap, col = column_gap(h, a, b, tool)
    k.check(gap <= COLUMN_TOL, f"{label}: the run's energy_error, internal_error and w_tool columns equal the "
            f"recomputed (a), (b) and press work within {gap:.1e} ({col}) ({COLUMN_TOL:g})")
    damped, kinetic = abs(h["w_damped"][-1]) / w[-1], (h["w_kinetic"] / w).max()
    k.check(damped < 1e-6 and kinetic < 1e-6,
            f"{label}: (c) damped energy {damped:.1e} of the work, kinetic at most {kinetic:.1e} (1e-6)")


if RANKS:
    # A. The default increments, 1 and 2 ranks (the single-rank runs side by side: B's at 300 increments too).
    run_all(tf, mpirun, [opts("squaring_np1.h5", []), opts("squaring_inside_300.h5", inside(300))], timeout=900)
    H = {1: read("squaring_np1.h5"), 2: history(2, "squaring_np2.h5", [])}
    h = H[1]
    load_stage = h["stage"] == 0
    energy_checks(h, "equilibrium", 5e-3)
    q = np.maximum(h["q_avg"], 1e-300)
    loaded = h["q_avg"] > 0
    k.check(loaded.sum() > 100 and (h["r_max"][loaded] / q[loaded]).max() <= 0.005 * (1 + 1e-12),
            f"every increment in balance: R_max / q_avg at most {(h['r_max'][loaded] / q[loaded]).max():.5f} (0.005)")
    k.check(h["penetration"].max() <= 1e-4, f"equilibrium: largest penetration {h['penetration'].max():.1e} mm (1e-4)")
    k.check((h["tension"] / q).max() <= 0.005 and (h["release_force"] / q).max() <= 0.005,
            f"equilibrium: largest tensile contact force before release {(h['tension'] / q).max():.1e} q_avg, force "
            f"dropped by a release {(h['release_force'] / q).max():.1e} q_avg (0.005)")
    k.check(all(H[n]["unsettled"][-1] == 0 and H[n]["inconsistent"][-1] == 0 for n in (1, 2)),
            "no unsettled step, no inconsistent loading state on 1 and 2 ranks")
    before = grid <= 2.6
    EARLY = 1.3e-8  # 100 x the largest 1 vs 2 rank difference measured up to U = 2.6 mm (docstring, A)
    for col in ("load", "x_max", "y_max", "c_over_t", "w_ext"):
        curves = [np.interp(grid, H[n]["stroke"][H[n]["stage"] == 0], H[n][col][H[n]["stage"] == 0]) for n in (1, 2)]
        rel = np.abs(curves[0] - curves[1]) / np.abs(curves[0]).max()
        k.check(rel[before].max() < EARLY and rel.max() < 3e-5,
                f"1 vs 2 ranks, {col}(U): {rel[before].max():.1e} relative up to U = 2.6 mm ({EARLY:g}), "
                f"{rel.max():.1e} to 4.2 mm (3e-5)")
    for col in ("x_max", "y_max", "c_over_t"):
        rel = abs(H[1][col][-1] - H[2][col][-1]) / max(abs(H[1][col][-1]), 1e-12)
        k.check(rel < 3e-5, f"1 vs 2 ranks after springback, {col}: {rel:.1e} (3e-5)")
    print(f"       U = 4.2: load {np.interp(4.2, h['stroke'][load_stage], h['load'][load_stage]):.2f} N/mm, "
          f"C/t {h['c_over_t'][load_stage][-1]:.3f}, C1/C2 {h['deviation_ratio'][load_stage][-1]:.4f}; "
          f"after springback C/t {h['c_over_t'][-1]:.3f}, C1/C2 {h['deviation_ratio'][-1]:.4f}")
    # B on 2 ranks: -rmin_yield inside at 300 increments within 2.7e-7 relative over the whole stroke (100 x the
    # measured 2.7e-9 on OpenBLAS Haswell, 6.2e-10 on SkylakeX); a missing or doubled contribution at the
    # partition boundary would show at 1e-2.
    hi, h2 = read("squaring_inside_300.h5"), history(2, "squaring_inside_300_np2.h5", inside(300))
    rel = max(np.abs(np.interp(grid, hi["stroke"], hi[c]) - np.interp(grid, h2["stroke"], h2[c])).max()
              / np.abs(hi[c]).max() for c in ("load", "c_over_t"))
    k.check(rel < 2.7e-7, f"-rmin_yield inside, 1 vs 2 ranks: load and C/t within {rel:.1e} (2.7e-7)")

if PAPER_PART:
    # B. The paper's forward increments, 1 rank, and -rmin_yield inside against them, factored by KLU (docstring).
    p = history(1, "squaring_paper.h5", PAPER + KLU)
    energy_checks(p, "paper's increments", 3e-3)
    top = p["load"].max()
    k.check(p["penetration"].max() <= 1e-6,
            f"paper's increments: largest penetration {p['penetration'].max():.1e} mm (1e-6)")
    k.check(p["tension"].max() <= 1e-6 * top and p["release_force"].max() <= 1e-6 * top,
            f"paper's increments: largest tensile contact force before release {p['tension'].max():.1e} N/mm, force "
            f"dropped by a release {p['release_force'].max():.1e} N/mm (1e-6 of the largest load, {top:.0f} N/mm)")
    ps = p["stage"] == 0
    ref = {c: p[c][ps] for c in ("stroke", "load", "c_over_t")}
    err = {}
    for n in (300, 1000):
        hi = history(1, f"squaring_inside_{n}.h5", inside(n) + KLU)
        dp = max(abs(np.interp(U, hi["stroke"], hi["load"]) / np.interp(U, ref["stroke"], ref["load"]) - 1)
                 for U in (1, 2, 3, 4.2))
        dc = max(abs(np.interp(U, hi["stroke"], hi["c_over_t"]) - np.interp(U, ref["stroke"], ref["c_over_t"]))
                 for U in (2, 3, 4.2))
        err[n] = dp
        if n == 1000:
            ea, eb = (np.abs(c).max() for c in self_checks(hi)[:2])
            k.check(dp < 5e-3 and dc < 0.01 and ea < 5e-3 and eb < 3e-3,
                    f"consistency: -rmin_yield inside, {n} increments ({len(hi['stroke']) - 1} taken): load within "
                    f"{dp:.1e} (5e-3), C/t within {dc:.3f} (0.01) of the onset run; self-checks (a) {ea:.1e}, "
                    f"(b) {eb:.1e}")
    k.check(err[300] > 2 * err[1000], f"consistency: -rmin_yield inside converges to the onset run: load difference "
            f"{err[300]:.1e} at 300, {err[1000]:.1e} at 1000")

    # C. mu = 0: symmetric until the determinant of the tangent changes sign.
    h0 = history(1, "squaring_mu0.h5", ["-friction_mu", 0, "-unload", "none", "-redundant_mat_mumps_icntl_33", 1])
    free = np.cumsum(h0["n_contact_apex"]) == 0
    dev = np.abs(h0["deviation_ratio"] - 1)
    sign = h0["det_sign"]
    k.check((sign[1:] != 0).all(), "mu = 0: MUMPS reports the determinant's sign in every increment")
    flips = np.nonzero((sign[2:] != sign[1:-1]) & (sign[1:-1] != 0))[0] + 2
    first = h0['stroke'][flips[0]] if len(flips) else float('nan')
    if k.check(len(flips) > 0 and free[flips[0]], f"mu = 0: the tangent's determinant changes sign before apex contact "
               f"({len(flips)} changes, the first at U = {first:.4f})"):
        f0 = flips[0]
        k.check(f0 > 10 and dev[1:f0].max() < 1e-8, f"mu = 0: symmetric before the first sign change: |C1/C2 - 1| <= "
                f"{dev[1:f0].max():.1e} over {f0 - 1} increments (1e-8)")
        past = np.nonzero(dev > 1e-6)[0]
        k.check(len(past) == 0 or past[0] >= f0, f"mu = 0: the deviation passes 1e-6 only after the bifurcation "
                f"(at U = {h0['stroke'][past[0]] if len(past) else float('nan'):.4f}; sign change at "
                f"{h0['stroke'][f0]:.4f})")
    print(f"       mu = 0: |C1/C2 - 1| up to U = 4.2 (apex contact: {'yes' if (~free).any() else 'no'}): "
          f"{dev[free].max():.1e}")
k.done()
