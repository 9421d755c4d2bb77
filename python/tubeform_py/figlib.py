"""Reading result files and drawing tubes and dies, shared by scripts/plot.py
and scripts/figures (run with /usr/bin/python3)."""
import math
import os

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


from .tfruns import deviation, option  # noqa: E402,F401  (scripts import them from here too)


# Sweep statuses of a case that ran to its end: "inaccurate" only says its own
# error estimate passes the preset's target (scripts/sweep), its results stand.
FINISHED = ("done", "inaccurate")


def finished(row):
    """Whether a sweep summary row ran to its end (its results can be drawn)."""
    return row["status"] in FINISHED


def rt_axis(ax):
    """A logarithmic R/t axis with plain tick labels."""
    ax.set_xscale("log")
    ticks = [6, 8, 10, 15, 20, 30, 40, 60, 80]
    ax.set_xticks(ticks, [str(t) for t in ticks])
    ax.minorticks_off()


class Result:
    """A result file: mesh, displacement and cell fields of every written step,
    the load parameter of each step (`lam`), the history and the options."""

    def __init__(self, path):
        self.path = path
        with h5py.File(path, "r") as h:
            self.X = h["/geometry/vertices"][:]
            self.C = h["/viz/topology/cells"][:]
            self.U = h["/vertex_fields/displacement_u"][:]
            self.lam = h["/time"][:, 0]
            self.cells = {n[:-2]: h["/cell_fields"][n][:] for n in h["/cell_fields"]}
            self.hist = {k: h["/history"][k][:] for k in h["/history"]}
            self.attrs = dict(h["/history"].attrs)
            opts = h.attrs.get("options", b"")
        self.opts = opts.decode() if isinstance(opts, bytes) else str(opts)
        self.stroke = float(option(self.opts, "-stroke", 4.2))
        self.loading = self.hist["stage"] == 0

    def value(self, name, default):
        return float(option(self.opts, name, default))

    def step_at(self, U):
        """The written step of the loading nearest stroke U (mm)."""
        k = np.flatnonzero(self.lam <= 1 + 1e-9)
        return int(k[np.argmin(np.abs(self.lam[k] * self.stroke - U))])

    def loaded_step(self):
        return int(np.flatnonzero(self.lam <= 1 + 1e-9)[-1])

    def unloaded(self):
        return self.lam[-1] > 1 + 1e-9

    def coords(self, step):
        return self.X + self.U[step]

    def column(self, name):
        """A history column over the loading, with the stroke."""
        return self.hist["stroke"][self.loading], self.hist[name][self.loading]

    def deviation(self):
        """The paper's deviation ratio min(C1, C2) / max(C1, C2) over the loading, with the stroke, from x_max (C1)
        and y_max (C2): not the history's deviation_ratio, which is C1 / C2 itself."""
        return self.hist["stroke"][self.loading], deviation(self.hist["x_max"], self.hist["y_max"])[self.loading]


def outline_edges(C):
    """Boundary edges of a quad mesh (edges used by one cell)."""
    count = {}
    for c in C:
        for k in range(4):
            e = tuple(sorted((c[k], c[(k + 1) % 4])))
            count[e] = count.get(e, 0) + 1
    return np.array([e for e, n in count.items() if n == 1])


def draw_outline(ax, xy, edges, **kw):
    """The mesh outline as one line collection."""
    from matplotlib.collections import LineCollection

    ax.add_collection(LineCollection(xy[edges], **kw))


def draw_die(ax, opts, stroke, **kw):
    """The upper V-die of the squaring scene at tool stroke U: a 90-degree V
    whose apex fillet (radius -die_r_apex) touches the round tube at the
    start (docs/dies.md)."""
    ro, ra = float(option(opts, "-tube_ro", 17.5)), float(option(opts, "-die_r_apex", 3))
    h0 = ro * math.sqrt(2) - stroke
    cy = ro * math.sqrt(2) - ra * math.sqrt(2) - stroke
    th = np.linspace(math.pi / 4, math.pi / 2, 30)
    xs = np.array([ra / math.sqrt(2), 1.3 * ro])
    x = np.concatenate((ra * np.cos(th[::-1]), xs))
    y = np.concatenate((cy + ra * np.sin(th[::-1]), h0 - xs))
    ax.plot(x, y, **kw)


def save(fig, outdir, name):
    """PNG (for the docs) and PDF (for print) of a figure; returns the PNG path."""
    os.makedirs(outdir, exist_ok=True)
    png = os.path.join(outdir, name + ".png")
    fig.savefig(png, dpi=130, bbox_inches="tight")
    # No creation date: the same figure gives the same file (no churn in git).
    fig.savefig(os.path.join(outdir, name + ".pdf"), bbox_inches="tight", metadata={"CreationDate": None})
    plt.close(fig)
    return png
