#!/usr/bin/python3
"""What the hardening model moves: the paper's squaring with its
springback, isotropic against mixed and kinematic hardening of the same
monotonic flow curve.

    /usr/bin/python3 studies/hardening_study.py [--cases NAME,...] [--preset default] [--figure-cases NAME,...]

The paper gives no cyclic data, so this is a sensitivity study, not a
calibration: Hodge's mixed hardening with a linear (Prager) backstress taking
the share 1 - M of the Ludwik hardening, -material_kinematic C,0 with
C = (1 - M) K, for M = 1 (isotropic), 0.5 and 0 (the whole hardening
kinematic; the flow curve sigma_y0 + K p^n stays the monotonic curve, docs/theory.md
"Kinematic hardening"); and a saturating Armstrong-Frederick backstress of
0.6 sigma_y0 reached within p ~ 0.02 (C = 0.6 sigma_y0 gamma, gamma = 200: the
shape tests/check_kinematic.py verifies), a strong Bauschinger effect whose
reverse yield comes near zero stress. Each case on the preset; the table gives the load at
the end of loading, C/t and C1/C2 = x_max / y_max loaded and after
springback, and the springback of the half-extents x_max (C1, across the
press) and y_max (C2, along it) (the paper's elastic springback:
studies/springback_study.py has what the material's own law changes), and
docs/figures/hardening_springback.png draws C/t over the stroke of each run
with its value after springback. Runs are kept under results/hardening/
(delete one to run it again); the table goes to results/hardening/table.md.
"""
import argparse
import os
import sys

import h5py

# The helper package python/tubeform_py (python/README.md).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from tubeform_py import tfruns  # noqa: E402

OUT = os.path.join(tfruns.root, "results", "hardening")
# case name -> (options file, Ludwik sigma_y0 and K of its material: the paper's Table 1, docs/scenes.md)
AL, CU = (165.3, 673.5), (445.0, 3628.6)
CASES = {}  # (the default case, options/squaring.opts, is al_11.67_mu0.05)
for tube, material in (("al_11.67", AL), ("al_37", AL), ("cu_29", CU)):
    for mu in ("0.05", "0.20", "0.35"):
        CASES[f"{tube}_mu{mu}"] = (f"options/squaring_{tube}_mu{mu}.opts",) + material
FIGURE_CASES = "al_11.67_mu0.05,al_37_mu0.05,cu_29_mu0.05"  # the figure's panels (the table has every case)
MIXED = (1.0, 0.5, 0.0)  # Hodge's M: the isotropic share of the hardening
AF_SHARE, AF_GAMMA = 0.6, 200.0  # the saturating backstress: 0.6 sigma_y0, reached within p ~ 3 / gamma


def row(name, preset, m):
    """One run: m the isotropic share (Hodge's M) with a linear backstress, or "AF" the saturating one."""
    case, sy0, k = CASES[name]
    h5 = os.path.join(OUT, f"{name}_{preset}_M{m}.h5")
    extra = ["-options_file", f"options/preset-{preset}.opts", "-error_estimate", "0", "-springback", "elastic"]
    if m == "AF":
        extra += ["-hardening", "chaboche", "-material_kinematic", f"{AF_SHARE * sy0 * AF_GAMMA:g},{AF_GAMMA:g}"]
    elif m < 1:
        extra += ["-hardening", "chaboche", "-material_kinematic", f"{(1 - m) * k:g},0"]
    if not os.path.exists(h5):
        wall, inc, _, _ = tfruns.run(case, extra, h5)
        print(f"  {os.path.basename(h5)}: {wall:.1f} s, {inc} increments", flush=True)
    with h5py.File(h5, "r") as f:
        a = f["/history"].attrs
        # (C1/C2 from the half-extents: a file's deviation_ratio was min/max before it was C1/C2)
        ratio = {w: a[f"{w}_x_max"] / a[f"{w}_y_max"] for w in ("loaded", "unloaded")}
        return (f"| {name} | {m} | {a['loaded_load']:.2f} | {a['loaded_c_over_t']:.4f} | "
                f"{ratio['loaded']:.4f} | {a['unloaded_c_over_t']:.4f} | {ratio['unloaded']:.4f} | "
                f"{a['unloaded_x_max'] - a['loaded_x_max']:+.4f} | {a['unloaded_y_max'] - a['loaded_y_max']:+.4f} |")


def figure(names, preset):
    """C/t over the loading of each case and model, and after springback (the markers at the end)."""
    from tubeform_py import figlib  # noqa: F401  (matplotlib without a display)
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(names), figsize=(4.2 * len(names), 3.6), squeeze=False)
    for ax, name in zip(axes[0], names):
        for m, style in zip(MIXED + ("AF",), ("-", "--", ":", "-.")):
            with h5py.File(os.path.join(OUT, f"{name}_{preset}_M{m}.h5"), "r") as f:
                h = f["/history"]
                load = h["stage"][:] == 0
                u, ct = h["stroke"][:][load], h["c_over_t"][:][load]
                label = "isotropic" if m == 1.0 else (f"M = {m:g} (linear)" if m != "AF" else "AF (saturating)")
                line, = ax.plot(u, ct, style, label=label)
                ax.plot([u[-1]], [h.attrs["unloaded_c_over_t"]], "o", color=line.get_color(), mfc="none")
        ax.set_title(name)
        ax.set_xlabel("stroke U (mm)")
        ax.set_ylabel("C/t (circle: after springback)")
        ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=8)
    fig.tight_layout()
    path = os.path.join(tfruns.root, "docs", "figures", "hardening_springback.png")
    fig.savefig(path, dpi=110)
    print(f"figure: {path}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cases", default=",".join(CASES))
    ap.add_argument("--preset", default="default")
    ap.add_argument("--figure-cases", default=FIGURE_CASES, help="the cases the figure draws")
    a = ap.parse_args()
    os.makedirs(OUT, exist_ok=True)
    lines = ["| case | M (isotropic share), or AF | load at the end of loading (N/mm) | C/t loaded | C1/C2 loaded | "
             "C/t sprung back | C1/C2 sprung back | springback of C1 (mm) | of C2 (mm) |",
             "|---|---|---|---|---|---|---|---|---|"]
    for name in a.cases.split(","):
        for m in MIXED + ("AF",):
            lines.append(row(name, a.preset, m))
    text = "\n".join(lines)
    print(text)
    with open(os.path.join(OUT, "table.md"), "w") as f:
        f.write(text + "\n")
    figure([c for c in a.figure_cases.split(",") if c in a.cases.split(",")], a.preset)


if __name__ == "__main__":
    main()
