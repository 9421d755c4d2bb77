#!/usr/bin/python3
"""Plots a tubeform result: load vs stroke (left; with the error estimate, its band) and the shapes (right): the
initial mesh (grey), the loaded shape coloured by von Mises stress, and, when
the run unloads, the shape after springback (red outline). A tool scene's
tools are drawn where they were at the loaded state (from the result file's
/tools). With two passes (-pass2_stroke) the curve has both presses and
springbacks; the shapes are the second pass's.

    /usr/bin/python3 scripts/plot.py results/squaring.h5 results/squaring.png

Small displacements are magnified (the factor is printed in the title).
"""
import os
import sys

# The helper package python/tubeform_py (python/README.md).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from tubeform_py.figlib import draw_die, option, outline_edges  # noqa: E402  (first: it sets the Agg backend)
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402


def main(path, png):
    tools = []  # (outline's points at the loaded step, lines)
    with h5py.File(path, "r") as h:
        X = h["/geometry/vertices"][:]
        C = h["/viz/topology/cells"][:]
        U = h["/vertex_fields/displacement_u"][:]
        vm = h["/cell_fields/von_mises_c"][:]
        t = h["/time"][:, 0]
        hist = {k: h["/history"][k][:] for k in h["/history"]}
        opts = h.attrs.get("options", b"")
        opts = opts.decode() if isinstance(opts, bytes) else str(opts)
        # The loaded state: the end of the last press (lambda 1, or 3 with a second pass).
        press_end = 3.0 if t[-1] > 2.0 + 1e-9 else 1.0
        loaded = int(np.nonzero(t <= press_end + 1e-9)[0][-1])
        for name in h.get("/tools", {}):
            g = h["/tools"][name]
            d = g["displacement"]
            if d.attrs.get("first_step", 0) <= loaded < d.shape[0]:
                tools.append((g["vertices"][:] + d[loaded], g["lines"][:]))
    scene = option(opts, "-scene", "?")
    unloads = t[-1] > press_end + 1e-9

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(13, 5.5))
    stage = hist.get("stage", np.zeros_like(hist["stroke"]))
    names = {0: ("loading", "-", "C0"), 1: ("unloading", "--", "C1"), 2: ("second press", "-", "C2"),
             3: ("second springback", "--", "C3")}
    for st, (label, style, color) in names.items():
        rows = np.flatnonzero(stage == st)
        if not len(rows):
            continue
        # From the row before, so that a few long unloading steps still start at the peak.
        rows = np.concatenate(([rows[0] - 1], rows)) if rows[0] > 0 and st > 0 else rows
        ax1.plot(hist["stroke"][rows], hist["load"][rows], style, color=color, label=label)
        if "error_load" in hist and st % 2 == 0:
            # The run's estimate of its error, row by row (docs/accuracy.md, "The error estimate").
            e = np.nan_to_num(hist["error_load"][rows])
            u, p = hist["stroke"][rows], hist["load"][rows]
            ax1.fill_between(u, p * (1 - e), p * (1 + e), color=color, alpha=0.2, lw=0,
                             label="estimated error" if st == 0 else None)
    if (stage > 0).any() or "error_load" in hist:
        ax1.legend()
    xlabel, ylabel = "stroke U (mm)", "punch load, full tube (N/mm)"
    if scene == "pressure":
        xlabel, ylabel = "inner radial displacement (mm)", "internal pressure (MPa)"
    ax1.set_xlabel(xlabel)
    ax1.set_ylabel(ylabel)
    ax1.set_title(f"{scene}: load vs stroke")
    ax1.grid(True, alpha=0.3)

    size = np.ptp(X, axis=0).max()
    umax = np.abs(U[loaded]).max()
    scale = 1.0 if umax > 0.01 * size or umax == 0 else 0.05 * size / umax
    ax2.add_collection(PolyCollection(X[C], facecolors="none", edgecolors="0.75", linewidths=0.3))
    shape = PolyCollection((X + scale * U[loaded])[C], array=vm[loaded], cmap="viridis", edgecolors="k", linewidths=0.15)
    ax2.add_collection(shape)
    fig.colorbar(shape, ax=ax2, label="von Mises stress, loaded (MPa)")
    for k, (xy, lines) in enumerate(tools):
        for i, (a, b) in enumerate(lines):
            ax2.plot(xy[[a, b], 0], xy[[a, b], 1], "b-", lw=1.2, label="tools, loaded" if k == 0 and i == 0 else None)
    if scene == "squaring" and not tools:  # (a result written before the tools were)
        draw_die(ax2, opts, hist["stroke"][stage == 0][-1], color="b", lw=1.2, label="die at the final stroke")
    if unloads:
        for a, b in outline_edges(C):
            p = X[[a, b]] + scale * U[-1][[a, b]]
            ax2.plot(p[:, 0], p[:, 1], "r-", lw=0.8)
        ax2.plot([], [], "r-", label="after springback")
    if unloads or tools:
        ax2.legend(loc="lower left")
    ax2.autoscale()
    ax2.set_aspect("equal")
    ax2.set_xlabel("x (mm)")
    ax2.set_ylabel("y (mm)")
    ax2.set_title("shapes: initial (grey), loaded" + (", springback (red)" if unloads else "") + (f", displacement x{scale:.0f}" if scale != 1 else ""))
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    print(f"plot: {png}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot.py RESULT.h5 OUT.png")
    main(sys.argv[1], sys.argv[2])
