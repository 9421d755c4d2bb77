#!/usr/bin/python3
"""How well a run's error estimate bounds its true error, for candidate estimators, on the tubes of
scripts/validate (issue 22, docs/accuracy.md "The error estimate").

    /usr/bin/python3 scripts/estimate_study.py [--cases a,b] [--presets fast,default] [-j N]

For each tube and preset it takes the preset's run cached by scripts/validate (results/validate/) and runs
its companion (the run's own estimate's coarser pass: half the cells through the wall, at least 2, and
around, half the trial increments) as a run of its own, cached beside it (<tube>_<preset>_companion.h5).
The true error is measured against the CalculiX reference of the tube where one exists
(scripts/calculix/converge.py, cases val_<tube>: the finest mesh whose loading finished; loading only) and
against scripts/validate's extrapolated reference otherwise. Estimators, each at the reported strokes (load, C/t)
and after springback (C/t):

  raw      |run - companion| at the stroke (what the runs print, times the factor)
  smooth   |S_run - S_comp| + A_run: S a straight line fitted by least squares to the curve over the
           window [u - w, u + w] of the stroke (clipped at the ends of the loading), A the run's largest
           departure from its line in that window (the contact ripple, a discretization error the converged
           curve does not have)

each with the safety factor F (1, and 3: Roache's grid convergence index for a two-grid study). Printed: per
tube and preset the largest error and each estimate, and per estimator how many errors it bounds and its
median ratio estimate / error.
"""
import argparse
import concurrent.futures
import importlib.machinery
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

V = importlib.machinery.SourceFileLoader("validate", os.path.join(HERE, "validate")).load_module()
WINDOW = 0.15  # mm of stroke each side: a few ripple periods on the default preset (0.05-0.1 mm each)
PRESET_INCREMENTS = {"fast": (100, 10), "default": (200, 10)}


def mesh_of(h5):
    """Cells through the wall and around of a result (from its cell count and vertex count)."""
    import h5py
    with h5py.File(h5, "r") as f:
        cells = f["viz/topology/cells"].shape[0]
        nodes = f["geometry/vertices"].shape[0]
    # nodes = (nt + 1) (ntheta + 1), cells = nt ntheta
    for nt in range(1, 65):
        if cells % nt == 0 and (nt + 1) * (cells // nt + 1) == nodes:
            return nt, cells // nt
    raise RuntimeError(f"{h5}: not a structured tube mesh")


def companion(case, preset):
    main = os.path.join(V.OUT, f"{case}_{preset}.h5")
    nt, nth = mesh_of(main)
    inc, uinc = PRESET_INCREMENTS[preset]
    extra = ["-options_file", f"options/preset-{preset}.opts", "-error_estimate", 0, "-mesh_nt", max(2, nt // 2),
             "-mesh_ntheta", max(4, 2 * (nth // 4)), "-increments", inc // 2, "-unload_increments", max(1, uinc // 2)]
    return V.run(case, f"{preset}_companion", extra)


def ccx_reference(case):
    """The finest finished CalculiX run of the tube: (U, P, C) of its loading and its sprung-back C/t (or None)."""
    sys.path.insert(0, os.path.join(HERE, "calculix"))
    import converge
    key = "val_" + case
    if key not in converge.CASES:
        return None
    best = None
    for lev in converge.levels(key, "mesh"):
        name = converge.name_of(key, lev)
        rows, meta = converge.load_rows(name)
        if rows and meta.get("final_stroke", 0) >= V.CASES[case][4] - 1e-6:  # the loading finished
            best = (name, rows)
    if best is None:
        return None
    name, rows = best
    load = [r for r in rows if r["stage"] == 0]
    s = float("nan")  # ccx withdraws the die for springback, scripts/validate's runs reverse the load
    return {"name": name, "U": np.array([r["stroke"] for r in load]), "P": np.array([r["load"] for r in load]),
            "C": np.array([r["c_over_t"] for r in load]), "S": s}


def fit(U, Y, u, lo, hi):
    """Least-squares line through (U, Y) on [u - w, u + w] within [lo, hi]: its value at u and the largest
    departure of the points from it."""
    a, b = max(lo, u - WINDOW), min(hi, u + WINDOW)
    k = (U >= a - 1e-12) & (U <= b + 1e-12)
    if k.sum() < 3:
        return float(np.interp(u, U, Y)), 0.0
    c = np.polyfit(U[k], Y[k], 1)
    return float(np.polyval(c, u)), float(np.abs(Y[k] - np.polyval(c, U[k])).max())


def estimates(m, c, strokes):
    """Per estimator: (load estimates at the strokes, C/t estimates at the strokes + springback)."""
    out = {}
    P, C, S = V.values(m, strokes)
    Pc, Cc, Sc = V.values(c, strokes)
    out["raw"] = ([abs(p / q - 1) for p, q in zip(P, Pc)], [abs(x - y) for x, y in zip(C, Cc)] + [abs(S - Sc)])
    lp, lc = [], []
    hi = m["U"][-1]
    for u, p in zip(strokes, P):
        sm, am = fit(m["U"], m["P"], u, 0, hi)
        sc, _ = fit(c["U"], c["P"], u, 0, hi)
        lp.append((abs(sm - sc) + am) / abs(p))
        tm, bm = fit(m["U"], m["C"], u, 0, hi)
        tc, _ = fit(c["U"], c["C"], u, 0, hi)
        lc.append(abs(tm - tc) + bm)
    out["smooth"] = (lp, lc + [abs(S - Sc)])
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cases", default=",".join(V.CASES))
    ap.add_argument("--presets", default="fast,default")
    ap.add_argument("-j", type=int, default=1)
    a = ap.parse_args()
    cases, presets = a.cases.split(","), a.presets.split(",")
    have = [(c, p) for c in cases for p in presets if os.path.exists(os.path.join(V.OUT, f"{c}_{p}.json"))]
    with concurrent.futures.ThreadPoolExecutor(a.j) as ex:
        list(ex.map(lambda job: companion(*job), have))
    tally = {}
    print("| tube | preset | reference | load error | raw | smooth | C/t error | raw | smooth |")
    print("|---|---|---|---|---|---|---|---|---|")
    for case, preset in have:
        m = V.run(case, preset, ["-options_file", f"options/preset-{preset}.opts"])
        c = companion(case, preset)
        if m["status"] != "done" or c["status"] != "done":
            continue
        strokes = V.reported(case)
        ref = ccx_reference(case)
        if ref is not None:
            rname = ref["name"]
            RP = [float(np.interp(u, ref["U"], ref["P"])) for u in strokes]
            RC = [float(np.interp(u, ref["U"], ref["C"])) for u in strokes] + [ref["S"]]
        else:
            r = V.reference(case)
            if r is None:
                continue
            rname, RP, RC = "own", r["P"], r["C"] + [r["S"]]
        P, C, S = V.values(m, strokes)
        ep = [abs(p / q - 1) for p, q in zip(P, RP)]
        ec = [abs(x - y) for x, y in zip(C + [S], RC)]
        est = estimates(m, c, strokes)
        row = f"| {case} | {preset} | {rname} | {100 * max(ep):.2f} %"
        for name, (lp, _) in est.items():
            row += f" | {100 * max(lp):.2f} %"
        ecm = max((e for e in ec if e == e), default=float("nan"))
        row += f" | {ecm:.4f}"
        for name, (_, lc) in est.items():
            row += f" | {max(lc):.4f}"
        print(row + " |")
        for name, (lp, lc) in est.items():
            for fs in (1, 3):
                t = tally.setdefault((name, fs), {"load": [], "ct": []})
                # bounded per quantity: the largest estimate against the largest error (what a run reports)
                t["load"].append(fs * max(lp) / max(max(ep), 1e-12))
                if ecm == ecm:
                    t["ct"].append(fs * max(lc) / max(ecm, 1e-12))
    print("\n| estimator | F | load: bounded | median estimate / error | C/t: bounded | median estimate / error |")
    print("|---|---|---|---|---|---|")
    for (name, fs), t in tally.items():
        lb, cb = sum(r >= 1 for r in t["load"]), sum(r >= 1 for r in t["ct"])
        print(f"| {name} | {fs} | {lb} of {len(t['load'])} | {np.median(t['load']):.1f} | {cb} of {len(t['ct'])} | "
              f"{np.median(t['ct']):.1f} |")


if __name__ == "__main__":
    main()
