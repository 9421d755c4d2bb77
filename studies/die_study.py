#!/usr/bin/python3
"""Which die would make the paper's collapse claims hold: "R/t 37 fits the die without
collapse" (its Fig. 4b, at U = 4.2 mm) and "no collapse above R/t 22.75" (Figs. 10 and 12, pressed by its
rule to an outer corner radius of 4 t). Aluminum tubes of Ro 17.5 mm at mu 0.05, R/t 11.67 to 50, pressed
4.2 mm by V-dies of 80, 90 (the paper's) and 100 degrees and by a flat-bottomed die
(options/dies/flat_bottom.profile), and by the rule with the three V-dies (the rule is the V's);
fast preset (its C/t within 0.05, docs/accuracy.md).

    /usr/bin/python3 studies/die_study.py [--preset fast] [-j JOBS]

Runs go to results/sweep/die_*; the table to stdout and results/die_study.md; the figures to
docs/figures/die_collapse.png (C/t at the end of loading against R/t, one curve per die, the paper's
claims as the shaded region where they say C/t is near zero) and docs/figures/die_collapse_map.png (the
collapse map of each die: C/t along the stroke for each R/t, and the stroke where it passes the
no-collapse line, also in the table's last rows). Never tuned toward the paper: the dies are the obvious
neighbours of its unstated one.
"""
import argparse
import csv
import glob
import os
import subprocess
import sys

# The helper package python/tubeform_py (python/README.md).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from tubeform_py import figlib, figmaps, tfruns  # noqa: E402  (figlib first: the Agg backend)
import matplotlib.pyplot as plt  # noqa: E402

RTS = ["11.67", "22.75", "37", "50"]
ANGLES = ["80", "90", "100"]
SCENE = "options/squaring_al_11.67_mu0.05.opts"
FLAT = "options/dies/flat_bottom.profile"


def sweep(name, axes, options, preset, jobs, more=()):
    cmd = ["/usr/bin/python3", os.path.join(tfruns.root, "scripts", "sweep"), "--name", name, "--scene", SCENE,
           "--preset", preset, "-j", str(jobs), "--options", options + " -error_estimate 0"]
    for a in axes:
        cmd += ["--axis", a]
    subprocess.run(cmd + list(more), cwd=tfruns.root, check=False)
    with open(os.path.join(tfruns.root, "results", "sweep", name, "summary.csv")) as f:
        return list(csv.DictReader(f))


def ct(rows, key, value):
    """C/t at the end of loading per R/t for the rows with rows[key] == value (all rows if key is None)."""
    out = {}
    for r in rows:
        if (key is None or r[key] == value) and figlib.finished(r):
            out[float(r["rt"])] = float(r["C_over_t_loaded"])
    return out


def histories(name, key):
    """{(value of `key` or None, R/t): (stroke, C/t) of the loading stage} of a sweep's result files."""
    import h5py
    out = {}
    for path in glob.glob(os.path.join(tfruns.root, "results", "sweep", name, "*.h5")):
        parts = dict(p.split("-", 1) for p in os.path.basename(path)[:-3].split("_rt-")[0:1] if "-" in p)
        rt = float(os.path.basename(path)[:-3].split("rt-")[1])
        try:
            with h5py.File(path, "r") as h:
                s = h["/history/stage"][:] == 0
                out[(parts.get(key), rt)] = (h["/history/stroke"][:][s], h["/history/c_over_t"][:][s])
        except (OSError, KeyError):
            continue  # a run that did not finish
    return out


def onset(curve):
    """The stroke where C/t first passes the no-collapse line (linear between rows), None if it never does."""
    u, c = curve
    for k in range(1, len(u)):
        if c[k] > figmaps.NO_COLLAPSE >= c[k - 1]:
            return u[k - 1] + (figmaps.NO_COLLAPSE - c[k - 1]) / (c[k] - c[k - 1]) * (u[k] - u[k - 1])
    return None


def collapse_map(preset):
    """One panel per die: C/t along the stroke for each R/t; the onset strokes as table rows."""
    dies = {f"V {g} deg": histories(f"die_angle_{preset}", "die_angle") for g in ANGLES}
    dies = {d: {rt: c for (g, rt), c in h.items() if g == d.split()[1]} for d, h in dies.items()}
    dies["flat-bottomed"] = {rt: c for (_, rt), c in histories(f"die_flat_{preset}", None).items()}
    fig, axes = plt.subplots(1, len(dies), figsize=(14, 3.8), sharey=True)
    rows = []
    for ax, (die, curves) in zip(axes, dies.items()):
        for rt in sorted(curves):
            ax.plot(curves[rt][0], curves[rt][1], label=f"R/t {rt:g}")
        ax.axhline(figmaps.NO_COLLAPSE, color="k", lw=0.8, ls=":")
        ax.set(xlabel="stroke U (mm)", title=die)
        ax.grid(alpha=0.3)
        cells = []
        for r in RTS:
            u = onset(curves[float(r)]) if float(r) in curves else None
            cells.append("-" if float(r) not in curves else "none" if u is None else f"{u:.2f} mm")
        rows.append(f"| {die} | collapse from | " + " | ".join(cells) + " |")
    axes[0].set_ylabel("collapse ratio C/t")
    axes[0].set_yscale("symlog", linthresh=0.1)
    axes[0].set_ylim(0, None)
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    print("figure:", figlib.save(fig, os.path.join(tfruns.root, "docs", "figures"), "die_collapse_map"))
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--preset", default="fast")
    ap.add_argument("-j", "--jobs", type=int, default=os.cpu_count() or 1)
    a = ap.parse_args()
    rt = "rt=" + ",".join(RTS)
    v42 = sweep(f"die_angle_{a.preset}", ["die_angle=" + ",".join(ANGLES), rt], "", a.preset, a.jobs)
    flat = sweep(f"die_flat_{a.preset}", [rt], f"-die_profile {FLAT}", a.preset, a.jobs)
    rule = sweep(f"die_angle_rule_{a.preset}", ["die_angle=" + ",".join(ANGLES), rt], "", a.preset, a.jobs,
                 ["--corner-over-t", str(figmaps.CORNER_OVER_T)])
    curves42 = {f"V {g} deg": ct(v42, "die_angle", g) for g in ANGLES}
    curves42["flat-bottomed"] = ct(flat, None, None)
    curves_rule = {f"V {g} deg": ct(rule, "die_angle", g) for g in ANGLES}
    lines = [f"C/t at the end of loading, aluminum Ro 17.5 mm, mu 0.05, {a.preset} preset (studies/die_study.py)", "",
             "| die | stroke | " + " | ".join(f"R/t {r}" for r in RTS) + " |",
             "|---|---|" + "---|" * len(RTS)]
    for curves, stroke in ((curves42, "4.2 mm"), (curves_rule, f"rule ({figmaps.CORNER_OVER_T} t)")):
        for die, c in curves.items():
            cells = [f"{c[float(r)]:.2f}" if float(r) in c else "-" for r in RTS]
            lines.append(f"| {die} | {stroke} | " + " | ".join(cells) + " |")
    lines += collapse_map(a.preset)
    text = "\n".join(lines)
    print(text)
    with open(os.path.join(tfruns.root, "results", "die_study.md"), "w") as f:
        f.write(text + "\n")
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
    for ax, curves, title in ((axes[0], curves42, "pressed 4.2 mm (the paper's Fig. 4)"),
                              (axes[1], curves_rule, f"pressed to corner radius {figmaps.CORNER_OVER_T} t (Figs. 10, 12)")):
        for die, c in curves.items():
            xs = sorted(c)
            ax.plot(xs, [c[x] for x in xs], "o-", label=die)
        ax.axhline(figmaps.NO_COLLAPSE, color="k", lw=0.8, ls=":")
        ax.axvspan(22.75, 55, color="g", alpha=0.08, label="the paper: no collapse here")
        figlib.rt_axis(ax)
        ax.set(xlabel="R/t (Ro 17.5 mm)", title=title)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("collapse ratio C/t at the end of loading")
    axes[0].set_yscale("symlog", linthresh=0.1)
    axes[0].set_ylim(0, None)
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    print("figure:", figlib.save(fig, os.path.join(tfruns.root, "docs", "figures"), "die_collapse"))


if __name__ == "__main__":
    main()
