#!/usr/bin/python3
"""Whether averaging mesh companions over their contact phase sharpens the estimate (docs/notes/estimate-companions.md:
a coarser companion meets the die's flank node by node at other strokes than the run). For each CalculiX case and
preset: the run, the shipped companions M and S, the run's cells at twice the increment limits (R), mesh companions
of half the run's cells through the wall and N / 2 + k around (k = -2, -1, 1, 2), and of the run's cells through
and N / 2 +- 1 around; the run's element and friction regularization kept. The estimate reads the companions' mean.

    /usr/bin/python3 studies/estimate_phase.py run  [--cases ...] [--presets fast,default] [-j 2]
    /usr/bin/python3 studies/estimate_phase.py eval [--cases ...] [--presets ...] [--cells]

Runs are cached under results/estimate_phase/ (the run and M, S, R under results/estimate_ccx/).
"""
import math
import os

import numpy as np

import estimate_ccx as ec  # (this folder: a study's module beside it)
from estimate_ccx import tfruns

OUT = os.path.join(tfruns.root, "results", "estimate_phase")
SHIFTS = (-2, -1, 1, 2)  # the half-through companions' cells around: N / 2 + k
A_SHIFTS = (-1, 1)  # the through-kept companions'


def run_case(case, preset):
    h5 = ec.run_one(case, preset, "run", [])
    nt, n, element = ec.run_mesh(h5)
    ro = float(tfruns.option(tfruns.calculix_reference(case)[0], "-tube_ro"))
    keep = ["-element", element, "-friction_vcri", repr(ec.VCRI_OF_CELL * (math.pi / 2) * ro / n)]
    lv = ec.levels(nt, n, ro, preset)
    for k in ("M", "S", "R"):
        ec.run_one(case, preset, k, lv[k] + keep)
    half_nt, half_n = ec.level_cells(nt, n)["M"]
    for k in SHIFTS:
        ec.run_one(case, preset, f"M{k:+d}", keep + ["-mesh_nt", str(half_nt), "-mesh_ntheta", str(half_n + k)], OUT)
    for k in A_SHIFTS:
        ec.run_one(case, preset, f"A{k:+d}", keep + ["-mesh_nt", str(nt), "-mesh_ntheta", str(half_n + k)], OUT)


def add(stats, name, el, ecc, err_l, err_c, unc_l, unc_c):
    stats.setdefault(name, []).extend(list(zip(el, err_l, unc_l)) + list(zip(ecc, err_c, unc_c)))


def evaluate(cases, presets, show):
    stats = {}
    for case in cases:
        for preset in presets:
            files = {k: os.path.join(ec.OUT, f"{case}_{preset}_{k}.h5") for k in ("run", "M", "S", "R")}
            files.update({f"M{k:+d}": os.path.join(OUT, f"{case}_{preset}_M{k:+d}.h5") for k in SHIFTS})
            files.update({f"A{k:+d}": os.path.join(OUT, f"{case}_{preset}_A{k:+d}.h5") for k in A_SHIFTS})
            if not all(os.path.exists(f) for f in files.values()):
                print(f"{case} {preset}: not run")
                continue
            v = {k: ec.values(f, case) for k, f in files.items()}
            us, load, ct, rload, rct = v["run"]
            err_l, err_c = np.abs(load / rload - 1), np.abs(ct - rct)
            unc = [np.array(u) for u in ec.REF_UNCERTAINTY[case]]
            run, M, S, R = v["run"], v["M"], v["S"], v["R"]
            steps_l, steps_c = np.abs(S[1] / M[1] - 1), np.abs(S[2] - M[2])
            rsteps_l, rsteps_c = np.abs(R[1] / run[1] - 1), np.abs(R[2] - run[2])
            groups = {"M": ["M"], "M+-1": ["M-1", "M+1"], "M+-1,2": ["M-2", "M-1", "M+1", "M+2"],
                      "M all five": ["M", "M-2", "M-1", "M+1", "M+2"]}
            for gname, keys in groups.items():
                ml = np.mean([v[k][1] for k in keys], axis=0)
                mc = np.mean([v[k][2] for k in keys], axis=0)
                for p, div in (("p1", 1.0), ("p2", 3.0)):
                    add(stats, f"{gname} {p}", steps_l + np.abs(ml / run[1] - 1) / div,
                        steps_c + np.abs(mc - run[2]) / div, err_l, err_c, *unc)
                if show and gname in ("M", "M+-1,2"):
                    print(f"{case} {preset} {gname}: mesh part load " +
                          " ".join(f"{100 * (m / r - 1):+.2f}" for m, r in zip(ml, run[1])) +
                          "  error " + " ".join(f"{100 * (r / l - 1):+.2f}" for r, l in zip(rload, load)))
            al = np.mean([v[k][1] for k in ("A-1", "A+1")], axis=0)
            ac = np.mean([v[k][2] for k in ("A-1", "A+1")], axis=0)
            for p, div in (("p1", 1.0), ("p2", 3.0)):
                add(stats, f"R + A+-1 {p}", rsteps_l + np.abs(al / run[1] - 1) / div,
                    rsteps_c + np.abs(ac - run[2]) / div, err_l, err_c, *unc)
    for name, s in stats.items():
        e, t, u = np.array(s).T
        eff = e / np.maximum(t, 1e-12)
        r = t > u
        print(f"{name:18s} cells {len(e)}  bounded {100 * np.mean(e + u >= t):.0f} %  median eff. "
              f"{np.median(eff):.2f}  within 3x {100 * np.mean((eff >= 1/3) & (eff <= 3)):.0f} %  resolved {r.sum()}: "
              f"median {np.median(eff[r]):.2f} within 3x {100 * np.mean((eff[r] >= 1/3) & (eff[r] <= 3)):.0f} %")


if __name__ == "__main__":
    ec.main(__doc__, run_case, evaluate, OUT)
