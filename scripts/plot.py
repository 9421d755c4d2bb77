#!/usr/bin/python3
"""Plots a tubeform result: load vs stroke (left) and the mesh, initial and
deformed, coloured by von Mises stress (right).

    /usr/bin/python3 scripts/plot.py results/pressure.h5 results/pressure.png

Small displacements are magnified (the factor is printed in the title).
"""
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402


def main(path, png):
    with h5py.File(path, "r") as h:
        X = h["/geometry/vertices"][:]
        C = h["/viz/topology/cells"][:]
        U = h["/vertex_fields/displacement_u"][-1]
        vm = h["/cell_fields/von_mises_c"][-1]
        hist = {k: h["/history"][k][:] for k in h["/history"]}
        opts = h.attrs.get("options", b"")
        opts = opts.decode() if isinstance(opts, bytes) else str(opts)
    scene = opts.split("-scene ")[1].split()[0] if "-scene " in opts else "?"

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 5))
    ax1.plot(hist["stroke"], hist["load"], "o-", ms=3)
    xlabel, ylabel = "stroke U (mm)", "punch load, full tube (N/mm)"
    if scene == "pressure":
        xlabel, ylabel = "inner radial displacement (mm)", "internal pressure (MPa)"
    ax1.set_xlabel(xlabel)
    ax1.set_ylabel(ylabel)
    ax1.set_title(f"{scene}: load vs stroke")
    ax1.grid(True, alpha=0.3)

    size = np.ptp(X, axis=0).max()
    umax = np.abs(U).max()
    scale = 1.0 if umax > 0.01 * size or umax == 0 else 0.05 * size / umax
    ax2.add_collection(PolyCollection(X[C], facecolors="none", edgecolors="0.7", linewidths=0.4))
    deformed = PolyCollection((X + scale * U)[C], array=vm, cmap="viridis", edgecolors="k", linewidths=0.2)
    ax2.add_collection(deformed)
    fig.colorbar(deformed, ax=ax2, label="von Mises stress (MPa)")
    ax2.autoscale()
    ax2.set_aspect("equal")
    ax2.set_xlabel("x (mm)")
    ax2.set_ylabel("y (mm)")
    ax2.set_title("initial (grey) and final shape" + (f", displacement x{scale:.0f}" if scale != 1 else ""))
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    print(f"plot: {png}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot.py RESULT.h5 OUT.png")
    main(sys.argv[1], sys.argv[2])
