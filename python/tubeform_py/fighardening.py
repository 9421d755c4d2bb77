"""The hardening model's figure of scripts/figures: the paper's three tubes at mu 0.05, isotropic hardening against
a saturating Armstrong-Frederick backstress of the same monotonic curve (studies/hardening_study.py's AF model:
0.6 sigma_y0 reached within p ~ 0.02), C/t over the stroke and after springback, with the springback of C1 and C2.
"""
import os

from . import figlib  # (first: it sets the Agg backend)
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

TUBES = ["al_11.67", "al_37", "cu_29"]
# Each tube's Ludwik sigma_y0 (MPa): the paper's aluminum and copper (its Table 1, docs/scenes.md).
SIGMA_Y0 = {"al_11.67": 165.3, "al_37": 165.3, "cu_29": 445.0}
AF_SHARE, AF_GAMMA = 0.6, 200.0  # the saturating backstress: 0.6 sigma_y0, reached within p ~ 3 / gamma


def kinematic_option(tube):
    """-material_kinematic of the AF model for a tube of the paper (its material's sigma_y0)."""
    return f"-material_kinematic {AF_SHARE * SIGMA_Y0[tube] * AF_GAMMA:g},{AF_GAMMA:g}"


def draw(isotropic, kinematic, labels, out):
    """isotropic, kinematic: tube -> result file (figlib.Result paths); labels: tube -> title."""
    fig, axes = plt.subplots(1, len(TUBES), figsize=(4.3 * len(TUBES), 3.7), squeeze=False)
    for ax, tube in zip(axes[0], TUBES):
        for path, name, style in ((isotropic[tube], "isotropic", "-"), (kinematic[tube], "AF backstress", "--")):
            if not os.path.exists(path):
                ax.text(0.5, 0.5, f"{name}: no result", transform=ax.transAxes, ha="center")
                continue
            r = figlib.Result(path)
            u, ct = r.hist["stroke"][r.loading], r.hist["c_over_t"][r.loading]
            a = r.attrs
            dc1 = a["unloaded_x_max"] - a["loaded_x_max"]
            dc2 = a["unloaded_y_max"] - a["loaded_y_max"]
            line, = ax.plot(u, ct, style, label=f"{name}: springback C1 {1e3 * dc1:+.0f}, C2 {1e3 * dc2:+.0f} um")
            ax.plot([u[-1]], [a["unloaded_c_over_t"]], "o", color=line.get_color(), mfc="none")
        ax.set_title(labels[tube], fontsize=10)
        ax.set_xlabel("stroke U (mm)")
        ax.set_ylabel("collapse ratio C/t (circle: after springback)")
        ax.set_ylim(bottom=min(0, ax.get_ylim()[0]))
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="upper left")
    fig.suptitle("Hardening model: isotropic vs a saturating backstress of the same monotonic curve (mu 0.05)",
                 fontsize=10)
    fig.tight_layout()
    return figlib.save(fig, out, "hardening_springback_tubes")
