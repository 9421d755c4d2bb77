#!/usr/bin/python3
"""Consecutive levels of accuracy on demand: does the difference between the default preset's run (level 1) and
its level 2 read the preset run's own error? The ground under a level taking the last one as its estimate's mesh
companion (docs/accuracy.md, "Accuracy on demand").

Each tube runs the default preset with the radial return (converged in the step, so that level 2 refines the cells
alone) and -target_load 0.005 -target_levels 2: its level 2 has twice the cells through the wall and around. Both
runs are cached beside studies/estimate_levels.py's (level 1 is that study's `preset_default_radial`, level 2
`demand2_radial`); the reference is that study's (the tangent update's step ladder extrapolated, --update tangent,
or the radial return's own, --update radial, on the tubes that have it).

    /usr/bin/python3 studies/level_pairs.py run  --tubes al_11.7_mu0.05,al_6_mu0.2,... [-j 2]
    /usr/bin/python3 studies/level_pairs.py show --tubes ... [--update radial]

`show` prints per cell (the load relative, at the reported strokes; C/t from U = 2 mm on and after springback)
level 1's and level 2's error against the reference, L1 - L2, the reference's uncertainty, and the effectivity
|L1 - L2| / |error of L1|; then the share of cells where |L1 - L2| reaches level 1's error (and level 2's) less the
reference's uncertainty, and the median effectivity.
"""
import argparse
import concurrent.futures
import os

import numpy as np

import estimate_levels as E

LEVEL2 = ["-options_file", "options/preset-default.opts", "-plastic_update", "radial", "-target_load", "0.005",
          "-target_levels", "2"]
A = np.abs


def run(tubes, jobs):
    E.PRESET_UPDATE = "radial"
    one = lambda t: (t, E.run_preset(t, "default")[0], E.cached_run(  # noqa: E731
        t, "demand2_radial", LEVEL2, lambda l: "level" in l or "estimated error" in l)[0])
    with concurrent.futures.ThreadPoolExecutor(jobs) as ex:
        for t, m1, m2 in ex.map(one, tubes):
            print(f"{t:22s} level 1 {m1['status']} {m1['wall']:.0f} s, level 2 {m2['status']} {m2['wall']:.0f} s")


def level_values(t, tag, st):
    P, C, S, _ = E.values(os.path.join(E.OUT, t, tag + ".h5"), st)
    return np.array(P + C + [S])


def show(tubes):
    cells = []
    print("| tube | value | at | error, level 1 | error, level 2 | L1 - L2 | reference's uncertainty | effectivity |")
    print("|---|---|---|---|---|---|---|---|")
    for t in tubes:
        ref, st = E.reference(t), E.strokes(t)
        if ref is None or not all(E.done(os.path.join(E.OUT, t, x)) for x in ("preset_default_radial",
                                                                                "demand2_radial")):
            print(f"| {t} | no reference or level runs cached |")
            continue
        n = len(st)
        v1, v2 = level_values(t, "preset_default_radial", st), level_values(t, "demand2_radial", st)
        scale = np.array([abs(x) for x in ref["value"][:n]] + [1.0] * (n + 1))
        e1, e2, d, u = (v1 - ref["value"]) / scale, (v2 - ref["value"]) / scale, (v1 - v2) / scale, ref["unc"] / scale
        for k in [k for k in range(2 * n + 1) if k < n or k == 2 * n or st[k - n] >= 2 - 1e-9]:
            cells.append((e1[k], e2[k], d[k], u[k]))
            print(f"| {t} | {'load' if k < n else 'C/t'} | {(st + st + ['sprung'])[k]} | {e1[k]:+.4f} | {e2[k]:+.4f} | "
                  f"{d[k]:+.4f} | {u[k]:.4f} | {A(d[k]) / max(A(e1[k]), 1e-12):.2f} |")
    if not cells:
        return
    e1, e2, d, u = (np.array([c[i] for c in cells]) for i in range(4))
    eff = A(d) / np.maximum(A(e1), 1e-12)
    resolved = A(e1) >= 2 * u
    print(f"\ncells {len(cells)}: |L1 - L2| reaches level 1's error in {np.mean(A(d) >= A(e1) - u):.0%} "
          f"(level 2's in {np.mean(A(d) >= A(e2) - u):.0%}); median effectivity for level 1 {np.median(eff):.2f} "
          f"({resolved.sum()} cells resolved by the reference: {np.median(eff[resolved]):.2f})")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("what", choices=("run", "show"))
    ap.add_argument("--tubes", required=True)
    ap.add_argument("-j", type=int, default=1)
    ap.add_argument("--update", choices=("tangent", "radial"), default="tangent", help="the reference's update")
    ap.add_argument("--cache", default=E.OUT, help="the folder of the cached runs (estimate_levels.py's)")
    a = ap.parse_args()
    E.OUT, E.UPDATE = a.cache, a.update
    tubes = a.tubes.split(",")
    run(tubes, a.j) if a.what == "run" else show(tubes)


if __name__ == "__main__":
    main()
