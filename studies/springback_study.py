#!/usr/bin/python3
"""The springback's law: the paper's elastic release (-springback elastic) against the material's own law
(-springback material), on the paper's nine cases, with isotropic hardening and with a saturating
Armstrong-Frederick backstress (AF: 0.6 sigma_y0 reached within p ~ 0.02, as studies/hardening_study.py).

    /usr/bin/python3 studies/springback_study.py [--cases NAME,...] [--preset default] [--unload reverse]

Each case on the preset, -error_estimate 0. The table gives the load and C/t at the end of loading, C/t and
C1/C2 after springback and the springback of the half-extents x_max (C1) and y_max (C2), the Gauss points that
reach the yield surface in the release (material: those that flow in it; elastic: those it carries past the
surface), how far: the largest plastic strain taken in it (material) or the largest excess
sigma_eq / sigma_y - 1 (elastic), and its plastic work over the elastic energy stored where it began (above 1:
a collapse under the loads, docs/theory.md "Unloading"). Runs are kept under results/springback/ (delete one to run it again); the
table goes to results/springback/table.md.
"""
import argparse
import os
import sys

import h5py
import numpy as np

# The helper package python/tubeform_py (python/README.md).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from tubeform_py import tfruns  # noqa: E402

OUT = os.path.join(tfruns.root, "results", "springback")
AL, CU = 165.3, 445.0  # the Ludwik sigma_y0 of the paper's aluminum and copper (its Table 1)
CASES = {}  # (the default tube, options/squaring.opts, is al_11.67_mu0.05)
for tube, sy0 in (("al_11.67", AL), ("al_37", AL), ("cu_29", CU)):
    for mu in ("0.05", "0.20", "0.35"):
        CASES[f"{tube}_mu{mu}"] = (f"options/squaring_{tube}_mu{mu}.opts", sy0)
AF_SHARE, AF_GAMMA = 0.6, 200.0  # the saturating backstress: 0.6 sigma_y0, reached within p ~ 3 / gamma


def row(name, preset, unload, hardening, law, exe):
    """One run and its table row."""
    case, sy0 = CASES[name]
    h5 = os.path.join(OUT, f"{name}_{preset}_{unload}_{hardening}_{law}.h5")
    extra = ["-options_file", f"options/preset-{preset}.opts", "-error_estimate", "0", "-unload", unload,
             "-springback", law]
    if hardening == "AF":
        extra += ["-hardening", "chaboche", "-material_kinematic", f"{AF_SHARE * sy0 * AF_GAMMA:g},{AF_GAMMA:g}"]
    if not os.path.exists(h5):
        wall, inc, _, _ = tfruns.run(case, extra, h5, exe=exe)
        print(f"  {os.path.basename(h5)}: {wall:.1f} s, {inc} increments", flush=True)
    with h5py.File(h5, "r") as f:
        h = f["/history"]
        a = h.attrs
        release = h["stage"][:] == 1
        reached = int(h["release_yielded"][:][release].max())
        how = h["release_dep"][:][release].max() if law == "material" else h["release_excess"][:][release].max()
        # (its plastic work over the elastic energy stored where it began: above 1 a collapse under the loads)
        start = np.flatnonzero(release)[0] - 1
        work = (h["w_plastic"][:][release][-1] - h["w_plastic"][start]) / h["w_elastic"][start]
        return (f"| {name} | {hardening} | {law} | {a['loaded_load']:.2f} | {a['loaded_c_over_t']:.4f} | "
                f"{a['unloaded_c_over_t']:.4f} | {a['unloaded_deviation_ratio']:.4f} | "
                f"{a['unloaded_x_max'] - a['loaded_x_max']:+.4f} | {a['unloaded_y_max'] - a['loaded_y_max']:+.4f} | "
                f"{reached} | {how:.3g} | {work:.3g} | {int(np.count_nonzero(release))} |")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cases", default=",".join(CASES))
    ap.add_argument("--preset", default="default")
    ap.add_argument("--unload", default="reverse", choices=("reverse", "withdraw"))
    ap.add_argument("--hardening", default="isotropic,AF")
    ap.add_argument("--exe", default=tfruns.EXE, help="the tubeform to run")
    a = ap.parse_args()
    os.makedirs(OUT, exist_ok=True)
    lines = ["| case | hardening | springback | load loaded (N/mm) | C/t loaded | C/t sprung back | C1/C2 sprung back | "
             "springback of C1 (mm) | of C2 (mm) | points at the yield surface | how far (dep, or excess) | "
             "plastic work / stored | release increments |", "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for name in a.cases.split(","):
        for hardening in a.hardening.split(","):
            for law in ("elastic", "material"):
                lines.append(row(name, a.preset, a.unload, hardening, law, a.exe))
    text = "\n".join(lines)
    print(text)
    with open(os.path.join(OUT, f"table_{a.unload}.md"), "w") as f:
        f.write(text + "\n")


if __name__ == "__main__":
    main()
