#!/usr/bin/python3
"""How well a run's error estimate bounds its true error, for candidate estimators, on the tubes of
scripts/validate (docs/accuracy.md, "The error estimate").

    /usr/bin/python3 scripts/estimate_study.py [--cases a,b] [--presets fast,default] [-j N]

For each tube and preset it takes the preset's run cached by scripts/validate (results/validate/) and runs
its companion (the run's own estimate's coarser pass: half the cells through the wall, at least 2, and
around, half the trial increments) as a run of its own, cached beside it (<tube>_<preset>_companion.h5).
The true error is measured against the CalculiX reference of the tube where one exists
(scripts/validate's ccx_reference: its middle or fine mesh whose loading finished; loading only) and
against scripts/validate's extrapolated reference otherwise. Estimators, each at the reported strokes (load, C/t)
and after springback (C/t):

  raw      |run - companion| at the stroke, relative to the run's load (what the runs print, times the factor;
           checked equal to each run's own estimate)
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
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

V = importlib.machinery.SourceFileLoader("validate", os.path.join(HERE, "validate")).load_module()
WINDOW = 0.15  # mm of stroke each side: a few ripple periods on the default preset (0.05-0.1 mm each)
# The factor the runs apply to their companion's difference (include/tubeform/driver/answer.hpp).
RUN_FACTOR = float(re.search(r"kEstimateSafety = ([0-9.]+);",
                             open(os.path.join(V.tfruns.root, "include", "tubeform", "driver",
                                               "answer.hpp")).read()).group(1))


def preset_option(preset, name):
    """A numeric option of a preset file (comment lines left out)."""
    text = [line for line in open(os.path.join(V.tfruns.root, "options", f"preset-{preset}.opts"))
            if not line.lstrip().startswith("#")]
    return int(V.tfruns.option(" ".join(text), name))


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
    """The run's companion as src/main.cpp makes it (Companion()): half the cells through the wall (at least 2)
    and around, half the trial and unloading increments."""
    main = os.path.join(V.OUT, f"{case}_{preset}.h5")
    nt, nth = mesh_of(main)
    inc, uinc = preset_option(preset, "-increments"), preset_option(preset, "-unload_increments")
    extra = ["-options_file", f"options/preset-{preset}.opts", "-error_estimate", 0, "-mesh_nt", max(2, nt // 2),
             "-mesh_ntheta", max(4, 2 * (nth // 4)), "-increments", max(1, inc // 2), "-unload_increments",
             max(1, uinc // 2)]
    return V.run(case, f"{preset}_companion", extra)


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
    # (relative to the run's load, as src/driver/answer.cpp takes it)
    out["raw"] = ([abs(p - q) / abs(p) for p, q in zip(P, Pc)], [abs(x - y) for x, y in zip(C, Cc)] + [abs(S - Sc)])
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
    unknown = [c for c in cases if c not in V.CASES] + [p for p in presets if p not in V.PRESETS]
    if unknown:
        ap.error(f"unknown tube or preset {', '.join(unknown)} (tubes: {', '.join(V.CASES)}; presets: "
                 f"{', '.join(V.PRESETS)})")
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
        ref = V.ccx_reference(case)
        rname = "own" if ref is None else ref["label"]
        ref = ref or V.reference(case)
        if ref is None:
            continue
        RP, RC = ref["P"], ref["C"] + [ref["S"]]
        P, C, S = V.values(m, strokes)
        ep = [abs(p / q - 1) for p, q in zip(P, RP)]
        ec = [abs(x - y) for x, y in zip(C + [S], RC)]
        est = estimates(m, c, strokes)
        # The replica of the companion must be the run's own: its "raw" difference times the run's factor is the
        # estimate the run wrote.
        own = (float(m["attrs"]["error_load"]), float(m["attrs"]["error_c_over_t"]))
        mine = (RUN_FACTOR * max(est["raw"][0]), RUN_FACTOR * max(e for e in est["raw"][1] if e == e))
        if any(abs(x - y) > 1e-9 * max(abs(x), 1e-12) for x, y in zip(own, mine)):
            sys.exit(f"estimate_study.py: {case} {preset}: the companion here gives {mine}, the run wrote {own}: "
                     "the companion's rules (src/main.cpp) and companion() above differ")
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
