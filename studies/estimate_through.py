#!/usr/bin/python3
"""Whether companions that keep the run's cells around, and so its contact phase, read the wall's part of the error
sharply (docs/notes/estimate-companions.md, "A wall refined at the run's cells around"). For each CalculiX case and
preset, beside the run and the shipped companions M and S (results/estimate_ccx/) and the phase companions P+k
(results/estimate_same_level/): T2, twice the run's cells through the wall at its cells around; Th, half of them
(at least 2) at its cells around; A, half the cells around at the run's cells through; Q, three quarters of the
cells both ways, and QS, Q at twice the increment limits (a companion nearer the run than M). The run's element and
friction regularization are kept. Candidates (load relative, C/t absolute; r = the run's cells around over Q's):

    shipped                    |S - M| + |M - run|
    Q, first / second order    |QS - Q| + |Q - run| / (r - 1), / (r^2 - 1)
    wall from T2               |S - M| + c |T2 - run| (+ max |P - run| over k = +-2 or all four): c = 2 (first
                               order), 4/3 (second), 1
    the same, signed           |c (T2 - run) + (S - M)| (+ max |P - run|)
    wall from Th               |S - M| + |Th - run| / 3 (+ |M - run| / 3, or their larger)
    by direction, signed       t + a + s, each at first order with its sign: t = Th - run (T2's -2 (T2 - run) where
                               the run has 2 cells through), a = A - run, s = S - M; |t + a + s| (+ max |P - run|
                               over k = +-2), and |t| + |a| + |s|

    /usr/bin/python3 studies/estimate_through.py run  [--cases ...] [--presets fast,default] [-j 2]
    /usr/bin/python3 studies/estimate_through.py eval [--cases ...] [--presets ...] [--cells]
"""
import math
import os

import numpy as np

import estimate_ccx as ec  # (this folder: a study's module beside it)
import estimate_same_level as sl
from estimate_ccx import tfruns

OUT = os.path.join(tfruns.root, "results", "estimate_through")


def run_case(case, preset):
    h5 = ec.run_one(case, preset, "run", [])
    nt, n, element = ec.run_mesh(h5)
    ro = float(tfruns.option(tfruns.calculix_reference(case)[0], "-tube_ro"))
    keep = ["-element", element, "-friction_vcri", repr(ec.VCRI_OF_CELL * (math.pi / 2) * ro / n)]
    inc, deps, dom, dy = ec.LIMITS[preset]
    twice = ["-increments", str(max(1, inc // 2)), "-rmin_deps", str(2 * deps), "-rmin_domega", str(2 * dom),
             "-rmin_deps_yield", str(2 * dy)]
    cells = lambda a, b: ["-mesh_nt", str(a), "-mesh_ntheta", str(b)]  # noqa: E731
    q, a = cells(*ec.level_cells(nt, n)["Q"]), cells(*ec.level_cells(nt, n)["A"])
    for level, extra in (("T2", cells(2 * nt, n)), ("Th", cells(max(2, nt // 2), n)), ("Q", q), ("QS", q + twice),
                         ("A", a)):
        ec.run_one(case, preset, level, keep + extra, OUT)


def candidates(v, r, nt):
    """Each candidate's estimate of the run's load (relative) and C/t (absolute) errors."""
    rel = lambda a, b: np.abs(v[a][1] / v[b][1] - 1)  # noqa: E731
    absd = lambda a, b: np.abs(v[a][2] - v[b][2])  # noqa: E731
    d = lambda a, b: np.array([rel(a, b), absd(a, b)], dtype=object)  # noqa: E731
    phase = lambda ks: np.array([np.max([rel(f"P{k:+d}", "run") for k in ks], axis=0),  # noqa: E731
                                 np.max([absd(f"P{k:+d}", "run") for k in ks], axis=0)], dtype=object)
    p2, p4 = phase((-2, 2)), phase(sl.SHIFTS)

    def signed(c, phase_part):
        load = c * (v["T2"][1] / v["run"][1] - 1) + (v["S"][1] / v["M"][1] - 1)
        ct = c * (v["T2"][2] - v["run"][2]) + (v["S"][2] - v["M"][2])
        return np.array([np.abs(load), np.abs(ct)], dtype=object) + phase_part

    sm, mr, th, t2 = d("S", "M"), d("M", "run"), d("Th", "run"), d("T2", "run")
    # By direction with their signs: each part the run's error at first order from a companion twice as coarse (or,
    # through a wall of 2 cells, twice as fine) in that direction alone.
    sgn = lambda a, b: np.array([v[a][1] / v[b][1] - 1, v[a][2] - v[b][2]], dtype=object)  # noqa: E731
    through = sgn("Th", "run") if nt >= 4 else -2 * sgn("T2", "run")
    net = through + sgn("A", "run") + sgn("S", "M")
    ab = lambda x: np.array([np.abs(x[0]), np.abs(x[1])], dtype=object)  # noqa: E731
    larger = np.array([np.maximum(th[0], mr[0]), np.maximum(th[1], mr[1])], dtype=object)
    return {
        "shipped |S-M| + |M-run|": sm + mr,
        "Q 1st |QS-Q| + |Q-run|/(r-1)": d("QS", "Q") + d("Q", "run") / (r - 1),
        "Q 2nd |QS-Q| + |Q-run|/(r^2-1)": d("QS", "Q") + d("Q", "run") / (r ** 2 - 1),
        "|S-M| + 2|T2-run|": sm + 2 * t2,
        "|S-M| + 4/3|T2-run|": sm + 4 / 3 * t2,
        "|S-M| + |T2-run|": sm + t2,
        "|S-M| + 4/3|T2-run| + maxP+-2": sm + 4 / 3 * t2 + p2,
        "|S-M| + |T2-run| + maxP all": sm + t2 + p4,
        "|4/3(T2-run) + (S-M)|": signed(4 / 3, 0),
        "|4/3(T2-run) + (S-M)| + maxP+-2": signed(4 / 3, p2),
        "|S-M| + |Th-run|/3": sm + th / 3,
        "|S-M| + |Th-run|/3 + |M-run|/3": sm + th / 3 + mr / 3,
        "|S-M| + max(|Th-run|, |M-run|)/3": sm + larger / 3,
        "by direction |t + a + s|": ab(net),
        "by direction |t + a + s| + maxP+-2": ab(net) + p2,
        "by direction |t| + |a| + |s|": ab(through) + ab(sgn("A", "run")) + sm,
    }


def evaluate(cases, presets, cells):
    stats = {}
    for case in cases:
        for preset in presets:
            files = {k: os.path.join(ec.OUT, f"{case}_{preset}_{k}.h5") for k in ("run", "M", "S")}
            files.update({k: os.path.join(OUT, f"{case}_{preset}_{k}.h5") for k in ("T2", "Th", "A", "Q", "QS")})
            files.update({f"P{k:+d}": os.path.join(sl.OUT, f"{case}_{preset}_P{k:+d}.h5") for k in sl.SHIFTS})
            if not all(os.path.exists(f) for f in files.values()):
                print(f"{case} {preset}: not run (the phase companions: studies/estimate_same_level.py run)")
                continue
            v = {k: ec.values(f, case) for k, f in files.items()}
            us, load, ct, rload, rct = v["run"]
            err = (np.abs(load / rload - 1), np.abs(ct - rct))
            unc = [np.array(u) for u in ec.REF_UNCERTAINTY[case]]
            nt, n, element = ec.run_mesh(files["run"])
            r = n / ec.run_mesh(files["Q"])[1]
            if cells:
                print(f"\n{case} {preset} ({nt} x {n}, {element}) at U = " + " ".join(f"{u:g}" for u in us) +
                      "; signed per cent of the run's load, then C/t (from 2 mm, then sprung back)")
                sgn = lambda a: " ".join(f"{100 * (x / y - 1):+6.2f}" for x, y in zip(a, load))  # noqa: E731
                sgc = lambda a: " ".join(f"{x - y:+.4f}" for x, y in zip(a, ct))  # noqa: E731
                print(f"  {'CalculiX - run':14s} load {sgn(rload)}  C/t {sgc(rct)}")
                for k in ("T2", "Th", "Q", "M"):
                    print(f"  {k + ' - run':14s} load {sgn(v[k][1])}  C/t {sgc(v[k][2])}")
            for name, (el, ecc) in candidates(v, r, nt).items():
                stats.setdefault((name, preset), []).extend(list(zip(el, err[0], unc[0])) +
                                                            list(zip(ecc, err[1], unc[1])))
    ec_table(stats, presets)


def ec_table(stats, presets):
    """The candidates' bound, effectivity and spread, preset by preset and over all (as estimate_same_level.py)."""
    for group in presets + ["all"] if len(presets) > 1 else presets:
        print(f"\n{'preset ' + group:36s} cells  bounded (within ref. unc.)  median eff.  within 3x  "
              "| resolved: n  bounded (unc.)  median  within 3x")
        for name in dict.fromkeys(n for n, _ in stats):
            s = [x for (n, p), xs in stats.items() if n == name and group in (p, "all") for x in xs]
            e, t, u = np.array(s, dtype=float).T
            eff, res = e / np.maximum(t, 1e-12), t > u
            w3 = lambda x: 100 * np.mean((x >= 1 / 3) & (x <= 3))  # noqa: E731
            pc = lambda m: 100 * np.mean(m)  # noqa: E731
            print(f"{name:36s} {len(e):5d}  {pc(e >= t):3.0f} % ({pc(e + u >= t):3.0f} %){np.median(eff):14.2f}  "
                  f"{w3(eff):6.0f} %   | {res.sum():11d}  {pc(e[res] + u[res] >= t[res]):5.0f} %"
                  f"  {np.median(eff[res]):6.2f}  {w3(eff[res]):6.0f} %")


if __name__ == "__main__":
    ec.main(__doc__, run_case, evaluate, OUT)
