#!/usr/bin/python3
"""Whether a mesh companion whose nodes are a subset of the run's reads the run's error more sharply than one whose
nodes lie elsewhere (docs/notes/estimate-companions.md: a companion's contact phase). For each CalculiX case and
preset: the run on a multiple of 4 cells around (N), and three mesh companions with half its cells through the wall
(at least 2): N / 2 around (nested: every companion node is a run node), N / 2 - 2 and N / 2 + 2 (not nested), each
with its steps companion (twice the increment limits); the run's element and friction regularization kept.

    /usr/bin/python3 studies/estimate_nested.py run  [--cases ...] [--presets fast,default] [-j 2]
    /usr/bin/python3 studies/estimate_nested.py eval [--cases ...] [--presets ...] [--cells]

Runs are cached under results/estimate_nested/.
"""
import math
import os

import numpy as np

import estimate_ccx as ec  # (this folder: a study's module beside it)
from estimate_ccx import tfruns

OUT = os.path.join(tfruns.root, "results", "estimate_nested")
SHIFTS = {"n": 0, "o": -2, "p": 2}  # the companion's cells around: N / 2 + shift


def run_case(case, preset):
    nt, n, element = ec.run_mesh(os.path.join(ec.OUT, f"{case}_{preset}_run.h5"))
    n4 = 4 * math.ceil(n / 4)
    ro = float(tfruns.option(tfruns.calculix_reference(case)[0], "-tube_ro"))
    keep = ["-element", element, "-friction_vcri", repr(ec.VCRI_OF_CELL * (math.pi / 2) * ro / n4)]
    ec.run_one(case, preset, "run", keep + ["-mesh_nt", str(nt), "-mesh_ntheta", str(n4)], OUT)
    inc, deps, dom, dy = ec.LIMITS[preset]
    twice = ["-increments", str(max(1, inc // 2)), "-rmin_deps", str(2 * deps), "-rmin_domega", str(2 * dom),
             "-rmin_deps_yield", str(2 * dy)]
    for tag, shift in SHIFTS.items():
        cells = ["-mesh_nt", str(max(2, nt // 2)), "-mesh_ntheta", str(n4 // 2 + shift)]
        ec.run_one(case, preset, "M" + tag, keep + cells, OUT)
        ec.run_one(case, preset, "S" + tag, keep + cells + twice, OUT)


def evaluate(cases, presets, show):
    stats = {}
    for case in cases:
        for preset in presets:
            files = {"run": os.path.join(OUT, f"{case}_{preset}_run.h5")}
            files.update({k + t: os.path.join(OUT, f"{case}_{preset}_{k}{t}.h5") for t in SHIFTS for k in "MS"})
            if not all(os.path.exists(f) for f in files.values()):
                print(f"{case} {preset}: not run")
                continue
            v = {k: ec.values(f, case) for k, f in files.items()}
            us, load, ct, rload, rct = v["run"]
            err_l, err_c = np.abs(load / rload - 1), np.abs(ct - rct)
            unc_l, unc_c = (np.array(u) for u in ec.REF_UNCERTAINTY[case])
            for t in SHIFTS:
                M, S, run = v["M" + t], v["S" + t], v["run"]
                for p, div in (("p1", 1.0), ("p2", 3.0)):
                    el = np.abs(S[1] / M[1] - 1) + np.abs(M[1] / run[1] - 1) / div
                    ecc = np.abs(S[2] - M[2]) + np.abs(M[2] - run[2]) / div
                    name = f"companion N/2{SHIFTS[t]:+d} {p}"
                    stats.setdefault(name, []).extend(
                        list(zip(el, err_l, unc_l)) + list(zip(ecc, err_c, unc_c)))
                    if show and p == "p1":
                        print(f"{case} {preset} N/2{SHIFTS[t]:+d}: mesh part load " +
                              " ".join(f"{100 * abs(m / r - 1):.2f}" for m, r in zip(M[1], run[1])) +
                              "  error " + " ".join(f"{100 * e:.2f}" for e in err_l))
    for name, s in stats.items():
        e, t, u = np.array(s).T
        eff = e / np.maximum(t, 1e-12)
        r = t > u
        print(f"{name:24s} cells {len(e)}  bounded {100 * np.mean(e + u >= t):.0f} % (within the reference's "
              f"uncertainty)  median eff. {np.median(eff):.2f}  within 3x {100 * np.mean((eff >= 1/3) & (eff <= 3)):.0f} %"
              f"  resolved {r.sum()}: median {np.median(eff[r]):.2f} within 3x "
              f"{100 * np.mean((eff[r] >= 1/3) & (eff[r] <= 3)):.0f} %")


if __name__ == "__main__":
    ec.main(__doc__, run_case, evaluate, OUT)
