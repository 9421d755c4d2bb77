#!/usr/bin/python3
"""The plastic update against CalculiX (docs/theory.md, section 1, "Radial return"): the default preset's run on
the CalculiX cases of tests/reference/calculix/ with each `-plastic_update` (and the tangent update with
`-drift_correction`), every increment limit divided by s; C/t loaded and after springback, the loads at the
reported strokes, increments and factorizations.

    /usr/bin/python3 studies/plastic_update.py [--cases default,steel,thin,thick] [--steps 1,2,4]

Runs are cached under results/plastic_update/ (delete one to run it again); one rank, one run at a time.
"""
import argparse
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from tubeform_py import tfruns  # noqa: E402

OUT = os.path.join(tfruns.root, "results", "plastic_update")
UPDATES = {"tangent": ["-plastic_update", "tangent"], "radial": ["-plastic_update", "radial"],
           "drift": ["-drift_correction", "1"]}


def run(case, update, s):
    """One run (cached): its history file and its log."""
    h5 = os.path.join(OUT, f"{case}_{update}_s{s}.h5")
    if not os.path.exists(h5):
        opts = tfruns.calculix_reference(case)[0] if case != "default" else []  # (the default tube: the scene's own)
        steps = [] if s == 1 else ["-increments", str(200 * s), "-rmin_deps", repr(0.002 / s), "-rmin_domega",
                                   repr(0.01 / s), "-rmin_deps_yield", repr(2 / s)]
        _, _, _, out = tfruns.run("options/squaring.opts", ["-options_file", "options/preset-default.opts"] + opts +
                                  ["-error_estimate", "0", "-progress", "0"] + UPDATES[update] + steps, h5)
        with open(h5[:-3] + ".log", "w") as f:
            f.write(out)
    return h5, open(h5[:-3] + ".log").read()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cases", default="default,steel,thin,thick")
    ap.add_argument("--steps", default="1,2,4", help="the divisors s of the increment limits")
    a = ap.parse_args()
    os.makedirs(OUT, exist_ok=True)
    print("| case | update | s | C/t loaded / after springback | CalculiX | loads at the strokes (N/mm) | "
          "increments | factorizations |")
    print("|---|---|---|---|---|---|---|---|")
    for case in a.cases.split(","):
        _, ref, spring, stroke = tfruns.calculix_reference(case)
        us = [u for u in (1.0, 2.0, 3.0, 4.2) if u < stroke - 1e-9] + [stroke]
        for update in UPDATES:
            for s in (int(x) for x in a.steps.split(",")):
                if update == "drift" and s != 1:
                    continue
                h5, log = run(case, update, s)
                H = tfruns.history(h5)
                m = re.search(r"done, (\d+) increments, (\d+) factorizations", log)
                loads = " / ".join(f"{tfruns.at(H, 'load', u):.1f}" for u in us)
                print(f"| {case} | {update} | {s} | {tfruns.at(H, 'c_over_t', stroke):.4f} / {H['spring']:.4f} | "
                      f"{tfruns.at(ref, 'c_over_t', stroke):.4f} / {spring:.4f} | {loads} | "
                      f"{m.group(1) if m else '?'} | {m.group(2) if m else '?'} |")


if __name__ == "__main__":
    main()
