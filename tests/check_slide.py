"""Friction on a flat rigid tool (options/slide.opts): a 10 x 2 elastic block
pressed on a floor by N = 100 N/mm, then its top pushed sideways.
References (Coulomb): the tangential force T stays below mu N while the block
sticks and slides at T = mu N; friction dissipation = mu N x slip.
  - slide at mu N within 1.2e-3 (1 % required; measured -1.2e-5, the
    regularized law's residual, on every OpenBLAS kernel tried: 100 times
    that), at 20 and at 200 increments (the law accumulates slip, so the
    increment size must not matter: equal within 2e-5, measured 1.9e-7);
  - stick: while T < mu N / 2 the bottom's slip stays below VCRI (1e-3 mm);
  - dissipation = mu N x slip in steady sliding (the second half of the
    push) within 1e-3 (Coulomb's law is exact there; measured 1.2e-5); over
    the whole push it may only be less (|f_l| <= mu f_n), to round-off (1e-12
    of the dissipation), and the deficit must converge with the increment to
    the regularized law's own: integral of (1 - tanh(3x/VCRI)) dx = VCRI ln2 / 3
    of slip per node (1.16e-3 of mu N slip here). The rest comes from the one
    increment that crosses from stick to slide (trapezoidal in the force), so
    it is first order: it must fall at least 5-fold from 20 to 200 increments
    (10-fold expected; measured 8.8e-3 -> 8.0e-4);
  - contact: no penetration beyond 1e-6 mm, no tensile contact force;
  - r6 (slide to stick, docs/theory.md section 5): the top pushed back (-slide_back)
    reverses the slip; with -rmin_dphi 0.5 each increment may lower a node's
    mobilization f_l / (mu f_n) by at most 0.5, so while T is still positive
    it falls by at most 0.5 mu N per increment (2 %: the normal forces shift
    between the nodes a little as the block rocks), and r6 limits at least
    two increments; with the bound off (-rmin_dphi 2, more than any fall can
    be) T falls from mu N to -mu N in one increment, so the same check
    fails: the bound is what limits;
  - the same on an arc tool (options/slide_arc.opts: a quarter ring turned
    inside a rigid cylinder, which exercises the curvature terms): the moment
    about the centre = mu R sum f_n within 1 %, and the dissipation = that
    moment x the turn within 1 % while it slides (the second half of the turn;
    over the whole turn the elastic wind-up and micro-slip take ~1 %).
The checks above test the paper's friction law and r_min bounds, on its
forward increments (-equilibrium_tol 0: with equilibrium iterations a step
is accepted anywhere within R_max <= 0.005 q, which moves the plateau by up to
that and is no test of the increment-size independence). The default
(equilibrium) increments: the plateau within the equilibrium tolerance 5e-3
of mu N at 20 and 200 increments.
"""
import numpy as np

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
k = Checks("slide")
mu, N, vcri = 0.2, 100.0, 1e-3


def history(extra, name, paper=True):
    f = out(name)
    run(tf, mpirun, 1, ["-options_file", f"{src}/options/slide.opts", "-output", f, "-output_every", 100000] + extra +
        (["-equilibrium_tol", 0] if paper else []))
    import h5py
    with h5py.File(f, "r") as h:
        return {c: h["/history"][c][:] for c in h["/history"]}


plateau, excess = {}, {}
for n in (20, 200):
    H = history(["-increments", n], f"slide_{n}.h5")
    plateau[n] = H["load"][-1]
    k.check(abs(plateau[n] / (mu * N) - 1) < 1.2e-3, f"{n} increments: sliding force {plateau[n]:.4f} vs mu N = {mu * N:g} "
            f"({plateau[n] / (mu * N) - 1:+.1e})")
    push = np.nonzero(H["stage"] == 1)[0]
    for name, i0 in (("steady sliding (second half)", push[len(push) // 2]), ("whole push", push[0] - 1)):
        slip = H["slip"][-1] - H["slip"][i0]
        wf = H["w_friction"][-1] - H["w_friction"][i0]
        ratio = wf / (mu * N * slip) - 1
        if name.startswith("steady"):
            if n == 20:
                k.check(abs(ratio) < 1e-3, f"friction dissipation, {name}: {wf:.5f} vs mu N slip {mu * N * slip:.5f} ({ratio:+.2e})")
            continue
        k.check(ratio <= 1e-12, f"{n} increments, friction dissipation over the whole push {wf:.5f} <= mu N slip {mu * N * slip:.5f} ({ratio:+.2e})")
        excess[n] = -ratio - vcri * np.log(2) / 3 / slip
    if n == 20:
        k.check(H["penetration"].max() <= 1e-6 and H["tension"].max() <= 0, f"no penetration ({H['penetration'].max():.1e} mm), no tension ({H['tension'].max():.1e})")
k.check(abs(excess[20]) >= 5 * abs(excess[200]),
        f"whole-push dissipation deficit beyond the tanh law's VCRI ln2 / 3: {excess[20]:.2e} at 20 increments, {excess[200]:.2e} at 200 (first order)")
k.check(abs(plateau[20] / plateau[200] - 1) < 2e-5, f"sliding force independent of the increment size: {plateau[20]:.5f} vs "
        f"{plateau[200]:.5f} ({plateau[20] / plateau[200] - 1:+.1e})")

for n in (20, 200):
    T = history(["-increments", n], f"slide_eq_{n}.h5", paper=False)["load"][-1]
    k.check(abs(T / (mu * N) - 1) < 5e-3, f"equilibrium increments, {n}: sliding force {T:.4f} vs mu N ({T / (mu * N) - 1:+.1e})")

H = history(["-slide_push", 0.002, "-increments", 200], "slide_stick.h5")
stage2 = H["stage"] == 1
low = stage2 & (H["load"] < 0.5 * mu * N)
k.check(low.sum() >= 3 and np.abs(H["slip"][low]).max() < vcri, f"stick: {low.sum()} increments with T < mu N / 2, largest slip {np.abs(H['slip'][low]).max():.2e} mm < VCRI")
k.check(H["load"][stage2].max() <= mu * N * 1.001, f"T never exceeds mu N ({H['load'][stage2].max():.4f})")


def reversal(dphi):
    H = history(["-slide_back", 0.4, "-increments", 20, "-rmin_dphi", dphi], f"slide_back_{dphi}.h5")
    back = np.nonzero(H["stage"] == 2)[0]
    T = H["load"][back[0] - 1:back[-1] + 1]
    falls = -np.diff(T)[T[:-1] > 0]
    return falls.max(), int((H["limiter"][back] == 7).sum()), H["load"][-1]


fall, limited, end = reversal(0.5)
k.check(fall <= 0.5 * mu * N * 1.02 and limited >= 2,
        f"r6 bounds slide to stick: largest fall of T from T > 0 {fall:.3f} <= 0.5 mu N = {0.5 * mu * N:g} (2 %), "
        f"{limited} increments limited by r6; T ends at {end:.3f}")
fall_off, _, _ = reversal(2)
k.check(fall_off > 0.5 * mu * N * 1.02, f"without the bound (-rmin_dphi 2) T falls by {fall_off:.3f} in one increment")
import h5py  # noqa: E402
f = out("slide_arc.h5")
run(tf, mpirun, 1, ["-options_file", f"{src}/options/slide_arc.opts", "-output", f, "-output_every", 100000, "-equilibrium_tol", 0])
with h5py.File(f, "r") as hf:
    A = {c: hf["/history"][c][:] for c in hf["/history"]}
R, sum_fn = 10.0, A["fn_sum"][-1]
k.check(abs(A["load"][-1] / (mu * R * sum_fn) - 1) < 0.01, f"arc: moment {A['load'][-1]:.3f} vs mu R sum f_n {mu * R * sum_fn:.3f}")
# Steady sliding (the second half of the turn): dissipation = moment x turn.
mid = int(np.nonzero(A["stage"] == 1)[0][len(np.nonzero(A["stage"] == 1)[0]) // 2])
wf, turn = A["w_friction"][-1] - A["w_friction"][mid], A["stroke"][-1] - A["stroke"][mid]
k.check(abs(wf / (A["load"][-1] * turn) - 1) < 0.01, f"arc: dissipation while sliding {wf:.4f} vs moment x turn {A['load'][-1] * turn:.4f}")
k.check(A["penetration"].max() <= 1e-6 * 10 and A["tension"].max() <= 0, f"arc: penetration {A['penetration'].max():.1e} mm, tension {A['tension'].max():.1e}")
k.done()
