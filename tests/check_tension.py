"""Homogeneous plane-strain tension/compression (options/tension.opts) for
each hardening law: Ludwik (aluminum n = 0.927, linear n = 1, n = 0.1),
Swift, a table, perfect plasticity, and compression.

1. With -drift_correction: sigma_xx against the rate problem itself, solved
   here independently of the code: plane strain (d_zz = 0), sigma_yy = 0,
   logarithmic strain ln(1 + e) for the nominal strain e, J2 flow with the
   law's hardening, Cauchy stress with the Kirchhoff term -sigma tr(de),
   integrated by backward-Euler radial return in substeps between the
   solver's own strokes (no interpolation across the yield kink) and
   Richardson-extrapolated over 10 and 20 substeps per stroke interval
   (accurate to ~3e-7: the same with 5k/10k and 80k/160k steps over the
   path). The drift correction only puts sbar back on sigma_y(ep); whether ep
   and the stress direction follow the flow rule is what this checks. The
   tangent update is first order in the increment, with a constant that grows
   with the initial hardening slope (errors at 100 and 200 increments,
   measured when this test was written: aluminum 1.7e-3, 7.2e-4; Ludwik
   n = 0.1 2.9e-2, 1.45e-2; Swift 7.3e-3, 4.1e-3; compression 2.0e-3,
   1.0e-3). The same holds with -rmin_yield inside, where the step that
   crosses the yield surface is not cut but split at the onset. So the test
   is convergence: for every law the error falls by at
   least 1.6 from 100 to 200 increments (first order: 2; a wrong limit would
   give ~1; measured 1.81-2.39), and stays below 1.3 times its own measured
   value at 200 (the bounds beside the cases: a discretization error, the
   same on every OpenBLAS kernel tried). Past a
   few hundred increments the paths level off 2e-4 (tension) to 7e-4
   (compression, 10 % strain) from this reference: the plastic step solves
   its consistency condition without the Kirchhoff-to-Cauchy term
   -sigma tr(de), so sbar drifts by the elastic volume change of the plastic
   path (p/K ~ 7e-4 there); docs/verification.md, "Tension".
Items 1 and 2 test the paper's forward increments (-equilibrium_tol 0).
3. The default equilibrium increments (the update a function of the strain
   increment, midpoint kinematics): sigma_xx against the same reference at 50
   and 100 increments, within 1.3 x the value measured at 100 (bounds beside
   the cases below).
2. Without correction: sbar against sigma_y(ep) evaluated here from the law's
   formula. The tangent update leaves sbar off the curve where the path turns
   (the elastic-plastic transition) by a first-order amount (aluminum: 1.5 %,
   0.2 %, 0.03 % at 50, 200, 800 increments); at 400 it must stay below 0.5 %.
4. -plastic_update radial with the equilibrium increments of item 3, balanced
   to -equilibrium_tol 1e-9: sbar on sigma_y(ep) (below 1e-6; round-off but
   for n = 0.1's first steps), and sigma_xx against the same reference at 50
   and 100 increments within 1.3 x the values measured so and below half
   the tangent update's error of item 3 (measured: aluminum 1.18e-3,
   6.5e-4 against 6.9e-3, 2.8e-3; compression 1.15e-3, 6.4e-4 against
   7.3e-3, 4.1e-3: first order). At the default tolerance the accepted
   iterates move the load by up to 3.2e-4 of its largest value near the
   yield onset, which hid the order (8.6e-4, 8.1e-4) and made the errors
   depend on the corrections' path.
   With the paper's forward increments (-equilibrium_tol 0) it is worse than
   the tangent update (aluminum 2.3e-2 at 100: the update is not the
   tangent's linearization and nothing balances the difference).
5. -plastic_update auto names the return with equilibrium increments and the
   tangent update with the paper's forward ones (aluminum, 50 increments):
   the load history bit for bit that of the update it names, and not the
   other's (the two differ by 1e-3 of the load here, item 4).
"""
import math

import h5py
import numpy as np

from tfcheck import Checks, args, out, run
from uniaxial import stress_path

tf, mpirun, src = args()
k = Checks("tension")
E, NU = 75000.0, 0.34
table = [(0.0, 165.0), (0.01, 200.0), (0.05, 240.0)]


def table_sy(ep):
    return float(np.interp(ep, [e for e, _ in table], [s for _, s in table]))


def table_h(ep):
    for (e0, s0), (e1, s1) in zip(table, table[1:]):
        if ep < e1:
            return (s1 - s0) / (e1 - e0)
    return 0.0


def ludwik(sy0, K, n):
    return (lambda ep: sy0 + K * max(ep, 0.0) ** n), (lambda ep: K * n * max(ep, 1e-12) ** (n - 1))


def swift(sy0, K, n):
    e0 = (sy0 / K) ** (1 / n)
    return (lambda ep: K * (e0 + max(ep, 0.0)) ** n), (lambda ep: K * n * (e0 + max(ep, 0.0)) ** (n - 1))


def reference(strokes, sy, hp, sub):
    """sigma_xx at the nominal strains `strokes` (starting at 0), `sub` substeps per interval (tests/uniaxial.py)."""
    G = E / (2 * (1 + NU))
    lam = E * NU / ((1 + NU) * (1 - 2 * NU))

    def update(state, dxx, dyy):
        s, ep = state
        tr = dxx + dyy
        trial = [si + lam * tr + 2 * G * di - si * tr for si, di in zip(s, (dxx, dyy, 0.0))]
        mean = sum(trial) / 3
        dev = [t - mean for t in trial]
        q = math.sqrt(1.5 * sum(d * d for d in dev))
        if q <= sy(ep):
            return tuple(trial), ep
        dep = 0.0  # radial return: q - 3G dep = sy(ep + dep)
        for _ in range(60):
            f = q - 3 * G * dep - sy(ep + dep)
            dep += f / (3 * G + hp(ep + dep))
            if abs(f) < 1e-13 * q:
                break
        return tuple(mean + d * (1 - 3 * G * dep / q) for d in dev), ep + dep

    return stress_path(strokes, sub, update, ((0.0, 0.0, 0.0), 0.0), lambda st: st[0][0], lambda st: st[0][1])


def solve(extra, n, paper=True):
    f = out("tension.h5")
    run(tf, mpirun, 1, ["-options_file", f"{src}/options/tension.opts", "-increments", n, "-rmin_deps", 0.5,
                        "-output", f] + extra + (["-equilibrium_tol", 0] if paper else []))
    with h5py.File(f, "r") as h:
        H = {c: h["/history"][c][:] for c in ("stroke", "load")}
        vm = h["/cell_fields/von_mises_c"][:].mean(axis=1)
        ep = h["/cell_fields/eps_p_c"][:].mean(axis=1)
    return H, vm, ep


# Each case with the bound on its error at 200 increments: 1.3 x the value measured (the same to 4 digits on
# OpenBLAS Haswell and SkylakeX: a first-order discretization error, not round-off), so that a defect raising
# one law's error by a third fails; the former common 2e-2 let aluminum's (7.2e-4) grow 28-fold.
cases = [
    ("ludwik aluminum", [], ludwik(165.3, 673.5, 0.927), 9.4e-4),  # measured 7.17e-4
    ("ludwik n=1", ["-material_n", 1], ludwik(165.3, 673.5, 1.0), 1.4e-3),  # 1.05e-3
    ("ludwik n=0.1", ["-material_n", 0.1], ludwik(165.3, 673.5, 0.1), 1.9e-2),  # 1.45e-2
    ("perfectly plastic", ["-material_k", 0], (lambda ep: 165.3, lambda ep: 0.0), 2.1e-3),  # 1.56e-3
    ("swift", ["-material_law", "swift", "-material_k", 500, "-material_n", 0.2], swift(165.3, 500.0, 0.2),
     5.3e-3),  # 4.07e-3
    ("table", ["-material_law", "table", "-material_table", ",".join(f"{e},{s}" for e, s in table)],
     (table_sy, table_h), 3.3e-3),  # 2.52e-3
    ("compression", ["-tension_strain", -0.1], ludwik(165.3, 673.5, 0.927), 1.4e-3),  # 1.04e-3
    # Points yield inside a step (the increment is not cut at the onset): the
    # same reference and the same convergence.
    ("yield inside, aluminum", ["-rmin_yield", "inside"], ludwik(165.3, 673.5, 0.927), 5.7e-3),  # 4.35e-3
    ("yield inside, n=0.1", ["-rmin_yield", "inside", "-material_n", 0.1], ludwik(165.3, 673.5, 0.1),
     1.3e-2),  # 9.97e-3
]
for name, extra, (sy, hp), bound in cases:
    # 1. Drift-corrected stress path against the rate problem, at 100 and 200 increments.
    errors = {}
    for n in (100, 200):
        H, _, _ = solve(extra + ["-drift_correction"], n)
        e = H["stroke"]
        ref = 2 * reference(e, sy, hp, 20) - reference(e, sy, hp, 10)
        errors[n] = np.abs(H["load"][1:] - ref[1:]).max() / np.abs(ref).max()
    k.check(errors[100] / errors[200] > 1.6 and errors[200] < bound,
            f"{name} (drift correction): sigma_xx against the rate problem, error {errors[100]:.1e} -> "
            f"{errors[200]:.2e} from 100 to 200 increments (ratio {errors[100] / errors[200]:.2f} > 1.6; < {bound:g})")
    # 2. Without correction: how far sbar drifts off the law's curve.
    _, vm, ep = solve(extra, 400)
    m = ep > 0
    drift = max(abs(v / sy(x) - 1) for v, x in zip(vm[m], ep[m]))
    k.check(m.sum() > 100 and drift < 5e-3,
            f"{name}: max |sbar / sigma_y(ep) - 1| = {drift:.1e} < 5e-3, ep(end) = {ep[-1]:.4f}")

# 3. Equilibrium increments: the error against the rate problem at 50 and 100 increments.
tangent_error = {}
# Bounds: 1.3 x the error measured at 100 (at 50: 6.9e-3, 1.27e-3, 7.3e-3; the largest error sits in the knee
# of the curve, first order; n = 0.1 is near the 2e-4..7e-4 floor of item 1 already at 50).
for name, extra, (sy, hp), bound in [("aluminum", [], ludwik(165.3, 673.5, 0.927), 3.7e-3),  # measured 2.79e-3
                                     ("n=0.1", ["-material_n", 0.1], ludwik(165.3, 673.5, 0.1), 1.3e-3),  # 9.64e-4
                                     ("compression", ["-tension_strain", -0.1], ludwik(165.3, 673.5, 0.927),
                                      5.3e-3)]:  # 4.08e-3
    err = tangent_error[name] = {}
    for n in (50, 100):
        H, _, _ = solve(extra, n, paper=False)
        e = H["stroke"]
        ref = 2 * reference(e, sy, hp, 20) - reference(e, sy, hp, 10)
        err[n] = np.abs(H["load"][1:] - ref[1:]).max() / np.abs(ref).max()
    k.check(err[100] < err[50] and err[100] < bound, f"equilibrium increments, {name}: sigma_xx against the rate problem, "
            f"error {err[50]:.2e} -> {err[100]:.2e} from 50 to 100 increments (falls; < {bound:g})")

# 4. The radial return with equilibrium increments: on the yield surface, and against the rate problem. Balanced to
# -equilibrium_tol 1e-9, so that the error is the update's alone: at the default tolerance the accepted iterates
# move the load by up to 3.2e-4 of its largest value at the yield onset (50 increments), which is the order of the
# margins here and depends on the corrections' path. Bounds: 1.3 x the errors measured so, per increment count
# (first order: about half at 100).
for name, extra, (sy, hp), bound in [("aluminum", [], ludwik(165.3, 673.5, 0.927), {50: 1.5e-3, 100: 8.5e-4}),
                                     # measured 1.18e-3, 6.51e-4
                                     ("compression", ["-tension_strain", -0.1], ludwik(165.3, 673.5, 0.927),
                                      {50: 1.5e-3, 100: 8.3e-4})]:  # 1.15e-3, 6.38e-4
    for n in (50, 100):
        H, vm, ep = solve(extra + ["-plastic_update", "radial", "-equilibrium_tol", 1e-9], n, paper=False)
        e = H["stroke"]
        ref = 2 * reference(e, sy, hp, 20) - reference(e, sy, hp, 10)
        err = np.abs(H["load"][1:] - ref[1:]).max() / np.abs(ref).max()
        m = ep > 0
        drift = max(abs(v / sy(x) - 1) for v, x in zip(vm[m], ep[m]))
        k.check(m.sum() > 10 and drift < 1e-6 and err < bound[n] and err < 0.5 * tangent_error[name][n],
                f"radial return, {name}, {n} equilibrium increments: |sbar / sigma_y(ep) - 1| = {drift:.1e} < 1e-6, "
                f"sigma_xx error {err:.2e} < {bound[n]:g} and < half the tangent update's {tangent_error[name][n]:.2e}")

# 5. -plastic_update auto: the return where the increments are in equilibrium, the tangent update where they are
# the paper's forward ones (what K linearizes there).
for paper, named, other in ((False, "radial", "tangent"), (True, "tangent", "radial")):
    tol = [] if paper else ["-equilibrium_tol", 1e-9]
    got = {u: solve(["-plastic_update", u] + tol, 50, paper)[0]["load"] for u in ("auto", named, other)}
    same = got["auto"].shape == got[named].shape and bool((got["auto"] == got[named]).all())
    apart = got["auto"].shape != got[other].shape or bool((got["auto"] != got[other]).any())
    k.check(same and apart, f"-plastic_update auto with {'forward' if paper else 'equilibrium'} increments: the "
            f"{named} update's history bit for bit ({same}), not the {other} one's ({apart})")
k.done()
