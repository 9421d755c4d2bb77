#!/usr/bin/python3
"""Whether mesh companions at the run's own resolution, with the cells around shifted, read the run's error sharply
and bound it (docs/notes/estimate-companions.md, "Why: the companions' contact phase": a mesh at the run's cells
moves by about +-0.3 % with where its nodes meet the die's flank, which is most of the run's error). For each
CalculiX case and preset: the run, the shipped companions M and S, the run's cells at twice the increment limits
(R, the steps' part on the run's mesh), and phase companions P+k of the run's cells through the wall and N + k
around (k = -4, -2, 2, 4), the run's element and friction regularization kept (as studies/estimate_phase.py keeps
them). Candidates (load relative, C/t absolute; P+-2 the two at k = +-2, P all four):

    1   shipped: |S - M| + |M - run|
    2   |R - run| + max |P - run| over P+-2
    3   |R - run| + max |P - run| over all four
    4   |R - run| + mean |P - run|
    5   |R - run| + |mean P - run| + sd P (the sample's, ddof 1)
    6   |S - M| + max |P - run|
    7   |S - M| + |M - run| / 3 + max |P - run|
    8a  |R - run| + (max - min of the four P and the run): the range of the phase samples the run is one of
    8b  |S - M| + max(|M - run| / 3, max |P - run|): |M - run| holds the run's phase already, so not their sum
    8c  the load by 3, C/t by 1 (C/t hardly moves with the contact phase: the P's within 5e-4 of the run at 2 mm)

The phase companions, and a timed re-run of the run and of R (the cost of a companion against the run's own, and
a check that the cached ones are this binary's), are cached under results/estimate_same_level/ (<name>.time: the
wall seconds); the run and M, S, R under results/estimate_ccx/.

    /usr/bin/python3 studies/estimate_same_level.py run  [--cases ...] [--presets fast,default] [-j 1]
    /usr/bin/python3 studies/estimate_same_level.py eval [--cases ...] [--presets ...] [--cells]
"""
import math
import os
import time

import numpy as np

import estimate_ccx as ec  # (this folder: a study's module beside it)
from estimate_ccx import tfruns

OUT = os.path.join(tfruns.root, "results", "estimate_same_level")
SHIFTS = (-4, -2, 2, 4)  # the phase companions' cells around: N + k, the run's cells through


def timed(case, preset, level, extra):
    """ec.run_one into OUT, its wall seconds beside it (<case>_<preset>_<level>.time) when it runs."""
    h5 = os.path.join(OUT, f"{case}_{preset}_{level}.h5")
    if not os.path.exists(h5):
        t0 = time.time()
        ec.run_one(case, preset, level, extra, OUT)
        with open(h5[:-3] + ".time", "w") as f:
            f.write(f"{time.time() - t0:.2f}\n")
    return h5


def run_case(case, preset):
    h5 = ec.run_one(case, preset, "run", [])
    nt, n, element = ec.run_mesh(h5)
    ro = float(tfruns.option(tfruns.calculix_reference(case)[0], "-tube_ro"))
    keep = ["-element", element, "-friction_vcri", repr(ec.VCRI_OF_CELL * (math.pi / 2) * ro / n)]
    lv = ec.levels(nt, n, ro, preset)
    for k in ("M", "S", "R"):
        ec.run_one(case, preset, k, lv[k] + keep)
    timed(case, preset, "timed_run", [])
    timed(case, preset, "timed_R", lv["R"] + keep)
    for k in SHIFTS:
        timed(case, preset, f"P{k:+d}", keep + ["-mesh_nt", str(nt), "-mesh_ntheta", str(n + k)])


def wall(case, preset, level):
    f = os.path.join(OUT, f"{case}_{preset}_{level}.time")
    return float(open(f).read()) if os.path.exists(f) else float("nan")


def candidates(v):
    """Each candidate's estimate of the run's load (relative) and C/t (absolute) errors."""
    run, M, S, R = v["run"], v["M"], v["S"], v["R"]
    P2, P4 = [v[f"P{k:+d}"] for k in (-2, 2)], [v[f"P{k:+d}"] for k in SHIFTS]
    rel = lambda a, b: np.abs(a[1] / b[1] - 1)  # noqa: E731
    absd = lambda a, b: np.abs(a[2] - b[2])  # noqa: E731
    both = lambda f: (f(rel), f(absd))  # noqa: E731
    steps_sm, steps_r, mesh_m = both(lambda d: d(S, M)), both(lambda d: d(R, run)), both(lambda d: d(M, run))
    max2 = both(lambda d: np.max([d(p, run) for p in P2], axis=0))
    max4 = both(lambda d: np.max([d(p, run) for p in P4], axis=0))
    meanabs = both(lambda d: np.mean([d(p, run) for p in P4], axis=0))
    pl, pc = np.array([p[1] for p in P4]), np.array([p[2] for p in P4])
    meansd = (np.abs(pl.mean(0) / run[1] - 1) + pl.std(0, ddof=1) / run[1],
              np.abs(pc.mean(0) - run[2]) + pc.std(0, ddof=1))
    al, ac = np.vstack([pl, run[1]]), np.vstack([pc, run[2]])
    span = ((al.max(0) - al.min(0)) / run[1], ac.max(0) - ac.min(0))
    plus = lambda *parts: tuple(sum(p[i] for p in parts) for i in (0, 1))  # noqa: E731
    third = tuple(m / 3 for m in mesh_m)
    return {
        "1 shipped |S-M|+|M-run|": plus(steps_sm, mesh_m),
        "2 |R-run| + max|P-run| +-2": plus(steps_r, max2),
        "3 |R-run| + max|P-run| +-2,4": plus(steps_r, max4),
        "4 |R-run| + mean|P-run|": plus(steps_r, meanabs),
        "5 |R-run| + |mean P-run| + sd P": plus(steps_r, meansd),
        "6 |S-M| + max|P-run|": plus(steps_sm, max4),
        "7 |S-M| + |M-run|/3 + max|P-run|": plus(steps_sm, third, max4),
        "8a |R-run| + span(P, run)": plus(steps_r, span),
        "8b |S-M| + max(|M-run|/3, max|P-run|)": plus(steps_sm, tuple(np.maximum(a, b) for a, b in zip(third, max4))),
        "8c load: 3, C/t: shipped": (plus(steps_r, max4)[0], plus(steps_sm, mesh_m)[1]),
        "  (steps alone |R-run|)": steps_r,
    }


def evaluate(cases, presets, cells):
    stats, costs = {}, []
    for case in cases:
        for preset in presets:
            files = {k: os.path.join(ec.OUT, f"{case}_{preset}_{k}.h5") for k in ("run", "M", "S", "R")}
            files.update({f"P{k:+d}": os.path.join(OUT, f"{case}_{preset}_P{k:+d}.h5") for k in SHIFTS})
            if not all(os.path.exists(f) for f in files.values()):
                print(f"{case} {preset}: not run")
                continue
            v = {k: ec.values(f, case) for k, f in files.items()}
            us, load, ct, rload, rct = v["run"]
            err_l, err_c = np.abs(load / rload - 1), np.abs(ct - rct)
            unc_l, unc_c = (np.array(u) for u in ec.REF_UNCERTAINTY[case])
            again = os.path.join(OUT, f"{case}_{preset}_timed_run.h5")
            if os.path.exists(again):  # the cached run against this binary's
                a = ec.values(again, case)
                d = max(np.max(np.abs(a[1] / load - 1)), np.max(np.abs(a[2] - ct)))
                if d > 1e-9:
                    print(f"{case} {preset}: the timed re-run differs from the cached run by {d:.2e}")
            t = {k: wall(case, preset, k) for k in ["timed_run", "timed_R"] + [f"P{k:+d}" for k in SHIFTS]}
            costs.append((case, preset, t))
            for name, (el, ecc) in candidates(v).items():
                stats.setdefault((name, preset), []).extend(list(zip(el, err_l, unc_l)) + list(zip(ecc, err_c, unc_c)))
            if cells:
                nt, n, element = ec.run_mesh(files["run"])
                print(f"\n{case} {preset} ({nt} x {n}, {element}) at U = " + " ".join(f"{u:g}" for u in us) +
                      "; signed per cent of the run's load, then C/t (from 2 mm, then sprung back)")
                sgn = lambda a: " ".join(f"{100 * (x / r - 1):+6.2f}" for x, r in zip(a, load))  # noqa: E731
                sgc = lambda a: " ".join(f"{x - r:+.4f}" for x, r in zip(a, ct))  # noqa: E731
                print(f"  {'CalculiX - run':16s} load {sgn(rload)}  C/t {sgc(rct)}")
                for k in ["R", "M", "S"] + [f"P{k:+d}" for k in SHIFTS]:
                    print(f"  {k + ' - run':16s} load {sgn(v[k][1])}  C/t {sgc(v[k][2])}")
                for name, (el, ecc) in candidates(v).items():
                    print(f"  {name:38s} err/est load " + " ".join(f"{100 * a:.2f}/{100 * e:.2f}" for e, a in
                                                                  zip(el, err_l)) +
                          "  C/t " + " ".join(f"{a:.4f}/{e:.4f}" for e, a in zip(ecc, err_c)))
    for group in presets + ["all"] if len(presets) > 1 else presets:
        print(f"\n{'preset ' + group:38s} cells  bounded (within ref. unc.)  median eff.  within 3x  "
              "| resolved: n  bounded (unc.)  median  within 3x")
        for name in dict.fromkeys(n for n, _ in stats):
            s = [x for (n, p), xs in stats.items() if n == name and group in (p, "all") for x in xs]
            if not s:
                continue
            e, t, u = np.array(s).T
            eff = e / np.maximum(t, 1e-12)
            w3 = lambda x: 100 * np.mean((x >= 1 / 3) & (x <= 3))  # noqa: E731
            r = t > u  # the cells whose error the reference resolves (above its own uncertainty)
            pc = lambda m: 100 * np.mean(m)  # noqa: E731
            print(f"{name:38s} {len(e):5d}  {pc(e >= t):3.0f} % ({pc(e + u >= t):3.0f} %){np.median(eff):14.2f}  "
                  f"{w3(eff):6.0f} %   | {r.sum():11d}  {pc(e[r] >= t[r]):5.0f} % ({pc(e[r] + u[r] >= t[r]):3.0f} %)"
                  f"  {np.median(eff[r]):6.2f}  {w3(eff[r]):6.0f} %")
    if costs:
        print("\nwall seconds (one core): run, R, P-4 P-2 P+2 P+4; each companion / the run")
        for case, preset, t in costs:
            ps = [t[f"P{k:+d}"] for k in SHIFTS]
            print(f"  {case:8s} {preset:8s} run {t['timed_run']:6.1f}  R {t['timed_R']:6.1f}  P " +
                  " ".join(f"{x:6.1f}" for x in ps) + f"   R/run {t['timed_R'] / t['timed_run']:.2f}  P/run " +
                  " ".join(f"{x / t['timed_run']:.2f}" for x in ps))
        tot = {k: sum(t[k] for _, _, t in costs) for k in costs[0][2]}
        print(f"  total: run {tot['timed_run']:.0f} s, R {tot['timed_R']:.0f} s, four P " +
              f"{sum(tot[f'P{k:+d}'] for k in SHIFTS):.0f} s: R / run {tot['timed_R'] / tot['timed_run']:.2f}, "
              f"each P / run {np.mean([tot[f'P{k:+d}'] for k in SHIFTS]) / tot['timed_run']:.2f}")


if __name__ == "__main__":
    ec.main(__doc__, run_case, evaluate, OUT)
