#!/usr/bin/python3
"""Plots a tubeform result: load vs stroke (left) and the shapes (right): the
initial mesh (grey), the loaded shape coloured by von Mises stress, and, when
the run unloads, the shape after springback (red outline). For the squaring
scene the die at the final stroke is drawn too.

    /usr/bin/python3 scripts/plot.py results/squaring.h5 results/squaring.png

Small displacements are magnified (the factor is printed in the title).
"""
import math
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402


def option(opts, name, default):
    parts = opts.split()
    return parts[parts.index(name) + 1] if name in parts and parts.index(name) + 1 < len(parts) else default


def outer_outline(X, C):
    """Boundary edges of the mesh (edges used by one cell)."""
    count = {}
    for c in C:
        for k in range(4):
            e = tuple(sorted((c[k], c[(k + 1) % 4])))
            count[e] = count.get(e, 0) + 1
    return [e for e, n in count.items() if n == 1]


def main(path, png):
    with h5py.File(path, "r") as h:
        X = h["/geometry/vertices"][:]
        C = h["/viz/topology/cells"][:]
        U = h["/vertex_fields/displacement_u"][:]
        vm = h["/cell_fields/von_mises_c"][:]
        t = h["/time"][:, 0]
        hist = {k: h["/history"][k][:] for k in h["/history"]}
        opts = h.attrs.get("options", b"")
        opts = opts.decode() if isinstance(opts, bytes) else str(opts)
    scene = option(opts, "-scene", "?")
    loaded = int(np.nonzero(t <= 1.0 + 1e-9)[0][-1])
    unloads = t[-1] > 1.0 + 1e-9

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(13, 5.5))
    stage = hist.get("stage", np.zeros_like(hist["stroke"]))
    ax1.plot(hist["stroke"][stage == 0], hist["load"][stage == 0], "-", label="loading")
    if (stage == 1).any():
        # From the last loading row, so that a few long unloading steps still start at the peak.
        un = np.flatnonzero(stage == 1)
        un = np.concatenate(([un[0] - 1], un)) if un[0] > 0 else un
        ax1.plot(hist["stroke"][un], hist["load"][un], "--", label="unloading")
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
    if unloads:
        for a, b in outer_outline(X, C):
            p = X[[a, b]] + scale * U[-1][[a, b]]
            ax2.plot(p[:, 0], p[:, 1], "r-", lw=0.8)
        ax2.plot([], [], "r-", label="after springback")
        ax2.legend(loc="lower left")
    if scene == "squaring":
        ro, ra = float(option(opts, "-tube_ro", 17.5)), float(option(opts, "-die_r_apex", 3))
        u = hist["stroke"][stage == 0][-1]
        h0 = ro * math.sqrt(2) - u
        cy = ro * math.sqrt(2) - ra * math.sqrt(2) - u
        th = np.linspace(math.pi / 4, math.pi / 2, 30)
        ax2.plot(ra * np.cos(th), cy + ra * np.sin(th), "b-", lw=1.2)
        xs = np.array([ra / math.sqrt(2), 1.3 * ro])
        ax2.plot(xs, h0 - xs, "b-", lw=1.2, label="die at the final stroke")
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
