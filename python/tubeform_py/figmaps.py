"""The figures past the paper: a collapse map over R/t and mu, the
press force against R/t, the critical R/t and the die's apex radius, from
scripts/sweep summaries (run with /usr/bin/python3; scripts/figures calls it)."""
import os

from . import figlib  # (first: it sets the Agg backend)
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

CORNER_OVER_T = 4  # the paper's stroke rule: press until the outer corner radius is 4 wall thicknesses
# C/t below this is "no collapse": a gap of a tenth of the wall, twice what a tube lying on the flank
# shows between its nodes on the fast preset's mesh (C/t 0.05-0.07 before any collapse, Figs. 8 and 10).
NO_COLLAPSE = 0.1
DIE_RTS = ["11.67", "37"]
APEX_RADII = ["1", "3", "5", "8"]


def _num(s):
    return float(s) if s not in ("", None) else np.nan


def _grid(rows, column):
    rts = sorted({_num(r["rt"]) for r in rows})
    mus = sorted({_num(r["friction_mu"]) for r in rows})
    Z = np.full((len(mus), len(rts)), np.nan)
    for r in rows:
        if figlib.finished(r):
            Z[mus.index(_num(r["friction_mu"])), rts.index(_num(r["rt"]))] = _num(r[column])
    return rts, mus, Z


def collapse_map(rows, out):
    """C/t at the end of loading and after springback over R/t x mu, values written in the cells."""
    fig, axes = plt.subplots(1, 2, figsize=(13, 4.8))
    zs = [_grid(rows, c) for c in ("C_over_t_loaded", "C_over_t_unloaded")]
    vmax = np.nanmax([z[2] for z in zs])
    for ax, (rts, mus, Z), what in zip(axes, zs, ("at the end of loading", "after springback")):
        im = ax.imshow(Z, origin="lower", aspect="auto", cmap="magma_r", vmin=0, vmax=vmax)
        for i in range(len(mus)):
            for j in range(len(rts)):
                if np.isfinite(Z[i, j]):
                    ax.text(j, i, f"{Z[i, j]:.2f}", ha="center", va="center", fontsize=7,
                            color="w" if Z[i, j] > 0.6 * vmax else "k")
        ax.set_xticks(range(len(rts)), [f"{v:g}" for v in rts])
        ax.set_yticks(range(len(mus)), [f"{v:g}" for v in mus])
        ax.set(xlabel="R/t = Ro / t (Ro 17.5 mm)", ylabel="friction coefficient mu", title=f"collapse ratio C/t {what}")
        fig.colorbar(im, ax=ax, label="C/t")
    fig.suptitle(f"Aluminum, stroke to an outer corner radius of {CORNER_OVER_T} t (the paper's rule)")
    fig.tight_layout()
    return figlib.save(fig, out, "collapse_map")


def press_force(rows, out):
    """The largest punch load of the loading against R/t, one curve per mu."""
    rts, mus, Z = _grid(rows, "P_max")
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    for i, mu in enumerate(mus):
        ax.plot(rts, Z[i], "o-", label=f"mu {mu:g}")
    ax.set_yscale("log")
    figlib.rt_axis(ax)
    ax.set(xlabel="R/t = Ro / t (Ro 17.5 mm)", ylabel="press force, largest punch load (N/mm of tube)",
           title=f"Press force, aluminum, stroke to corner radius {CORNER_OVER_T} t")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    return figlib.save(fig, out, "press_force_rt")


def critical_rt(rows):
    """Per mu, where the grid's runs stop collapsing (C/t < NO_COLLAPSE at the end of loading): the range of
    R/t above which every run is collapse-free (the paper's claim: above 22.75) and the range below which every
    run is. Returns [(mu, above, below)], each a pair of bracketing runs ((rt, C/t) collapsing, (rt, C/t) free)
    or None when the grid has no such range."""
    rts, mus, Z = _grid(rows, "C_over_t_loaded")
    out = []
    for i, mu in enumerate(mus):
        free = Z[i] < NO_COLLAPSE
        hi = len(rts)
        while hi > 0 and free[hi - 1]:
            hi -= 1  # rts[hi:] collapse-free
        lo = 0
        while lo < len(rts) and free[lo]:
            lo += 1  # rts[:lo] collapse-free
        above = ((rts[hi - 1], Z[i, hi - 1]), (rts[hi], Z[i, hi])) if 0 < hi < len(rts) else None
        below = ((rts[lo], Z[i, lo]), (rts[lo - 1], Z[i, lo - 1])) if 0 < lo < len(rts) else None
        out.append((mu, above, below))
    return out


def die_table(rows, path):
    """Markdown: the apex radius's effect at two R/t (the stroke rule fixes the stroke)."""
    lines = [f"Apex radius of the die (`scripts/figures`, grid `die`: aluminum Ro 17.5 mm, mu 0.05, stroke to corner "
             f"radius {CORNER_OVER_T} t)", "",
             "| R/t | apex radius (mm) | largest load (N/mm) | C/t end of loading | C/t after springback | "
             "smallest min(C1, C2)/max(C1, C2) | status |", "|---|---|---|---|---|---|---|"]
    for r in sorted(rows, key=lambda r: (_num(r["rt"]), _num(r["die_r_apex"]))):
        lines.append(f"| {r['rt']} | {r['die_r_apex']} | {_num(r['P_max']):.1f} | {_num(r['C_over_t_loaded']):.3f} | "
                     f"{_num(r['C_over_t_unloaded']):.3f} | {_num(r['deviation_min']):.3f} | {r['status']} |")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return path


def critical_table(rows, path):
    """Markdown: the critical R/t per mu with its bracketing runs."""
    lines = [f"Critical R/t (`scripts/figures`, grid `rule`: aluminum Ro 17.5 mm, stroke to an outer corner radius "
             f"of {CORNER_OVER_T} t; no collapse: C/t < {NO_COLLAPSE} at the end of loading)", "",
             "| mu | no collapse above R/t (paper: 22.75) | no collapse below R/t | bracketing runs (R/t: C/t) |",
             "|---|---|---|---|"]
    fmt = (lambda p: f"{p[0]:g}: {p[1]:.3f}")
    for mu, above, below in critical_rt(rows):
        runs = "; ".join(f"{fmt(pair[0])} and {fmt(pair[1])}" for pair in (above, below) if pair)
        lines.append(f"| {mu:g} | {f'between {above[0][0]:g} and {above[1][0]:g}' if above else 'none in the grid'} | "
                     f"{f'between {below[1][0]:g} and {below[0][0]:g}' if below else 'none in the grid'} | {runs} |")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return path
