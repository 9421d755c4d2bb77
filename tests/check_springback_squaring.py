"""The springback's law (-springback) in the squaring scene: what the material's law changes against the paper's
elastic release is what the elastic release's excursion past the yield surface says it should change.

The default tube (options/squaring.opts). With a saturating Armstrong-Frederick backstress (AF: 0.6 sigma_y0
reached within p ~ 0.02, -material_kinematic 19836,200 as studies/hardening_study.py; its elastic range on
reversal shrinks to about 0.8 sigma_y0, docs/results.md) the springback yields back; with isotropic hardening it
hardly does. For each release, s = (how far the elastic release carries a point past the yield surface,
release_excess) x (the share of Gauss points it carries past it): the share of the release's stress change that
the material's law would not take elastically. The springback of C/t, C1 and C2 (their change over the release)
then changes with the material's law by a fraction of itself of the order of s: at most 10 s (a point that
yields back at a corner moves the side by the corner's turn times the side's length, which a share of points
does not weigh: ten times covers it) and, where s is not small, at least s / 10. Runs:
1. AF, the paper's reverse release, two passes (-pass2_stroke 4.2 -pass2_turn 90), fast preset: in each release
   the elastic one passes the surface (s > 0.01) and the material's law yields back (points, plastic strain);
   each springback changes by a fraction in [s/10, 10 s]; the run's lines say so (a warning for the elastic one).
2. Isotropic hardening, reverse, the default preset: the elastic release passes the surface at a few points by
   little (s < 1e-4); the springbacks of the two laws agree within 10 s. (On the fast preset no point passes it
   and the two runs agree bit for bit.)
3. AF, -unload withdraw (the die moves back, fast preset): as 1 for C1 and C2.
4. A springback is driven by the elastic energy stored where it began and dissipates a small part of it (0.02
   with the AF backstress); the copper 14.5/0.5 (fast preset) released by the reversed contact forces, dead loads,
   with the material's law collapses under them (C1 goes from 15.5 to 5 mm): its plastic work passes that energy
   and the run warns; released by the die's motion it dissipates less than a tenth of it and does not warn.
5. 1 vs 2 ranks (AF, two passes, material): the release columns agree, the counts of points within one (a point
   at its yield onset within the step's round-off may flow in one and not in the other), plastic strains and
   excesses within 1e-6 of their largest.
6. A restart inside an elastic release with backstresses (AF, withdraw) and inside the second pass's release by
   the material's law (AF, two passes): the history within 1e-12 of the run never stopped (the bound of
   tests/check_restart.py: a missing piece of state shows as 1e-10 or more).
"""
import os
import sys

import h5py
import numpy as np

from tfcheck import Checks, args, checkpoint_at, out, run

tf, mpirun, src = args()
# The single-rank runs (1-4, 6) in the `np1` part; the 2-rank run and its comparison (5) in the `np2` part, which
# reads the `np1` part's two-pass run (its fixture in tests/CMakeLists.txt): no 2-rank run beside another test.
part = sys.argv[4] if len(sys.argv) > 4 else "both"
k = Checks("springback_squaring" + (f" ({part})" if part != "both" else ""))
CASE = ["-options_file", f"{src}/options/squaring.opts", "-error_estimate", 0, "-progress", 0]
FAST = CASE + ["-options_file", f"{src}/options/preset-fast.opts"]
DEFAULT = CASE + ["-options_file", f"{src}/options/preset-default.opts"]
AF = ["-hardening", "chaboche", "-material_kinematic", "19836,200"]
TWO = ["-pass2_stroke", 4.2, "-pass2_turn", 90]
PASSES = (("", 1), ("pass2_", 3))  # (attribute prefix, history stage) of each release


def go(name, opts, np_=1, fresh=True, checkpoint=None):
    """A run's history, attributes and output; `checkpoint` (file, increment): run to that increment, its checkpoint
    written there (tfcheck.checkpoint_at)."""
    f = out(f"sb_{name}.h5")
    for p in (f, f + ".partial") if fresh else ():
        if os.path.exists(p):
            os.remove(p)
    if checkpoint:
        p = checkpoint_at(tf, mpirun, np_, opts + ["-output", f], *checkpoint)
    else:
        p = run(tf, mpirun, np_, opts + ["-output", f])
    with h5py.File(f, "r") as h:
        attrs = dict(h["/history"].attrs, gauss_points=4 * h["/viz/topology/cells"].shape[0])
        return {c: h["/history"][c][:] for c in h["/history"]}, attrs, p.stdout


def springbacks(a, prefix, withdraw=False):
    """The changes of C/t, C1 (x_max) and C2 (y_max) over a release (C/t left out after a withdrawal)."""
    out_ = {"C1": a[f"{prefix}unloaded_x_max"] - a[f"{prefix}loaded_x_max"],
            "C2": a[f"{prefix}unloaded_y_max"] - a[f"{prefix}loaded_y_max"]}
    if not withdraw:
        out_["C/t"] = a[f"{prefix}unloaded_c_over_t"] - a[f"{prefix}loaded_c_over_t"]
    return out_


def compare(what, el, mat, prefix, lower=True, withdraw=False):
    """The two laws' springbacks of one release against the elastic one's excursion s."""
    a_el, a_mat = el[1], mat[1]
    points, total = a_el[f"{prefix}springback_yielded_points"], a_el["gauss_points"]
    s = a_el[f"{prefix}springback_yield_excess"] * points / total
    sb_el, sb_mat = springbacks(a_el, prefix, withdraw), springbacks(a_mat, prefix, withdraw)
    for q in sb_el:
        rel = abs(sb_mat[q] / sb_el[q] - 1)
        ok = rel <= 10 * s and (not lower or rel >= s / 10)
        k.check(ok, f"{what}: springback of {q} {sb_el[q]:+.5f} elastic, {sb_mat[q]:+.5f} by the material's law: "
                f"{rel:.2e} of it, within [{s / 10 if lower else 0:.2e}, {10 * s:.2e}] (s = excess "
                f"{a_el[f'{prefix}springback_yield_excess']:.3g} x {points:.0f} of {total:.0f} points)")
    return s


# 5. 1 vs 2 ranks: the two-pass run with the material's law on 2 ranks against its history h1 on 1.
def ranks(h1):
    h2 = go("two_material_np2", FAST + AF + TWO + ["-springback", "material"], np_=2)[0]
    same = len(h1["stroke"]) == len(h2["stroke"])
    dn = np.abs(h1["release_yielded"] - h2["release_yielded"]).max() if same else np.inf
    dp = np.abs(h1["release_dep"] - h2["release_dep"]).max() / h1["release_dep"].max() if same else np.inf
    k.check(dn <= 1 and dp <= 1e-6, f"1 vs 2 ranks: {len(h1['stroke'])} and {len(h2['stroke'])} rows, points at the "
            f"yield surface within {dn:.0f} (1), plastic strains within {dp:.1e} of the largest (1e-6)")


if part == "np2":
    with h5py.File(out("sb_two_material.h5"), "r") as h:  # (written by the `np1` part, this one's fixture)
        ranks({c: h["/history"][c][:] for c in h["/history"]})
    k.done()

# 1. AF, reverse, two passes.
P = {law: go(f"two_{law}", FAST + AF + TWO + ["-springback", law]) for law in ("elastic", "material")}
for prefix, stage in PASSES:
    el, mat = P["elastic"], P["material"]
    rel = mat[0]["stage"] == stage
    k.check(el[1][f"{prefix}springback_yielded_points"] > 0 and el[1][f"{prefix}springback_yield_excess"] > 0.1 and
            el[1][f"{prefix}springback_plastic_strain"] == 0,
            f"AF, release {stage}, elastic: {el[1][f'{prefix}springback_yielded_points']:.0f} points carried past "
            f"the yield surface, by up to {el[1][f'{prefix}springback_yield_excess']:.3f} sigma_y")
    k.check(mat[1][f"{prefix}springback_yielded_points"] > 0 and mat[1][f"{prefix}springback_plastic_strain"] > 0 and
            mat[0]["n_plastic"][rel].max() > 0 and mat[0]["release_excess"].max() == 0,
            f"AF, release {stage}, material: {mat[1][f'{prefix}springback_yielded_points']:.0f} points yield back, "
            f"plastic strain up to {mat[1][f'{prefix}springback_plastic_strain']:.2e}")
    s = compare(f"AF, reverse, release {stage}", el, mat, prefix)
    k.check(s > 0.01, f"AF, release {stage}: the elastic release's excursion s = {s:.3f} (> 0.01)")
which = ("the springback", "the second pass's springback")
k.check(all(f"warning: {w}, elastic, carries" in P["elastic"][2] for w in which) and
        all(f"{w} by the material's law: " in P["material"][2] and "yield back" in P["material"][2] for w in which),
        "the runs say it for each release: a warning for the elastic one, the points yielding back for the other")

# 2. Isotropic hardening, default preset.
I = {law: go(f"iso_{law}", DEFAULT + ["-springback", law]) for law in ("elastic", "material")}
s = compare("isotropic, default preset", I["elastic"], I["material"], "", lower=False)
k.check(s < 1e-4, f"isotropic: the elastic release passes the yield surface by little: s = {s:.1e} (< 1e-4)")

# 3. AF, withdraw.
W = {law: go(f"withdraw_{law}", FAST + AF + ["-unload", "withdraw", "-springback", law]) for law in ("elastic", "material")}
compare("AF, withdraw", W["elastic"], W["material"], "", withdraw=True)

# 4. A collapse under the reversed contact forces: the thin copper tube (14.5/0.5) released by them with the
# material's law, against the same tube released by the die's motion.
for unload in ("reverse", "withdraw"):
    h, a, said = go(f"copper_{unload}", ["-options_file", f"{src}/options/squaring_cu_29_mu0.05.opts"] + FAST[2:] +
                    ["-unload", unload, "-springback", "material"])
    warned = "the loads drove the tube into a collapse" in said
    w = a["springback_plastic_work"]
    k.check((w > 1 and warned) if unload == "reverse" else (w < 0.1 and not warned and a["springback_x_max"] > 0),
            f"copper 14.5/0.5, {unload}, material: the springback dissipates {w:.3g} of the elastic energy stored "
            f"where it began ({'> 1 and warned: a collapse' if unload == 'reverse' else '< 0.1, no warning'})")

w = P["material"][1]["springback_plastic_work"]
k.check(w < 0.1 and "collapse" not in P["material"][2],
        f"AF, the default tube, material: the springback dissipates {w:.3g} of the elastic energy stored (< 0.1)")

# 5. 1 vs 2 ranks.
if part == "both":
    ranks(P["material"][0])


# 6. Restarts inside a release.
def restart(name, opts, full, stage):
    rows = np.flatnonzero(full["stage"] == stage)
    every = int(full["increment"][rows[len(rows) // 2]])  # (past half the run: its only multiple)
    ck = out(f"sb_{name}.ck.h5")
    go(name, opts, checkpoint=(ck, every))
    with h5py.File(ck, "r") as c:
        lam = c["/run/lambda"][0]
    h, _, said = go(name, opts + ["-restart", ck], fresh=False)
    k.check(stage < lam < stage + 1 and "restarting from" in said,
            f"{name}: the checkpoint after increment {every} lies in release {stage} (lambda {lam:.4f}), and the run "
            "continues from it")
    worst, col = 0.0, ""
    for c in full:
        if h[c].shape != full[c].shape:
            worst, col = np.inf, f"{c}: {len(h[c])} vs {len(full[c])} rows"
            break
        d = np.where(h[c] == full[c], 0.0, np.abs(h[c] - full[c])).max(initial=0)
        d /= max(np.abs(full[c][np.isfinite(full[c])]).max(initial=0), 1e-300)
        if d > worst:
            worst, col = d, c
    k.check(worst <= 1e-12, f"restart after increment {every} (release {stage}) of {name}: the history within "
            f"{worst:.1e} ({col}) of the run never stopped (1e-12)")


restart("withdraw_elastic_ck", FAST + AF + ["-unload", "withdraw", "-springback", "elastic"], W["elastic"][0], 1)
restart("two_material_ck", FAST + AF + TWO + ["-springback", "material"], P["material"][0], 3)
k.done()
