#!/usr/bin/python3
"""Where the error estimate's companions lie against the converged reference (docs/notes/estimate-validation.md): for
each tube and preset, at the end of loading (load, C/t) and after springback (C/t), the run's error against the
reference of studies/estimate_levels.py, the steps' part on the run's own mesh (S - run: the run at twice its
increment limits), the steps companion the estimate reads (MS - M, on the mesh companion's cells), and the mesh
companion's difference M - run, with whether the three meshes converge in order (M, run, reference: run - M and
reference - run of one sign, as a first-order extrapolation from M through the run assumes).

    /usr/bin/python3 studies/estimate_sides.py --tubes al_11.7_mu0.05,al_6_mu0.2,...

Reads the cache of `estimate_levels.py run --plan preset,estimate,reference` (starts no run).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import estimate_levels as levels  # noqa: E402
from estimate_candidates import at_cells  # noqa: E402


def rows(tubes):
    """(tube, preset, quantity, error, reference's uncertainty, S - run, MS - M, M - run), the load relative."""
    out = []
    for t in tubes:
        ref = levels.reference(t)
        for p in levels.PRESETS if ref is not None else ():
            r = levels.record(t, p)
            if r is None or r["curves"].get("S") is None:
                continue
            n = len(r["strokes"])
            v = {k: at_cells(r, k) for k in ("run", "S", "M", "MS")}
            for k, what in ((n - 1, "load"), (2 * n - 1, "C/t"), (2 * n, "C/t sprung")):
                sc = abs(ref["value"][k]) if k < n else 1.0
                d = lambda a, b: (v[a][k] - v[b][k]) / sc  # noqa: E731
                out.append((t, p, what, (v["run"][k] - ref["value"][k]) / sc, ref["unc"][k] / sc, d("S", "run"),
                            d("MS", "M"), d("M", "run")))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tubes", required=True)
    ap.add_argument("--cache", default=levels.OUT, help="the folder of the cached runs (estimate_levels.py's)")
    a = ap.parse_args()
    levels.OUT = a.cache
    got = rows(a.tubes.split(","))
    if not got:
        sys.exit("estimate_sides.py: no tube with its reference and preset levels (S, M, MS) cached")
    print("| tube | preset | at the end | error | reference's uncertainty | S - run | MS - M | M - run | in order |")
    print("|---" * 9 + "|")
    for t, p, what, e, u, sr, sm, mr in got:
        order = "yes" if -mr * e < 0 and abs(e) > u else "no" if abs(e) > u else "-"
        print(f"| {t} | {p} | {what} | {e:+.4f} | {u:.4f} | {sr:+.4f} | {sm:+.4f} | {mr:+.4f} | {order} |")
    resolved = [x for x in got if abs(x[3]) > x[4]]
    in_order = [x for x in resolved if -x[7] * x[3] < 0]
    ratio = [abs(x[6]) / abs(x[5]) for x in got if abs(x[5]) > 0]
    print(f"\ncells {len(got)}, error beyond the reference's uncertainty {len(resolved)}: M, run and reference in "
          f"order in {len(in_order)} ({len(in_order) / max(1, len(resolved)):.0%}); |MS - M| / |S - run| at 20, 50, "
          f"80 %: " + " ".join(f"{q:.2f}" for q in np.percentile(ratio, [20, 50, 80])))


if __name__ == "__main__":
    main()
