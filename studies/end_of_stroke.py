#!/usr/bin/python3
"""tubeform's own convergence on a CalculiX case, one refinement at a time, against the CalculiX reference: what the
default preset's load error at the reported strokes is once the cells through the wall, the cells around (each
level a family of nearby counts, so that the contact ripple averages out) and the increment limits are refined.

    /usr/bin/python3 studies/end_of_stroke.py run  [--cases default,steel] [--around 1,2,4] [-j 1]
    /usr/bin/python3 studies/end_of_stroke.py eval [--cases default,steel] [--around 1,2,4]

Every run is the case's loading (options of tests/reference/calculix/<case>.csv's `# case:` line, the default
preset, no estimate, no unloading) with the element the preset chose on its own mesh kept (-element). For the
preset's mesh nt x N:
- through: 1, 1.5, 2, 3 and 4 x nt cells through the wall, N around;
- phase: N - 8, N - 4, N + 4, N + 8 around (nt and 2 nt through): where the wall's nodes meet the die's flank;
- around: 2 nt through, N, 2 N and 4 N around (--around), each with its phase family (+-4, +-8);
- steps: 2 nt x 2 N at the increment limits / 2 and / 4 (-rmin_deps, -rmin_deps_yield, -rmin_domega, -increments);
- update: 2 nt x 2 N with the radial return (-plastic_update radial) in place of the tangent update.
Runs are cached under results/end_of_stroke/ (delete one to run it again). `eval` prints each level's load at the
reported strokes (its family's mean and spread where it has one), the preset's run against the finest level
and against CalculiX, and the shipped estimate of studies/estimate_ccx.py's runs (where its cache has them)
against the finest level.
"""
import argparse
import concurrent.futures
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from tubeform_py import tfruns  # noqa: E402

OUT = os.path.join(tfruns.root, "results", "end_of_stroke")
# The default preset's increment limits (options/preset-default.opts; -rmin_deps, -rmin_domega the driver's).
LIMITS = (200, 0.002, 0.01, 2.0)
PHASE = (-8, -4, 4, 8)  # cells around added to a level's count: its family


def run_one(case, name, extra):
    opts, _, _, _ = tfruns.calculix_reference(case)
    h5 = os.path.join(OUT, f"{case}_{name}.h5")
    if not os.path.exists(h5):
        _, _, _, out = tfruns.run("options/squaring.opts", ["-options_file", "options/preset-default.opts"] + opts +
                                  ["-error_estimate", "0", "-unload", "none", "-progress", "0", "-output_every",
                                   "100000"] + extra, h5)
        with open(h5[:-3] + ".log", "w") as f:
            f.write(out)
    return h5


def preset_mesh(case):
    """The preset's own run of the case, and its cells through the wall, around, and element."""
    h5 = run_one(case, "preset", [])
    m = re.search(r"-mesh_nt (\d+) through the wall x -mesh_ntheta (\d+) around\), (\w+) elements",
                  open(h5[:-3] + ".log").read())
    return int(m.group(1)), int(m.group(2)), m.group(3)


def steps(s):
    inc, deps, dom, dy = LIMITS
    return ["-increments", str(inc * s), "-rmin_deps", repr(deps / s), "-rmin_domega", repr(dom / s),
            "-rmin_deps_yield", repr(dy / s)]


def plan(case, around=(1, 2, 4)):
    """Each level: name -> the runs of its family (name, options); `around`: the multiples of the preset's cells
    around whose families run with 2 nt through the wall."""
    nt, n, element = preset_mesh(case)
    cells = lambda a, b: ["-element", element, "-mesh_nt", str(a), "-mesh_ntheta", str(b)]  # noqa: E731
    family = lambda a, b: [(f"{a}x{b + d}", cells(a, b + d)) for d in (0,) + PHASE]  # noqa: E731
    levels = {f"through {k}": [(f"{k}x{n}", cells(k, n))] for k in sorted({nt, round(1.5 * nt), 2 * nt, 3 * nt,
                                                                             4 * nt})}
    levels[f"{nt} x {n} family"] = family(nt, n)
    for m in around:
        levels[f"{2 * nt} x {m * n} family"] = family(2 * nt, m * n)
    for s in (2, 4):
        levels[f"{2 * nt} x {2 * n}, limits / {s}"] = [(f"{2 * nt}x{2 * n}_s{s}", cells(2 * nt, 2 * n) + steps(s))]
    levels[f"{2 * nt} x {2 * n}, radial return"] = [(f"{2 * nt}x{2 * n}_radial", cells(2 * nt, 2 * n) +
                                                     ["-plastic_update", "radial"])]
    return levels


def reported(case, h5, col):
    """Column `col` at the reported strokes (the load from 1 mm, C/t from 2 mm on) of a run and of CalculiX."""
    _, ref, _, stroke = tfruns.calculix_reference(case)
    us = [u for u in (1.0, 2.0, 3.0, 4.2) if u < stroke - 1e-9 and (col == "load" or u >= 2)] + [stroke]
    H = tfruns.history(h5)
    return us, np.array([tfruns.at(H, col, u) for u in us]), np.array([tfruns.at(ref, col, u) for u in us])


def table(case, col, fmt, levels):
    """Every level's values of `col` (a family: its mean and half its spread), the preset's against the finest
    family's and CalculiX's (the load relative, in %; C/t absolute)."""
    us, preset, ccx = reported(case, run_one(case, "preset", []), col)
    print(f"\n{case}: {col} at U = {', '.join(f'{u:g}' for u in us)} mm; a family: its mean (+- half its spread)")
    print(f"{'CalculiX 8 x 180 (tests/reference/calculix)':44s} " + "  ".join(fmt.format(x) for x in ccx))
    print(f"{'the preset':44s} " + "  ".join(fmt.format(x) for x in preset))
    means = {}
    for name, runs in levels.items():
        v = np.array([reported(case, run_one(case, r, extra), col)[1] for r, extra in runs])
        means[name] = v.mean(axis=0)
        spread = (v.max(axis=0) - v.min(axis=0)) / 2
        print(f"{name:44s} " + "  ".join(fmt.format(m) + (" +-" + fmt.format(s).strip() if len(runs) > 1 else "")
                                          for m, s in zip(means[name], spread)))
    finest = [k for k in means if k.endswith("family")][-1]
    diff = (lambda a, b: f"{100 * (a / b - 1):+.2f}") if col == "load" else (lambda a, b: f"{a - b:+.4f}")
    print(f"the preset against {finest}: " + ", ".join(diff(p, f) for p, f in zip(preset, means[finest])))
    print("the preset against CalculiX: " + ", ".join(diff(p, c) for p, c in zip(preset, ccx)))
    print(f"{finest} against CalculiX: " + ", ".join(diff(f, c) for f, c in zip(means[finest], ccx)))


def finest(case, levels, col):
    """The finest family's mean of `col` at the reported strokes."""
    runs = [r for k, r in levels.items() if k.endswith("family")][-1]
    return np.mean([reported(case, run_one(case, r, extra), col)[1] for r, extra in runs], axis=0)


def shipped(case, levels):
    """The shipped estimate of studies/estimate_ccx.py's runs (its cache: the fast and default presets with their
    companions) against the finest family: each reported load (%) and loaded C/t, error / estimate."""
    import estimate_ccx  # (beside this file: its runs, its values)
    ref_l, ref_c = finest(case, levels, "load"), finest(case, levels, "c_over_t")
    for preset in ("fast", "default"):
        f = {k: os.path.join(estimate_ccx.OUT, f"{case}_{preset}_{k}.h5") for k in ("run", "M", "S")}
        if not all(os.path.exists(p) for p in f.values()):
            print(f"{case} {preset}: no runs of studies/estimate_ccx.py to compare")
            continue
        run, m, s = (estimate_ccx.values(p, case) for p in f.values())
        est_l, est_c = estimate_ccx.shipped(run, m, s)
        est_c = est_c[:-1]  # (loaded: the ladder has no springback)
        err_l, err_c = np.abs(run[1] / ref_l - 1), np.abs(run[2][:-1] - ref_c)
        print(f"{case} {preset}, the shipped estimate against the finest family, error / estimate: load " +
              ", ".join(f"{100 * e:.2f}/{100 * x:.2f} %" for e, x in zip(err_l, est_l)) + "; C/t " +
              ", ".join(f"{e:.4f}/{x:.4f}" for e, x in zip(err_c, est_c)))


def evaluate(case, around):
    levels = plan(case, around)
    table(case, "load", "{:8.2f}", levels)
    table(case, "c_over_t", "{:7.4f}", levels)
    shipped(case, levels)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("what", choices=("run", "eval"))
    ap.add_argument("--cases", default="default,steel")
    ap.add_argument("-j", type=int, default=1)
    ap.add_argument("--around", default="1,2,4", help="multiples of the preset's cells around run as families "
                    "(2 x its cells through the wall); 1,2 on a costly case")
    a = ap.parse_args()
    os.makedirs(OUT, exist_ok=True)
    cases = a.cases.split(",")
    try:
        around = tuple(int(m) for m in a.around.split(","))
    except ValueError:
        around = ()
    if not around or min(around) < 1:
        sys.exit(f"end_of_stroke.py: --around {a.around}: positive whole multiples, comma-separated (1,2,4)")
    if a.what == "run":
        jobs = [(c, r, extra) for c in cases for runs in plan(c, around).values() for r, extra in runs]
        with concurrent.futures.ThreadPoolExecutor(a.j) as pool:
            for f in [pool.submit(run_one, *job) for job in jobs]:
                f.result()
    for c in cases:
        evaluate(c, around)


if __name__ == "__main__":
    main()
