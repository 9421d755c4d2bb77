#!/usr/bin/python3
"""How a squaring run's error splits into the mesh's and the steps', tube by tube: the study behind the error
estimate's design (docs/accuracy.md, "The error estimate").

Each tube of scripts/validate's set (and the paper's nine) is run at resolutions (nt cells through the wall,
D cells around per bending length sqrt(Ro t), step level s: -increments 100 s, -rmin_deps 0.002 / s,
-rmin_domega 0.01 / s) with one element for all (the preset run's) and one friction regularization (VCRI a length
of the tube, 8.3e-4 sqrt(Ro t): 2 % of the default preset's node spacing), so that only what a level names
changes. Runs are cached under results/levels/<tube>/ (delete a file to run it again).

    /usr/bin/python3 studies/estimate_levels.py run  --tubes al_11.7_mu0.05,... [--plan grid|estimate|reference] [-j 2]
    /usr/bin/python3 studies/estimate_levels.py show --tubes ...            # values at the reported strokes
    /usr/bin/python3 studies/estimate_levels.py eval --tubes ...            # candidates' effectivity
    /usr/bin/python3 studies/estimate_levels.py shipped --tubes ...         # the runs' own estimate (plan preset)
    /usr/bin/python3 studies/estimate_levels.py demand --tubes ... [--target 0.005]   # accuracy on demand

Plans: `preset` runs the tube with options/preset-fast.opts and preset-default.opts as a user would, its estimate
on (what `shipped` judges); `estimate` runs what the estimate's candidates read (the preset levels (2, 12, 1) and (4, 24, 1) with
their step and mesh companions); `reference` the tube's converged answer (the step ladder s 1, 2, 4 on the mesh
(2 nt, 48) and the mesh (3 nt, 68) at s 1, nt the default preset's); `grid` nt x D at s 1.
"""
import argparse
import concurrent.futures
import importlib.machinery
import importlib.util
import json
import math
import os
import sys

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import tfruns  # noqa: E402

_loader = importlib.machinery.SourceFileLoader("validate", os.path.join(ROOT, "scripts", "validate"))
_spec = importlib.util.spec_from_loader("validate", _loader)
validate = importlib.util.module_from_spec(_spec)
_loader.exec_module(validate)

OUT = os.path.join(ROOT, "results", "levels")
PAPER = {f"paper_{tube}_mu{mu}": f"options/squaring_{tube}_mu{mu}.opts" for tube in ("al_11.67", "al_37", "cu_29")
         for mu in ("0.05", "0.20", "0.35")}
# The friction regularization as a length of the tube: 2 % of the default preset's node spacing sqrt(Ro t) / 24.
VCRI_OF_BENDING_LENGTH = 0.02 / 24


def tube(name):
    """(options of the tube's scene, Ro, t, final stroke)."""
    if name in PAPER:
        opts = ["-options_file", PAPER[name], "-progress", 0, "-output_every", 100000, "-output_stroke", 0]
        text = open(os.path.join(ROOT, "options", "squaring.opts")).read() + open(os.path.join(ROOT, PAPER[name])).read()
        ro, t = float(tfruns.option(text, "-tube_ro")), float(tfruns.option(text, "-tube_t"))
        return [str(o) for o in opts], ro, t, float(tfruns.option(text, "-stroke", 4.2))
    _, ro, t, _, stroke = validate.CASES[name]
    return validate.case_options(name), ro, t, stroke


def label(nt, d, s, element):
    return f"n{nt}_d{d:g}_s{s:g}_{element}"


def run(name, nt, d, s, element):
    """One run (cached): its meta (wall, increments, factorizations, status) and file."""
    _, ro, t, _ = tube(name)
    extra = ["-mesh_nt", nt, "-mesh_ntheta", 0, "-mesh_density", d, "-element", element, "-increments",
             round(100 * s), "-rmin_deps", 0.002 / s, "-rmin_domega", 0.01 / s, "-rmin_yield", "inside",
             "-friction_vcri", VCRI_OF_BENDING_LENGTH * math.sqrt(ro * t), "-unload_increments", 10,
             "-error_estimate", 0, "-rmin_deps_yield", 2 / s]
    return cached_run(name, label(nt, d, s, element), [str(o) for o in extra], lambda line: False)


# SMOOTH > 0: values read off a local quadratic fit over +-SMOOTH mm of stroke (one-sided at the end), the contact
# ripple taken out; the run's own departure from its fit is then added to each candidate (it is the run's error).
SMOOTH = float(os.environ.get("SMOOTH", "0"))


def at(U, F, u):
    if SMOOTH <= 0:
        return float(np.interp(u, U, F))
    m = (U >= u - SMOOTH) & (U <= u + SMOOTH)
    if u + SMOOTH > U[-1] + 1e-9:
        m = U >= U[-1] - 2 * SMOOTH
    c = np.polyfit(U[m] - u, F[m], 2)
    return float(c[-1])


def values(h5, strokes, raw=False):
    """Load and C/t at the strokes, C/t after springback; and the loading curve."""
    global SMOOTH
    keep = SMOOTH
    if raw:
        SMOOTH = 0
    with h5py.File(h5, "r") as h:
        H = h["/history"]
        load = H["stage"][:] == 0
        U, P, C = H["stroke"][:][load], H["load"][:][load], H["c_over_t"][:][load]
        spring = float(H["c_over_t"][-1])
    out = [at(U, P, u) for u in strokes], [at(U, C, u) for u in strokes], spring, (U, P, C)
    SMOOTH = keep
    return out


def preset_nt(name, strain, least):
    _, ro, t, _ = tube(name)
    return max(least, math.ceil(t / (ro * strain) - 1e-9))


PRESETS = {"fast": (0.05, 0.05), "default": (0.015, 0.03)}  # their targets (load relative, C/t), as the files set


def cached_run(name, tag, extra, keep):
    """The tube's run with `extra` options after its own, cached as <tag>.h5 beside a .json of its wall time,
    counts, status and the lines of its output that `keep` picks: (meta, file)."""
    folder = os.path.join(OUT, name)
    os.makedirs(folder, exist_ok=True)
    h5 = os.path.join(folder, tag + ".h5")
    meta = h5[:-3] + ".json"
    if not os.path.exists(meta):
        opts, _, _, _ = tube(name)
        try:
            wall, incs, facts, out = tfruns.run(opts[1], opts[2:] + extra, h5)
            status, lines = "done", [line for line in out.splitlines() if keep(line)]
        except tfruns.RunFailed as e:
            wall, incs, facts, status, lines = float("nan"), 0, 0, "failed: " + str(e).splitlines()[-1][:300], []
        with open(meta, "w") as f:
            json.dump({"wall": wall, "increments": incs, "factorizations": facts, "status": status, "lines": lines}, f)
    with open(meta) as f:
        return json.load(f), h5


def run_preset(name, preset):
    """The tube's run with a preset, its error estimate on (cached): its meta and file."""
    return cached_run(name, f"preset_{preset}", ["-options_file", f"options/preset-{preset}.opts"],
                      lambda line: "companion runs" in line)


def plan(name, which):
    """The runs (nt, D, s, element) of a plan for a tube."""
    fast_nt, default_nt = preset_nt(name, 0.044, 2), preset_nt(name, 0.022, 4)
    element = "qm6bar" if default_nt >= 5 else "qm6"
    if which == "grid":
        return [(n, d, 1, element) for n in (2, 4, 8) for d in (12, 24, 48)]
    if which == "estimate":
        runs = []
        for nt, d in ((fast_nt, 12), (default_nt, 24)):
            el = "qm6bar" if nt >= 5 else "qm6"
            runs += [(nt, d, 1, el), (nt, d, 0.5, el), (max(2, nt // 2), d / 2, 1, el), (max(2, nt // 2), d / 2, 0.5, el)]
        return runs
    if which == "preset":
        return [("preset", p) for p in PRESETS]
    if which == "reference":
        nt = max(4, default_nt)
        return [(2 * nt, 48, 1, element), (2 * nt, 48, 2, element), (2 * nt, 48, 4, element),
                (3 * nt, 68, 1, element)]
    raise SystemExit(f"estimate_levels.py: unknown plan {which} (grid, estimate, reference)")


def strokes(name):
    final = tube(name)[3]
    return [u for u in tfruns.LOAD_AT if u < final - 1e-9] + [final]


def reference(name):
    """The tube's converged answer: the step ladder on the mesh (2 nt, 48) extrapolated as a first-order method's
    limit (2 f(4) - f(2)), with the mesh's remaining error from (3 nt, 68) at s 1 against (2 nt, 48) at s 1; its
    uncertainty the larger of the two corrections (per value). None until its runs exist."""
    nt = max(4, preset_nt(name, 0.022, 4))
    element = "qm6bar" if preset_nt(name, 0.022, 4) >= 5 else "qm6"
    want = [(2 * nt, 48, 1), (2 * nt, 48, 2), (2 * nt, 48, 4), (3 * nt, 68, 1)]
    got = []
    for n, d, s in want:
        path = os.path.join(OUT, name, label(n, d, s, element))
        if not os.path.exists(path + ".json") or json.load(open(path + ".json"))["status"] != "done":
            return None
        P, C, S, _ = values(path + ".h5", strokes(name))
        got.append(np.array(P + C + [S]))
    f1, f2, f4, fine = got
    step = 2 * f4 - f2 - f1          # the step's correction at s 1 on the mesh (2 nt, 48)
    mesh = fine - f1                 # the mesh's correction from 48 to 68 around (and 3/2 through the wall)
    return {"value": f1 + step + mesh, "unc": np.maximum(np.abs(f4 - f2), np.abs(mesh))}


def estimates(name, nt, d, element):
    """The run (nt, d, 1) and its companions' values (None if missing)."""
    runs = {}
    for key, (n, dd, s) in {"run": (nt, d, 1), "S": (nt, d, 0.5), "M": (max(2, nt // 2), d / 2, 1),
                            "MS": (max(2, nt // 2), d / 2, 0.5)}.items():
        path = os.path.join(OUT, name, label(n, dd, s, element))
        if not os.path.exists(path + ".json") or json.load(open(path + ".json"))["status"] != "done":
            return None
        P, C, S, _ = values(path + ".h5", strokes(name))
        runs[key] = np.array(P + C + [S])
        if key == "run":
            P, C, S, _ = values(path + ".h5", strokes(name), raw=True)
            runs["raw"] = np.array(P + C + [S])
    return runs


def _a(x):
    return np.abs(x)


# Candidate estimators from the run and its companions: S (the run's mesh, half the step level), M (half the mesh,
# the run's steps), MS (both halved: the estimate before this study).
CANDIDATES = {
    "old: 3 |MS - run|": lambda r: 3 * _a(r["MS"] - r["run"]),
    "|MS - run|": lambda r: _a(r["MS"] - r["run"]),
    "1.25 |MS - run|": lambda r: 1.25 * _a(r["MS"] - r["run"]),
    "|S - run| + |M - run| / 3": lambda r: _a(r["S"] - r["run"]) + _a(r["M"] - r["run"]) / 3,
    "|S - run| + |M - run|": lambda r: _a(r["S"] - r["run"]) + _a(r["M"] - r["run"]),
    "1.25 |S - run + (M - run) / 3|": lambda r: 1.25 * _a(r["S"] - r["run"] + (r["M"] - r["run"]) / 3),
    "|MS - M| + |M - run| / 3": lambda r: _a(r["MS"] - r["M"]) + _a(r["M"] - r["run"]) / 3,
    "|MS - M| + |M - run|": lambda r: _a(r["MS"] - r["M"]) + _a(r["M"] - r["run"]),
}


def evaluate(tubes):
    """Each candidate's effectivity (estimate / true error) over the cells: load (relative) and C/t at the reported
    strokes, C/t after springback; a cell is bounded when the estimate reaches the error less the reference's
    uncertainty."""
    cells = {c: [] for c in CANDIDATES}
    for t in tubes:
        ref = reference(t)
        if ref is None:
            print(f"{t}: no reference yet")
            continue
        fast_nt, default_nt = preset_nt(t, 0.044, 2), preset_nt(t, 0.022, 4)
        for preset, nt, d in (("fast", fast_nt, 12), ("default", default_nt, 24)):
            r = estimates(t, nt, d, "qm6bar" if nt >= 5 else "qm6")
            if r is None:
                print(f"{t} {preset}: no runs yet")
                continue
            n = len(strokes(t))
            scale = np.array([abs(v) for v in ref["value"][:n]] + [1.0] * (n + 1))  # load relative, C/t absolute
            err, unc = (r["raw"] - ref["value"]) / scale, ref["unc"] / scale
            ripple = np.abs(r["raw"] - r["run"])
            for c, f in CANDIDATES.items():
                est = (f(r) + ripple) / scale
                for k in range(2 * n + 1):
                    what = "load" if k < n else "C/t"
                    if what == "C/t" and k < 2 * n and strokes(t)[k - n] < 2 - 1e-9:
                        continue  # (C/t below U = 2 mm: the side has not folded in; 0 on most tubes)
                    cells[c].append((t, preset, what, k, err[k], unc[k], est[k]))
    if os.environ.get("CELLS"):
        for x in cells[os.environ["CELLS"]]:
            print(f"  {x[0]:20s} {x[1]:8s} {x[2]:5s} {x[3]} error {x[4]:+.5f} unc {x[5]:.5f} estimate {x[6]:.5f}")
    for c, rows in cells.items():
        if not rows:
            continue
        e = np.array([abs(x[4]) for x in rows]); u = np.array([x[5] for x in rows]); s = np.array([x[6] for x in rows])
        bounded = s >= e - u
        eff = s / np.maximum(e, 1e-12)
        print(f"{c:32s} cells {len(rows):3d}  bounded {bounded.mean():5.1%}  median effectivity {np.median(eff):6.2f}"
              f"  within 3x {np.mean(bounded & (eff <= 3)):5.1%}")
    return cells


def shipped(tubes):
    """The runs' own estimate (plan preset) against the reference, cell by cell (the cells of `evaluate`), and
    run by run: a false alarm warns (its estimate passes the preset's target) where the true error is within half
    the target, a missed alarm does not warn where the true error passes it."""
    cells, alarms, rows = [], {"false": [], "missed": [], "runs": 0}, []
    for t in tubes:
        ref = reference(t)
        if ref is None:
            print(f"{t}: no reference yet")
            continue
        n = len(strokes(t))
        for preset, (tp, tc) in PRESETS.items():
            m, h5 = run_preset(t, preset)
            if m["status"] != "done":
                print(f"{t} {preset}: {m['status']}")
                continue
            P, C, S, _ = values(h5, strokes(t), raw=True)
            with h5py.File(h5, "r") as h:
                a = dict(h["/history"].attrs)
            us = [f"{u:g}" for u in strokes(t)[:-1]]
            est = ([a[f"error_load_at_{u}"] for u in us] + [a["error_loaded_load"]] +
                   [a[f"error_c_over_t_at_{u}"] for u in us] + [a["error_loaded_c_over_t"], a["error_unloaded_c_over_t"]])
            scale = np.array([abs(v) for v in ref["value"][:n]] + [1.0] * (n + 1))
            err, unc = (np.array(P + C + [S]) - ref["value"]) / scale, ref["unc"] / scale
            for k in range(2 * n + 1):
                if n <= k < 2 * n and strokes(t)[k - n] < 2 - 1e-9:
                    continue  # (C/t below U = 2 mm, as in evaluate)
                cells.append((t, preset, "load" if k < n else "C/t", k, err[k], unc[k], est[k]))
            worst_p, worst_c = np.abs(err[:n]).max(), np.abs(err[n:]).max()
            warns = a["error_load"] > tp or a["error_c_over_t"] > tc
            alarms["runs"] += 1
            if warns and worst_p < tp / 2 and worst_c < tc / 2:
                alarms["false"].append(f"{t} {preset}")
            if not warns and (worst_p > tp or worst_c > tc):
                alarms["missed"].append(f"{t} {preset}")
            rows.append(f"| {t} | {preset} | {100 * worst_p:.2f} % | {100 * a['error_load']:.2f} % | {worst_c:.4f} | "
                        f"{a['error_c_over_t']:.4f} | {'warns' if warns else ''} |")
    if not cells:
        return
    if os.environ.get("CELLS"):
        for x in cells:
            print(f"  {x[0]:18s} {x[1]:8s} {x[2]:5s} {x[3]} error {x[4]:+.5f} unc {x[5]:.5f} estimate {x[6]:.5f}"
                  f"  {x[6] / max(abs(x[4]), 1e-12):6.2f}")
    print("| tube | preset | load: largest error | estimate | C/t: largest error | estimate | |")
    print("|---|---|---|---|---|---|---|")
    print("\n".join(rows) + "\n")
    e = np.array([abs(x[4]) for x in cells]); u = np.array([x[5] for x in cells]); s = np.array([x[6] for x in cells])
    bounded, eff = s >= e - u, s / np.maximum(e, 1e-12)
    print(f"shipped: cells {len(cells)}  bounded {bounded.mean():5.1%}  median effectivity {np.median(eff):.2f}  "
          f"within 3x {np.mean(bounded & (eff <= 3)):5.1%};  runs {alarms['runs']}, false alarms "
          f"{len(alarms['false'])} {alarms['false']}, missed alarms {len(alarms['missed'])} {alarms['missed']}")


def demand(tubes, target):
    """Accuracy on demand: the tube with the default preset and -target_load `target` (cached as
    demand_<target>.h5): its levels, wall time, and its largest true load error against the reference."""
    print(f"| tube | -target_load | levels | wall (s) | final mesh | largest load error | its estimate | C/t error |")
    print("|---|---|---|---|---|---|---|---|")
    for t in tubes:
        ref = reference(t)
        m, h5 = cached_run(t, f"demand_{target:g}", ["-options_file", "options/preset-default.opts", "-target_load",
                                                     str(target)],
                           lambda l: "level" in l or "estimated error" in l or "mesh " in l[:16])
        if m["status"] != "done" or ref is None:
            print(f"| {t} | {target:g} | {m['status']} | | | | | |")
            continue
        n = len(strokes(t))
        P, C, S, _ = values(h5, strokes(t), raw=True)
        with h5py.File(h5, "r") as h:
            a = dict(h["/history"].attrs)
        err = (np.array(P + C + [S]) - ref["value"])
        ep = np.abs(err[:n] / ref["value"][:n]).max()
        meshes = [l.split("(")[1].split(")")[0] for l in m["lines"] if l.startswith("tubeform: mesh ")]
        mesh = meshes[-1] if meshes else "?"
        print(f"| {t} | {target:g} | {int(a['accuracy_level'])} | {m['wall']:.0f} | {mesh} | {100 * ep:.2f} % | "
              f"{100 * a['error_load']:.2f} % | {np.abs(err[n:]).max():.4f} |")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("what", choices=("run", "show", "eval", "shipped", "demand"))
    ap.add_argument("--target", type=float, default=0.005, help="demand: the -target_load")
    ap.add_argument("--tubes", required=True)
    ap.add_argument("--plan", default="estimate,reference")
    ap.add_argument("-j", type=int, default=1)
    a = ap.parse_args()
    tubes = a.tubes.split(",")
    if a.what == "eval":
        evaluate(tubes)
        return
    if a.what == "shipped":
        shipped(tubes)
        return
    if a.what == "demand":
        demand(tubes, a.target)
        return
    jobs = [(t, *r) for t in tubes for p in a.plan.split(",") for r in plan(t, p)]
    if a.what == "run":
        one = lambda j: run_preset(j[0], j[2]) if j[1] == "preset" else run(*j)  # noqa: E731
        with concurrent.futures.ThreadPoolExecutor(a.j) as ex:
            for (t, *r), (m, _) in zip(jobs, ex.map(one, jobs)):
                tag = f"preset_{r[1]}" if r[0] == "preset" else label(*r)
                print(f"{t:22s} {tag:24s} {m['status']:8s} {m['wall']:7.1f} s {m['increments']:6d} incr "
                      f"{m['factorizations']:7d} fact", flush=True)
        return
    for t, *r in [j for j in jobs if j[1] != "preset"]:
        m, h5 = run(t, *r) if os.path.exists(os.path.join(OUT, t, label(*r) + ".json")) else ({"status": "-"}, None)
        if m["status"] != "done":
            print(f"{t:22s} {label(*r):24s} {m['status']}")
            continue
        P, C, S, _ = values(h5, strokes(t))
        print(f"{t:22s} {label(*r):24s} P " + " ".join(f"{p:9.3f}" for p in P) + "  C/t " +
              " ".join(f"{c:.4f}" for c in C) + f"  sprung {S:.4f}")


if __name__ == "__main__":
    main()
