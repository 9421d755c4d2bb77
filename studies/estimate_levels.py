#!/usr/bin/python3
"""How a squaring run's error splits into the mesh's and the steps', tube by tube: the study behind the error
estimate's design (docs/accuracy.md, "The error estimate").

Each tube of tools/validate's set (and the paper's nine, and the hold-out tubes of
python/tubeform_py/validation.py, HOLDOUT) is run at resolutions (nt cells through the wall,
D cells around per bending length sqrt(Ro t), step level s: -increments 100 s, -rmin_deps 0.002 / s,
-rmin_domega 0.01 / s) with one element for all (the preset run's) and one friction regularization (VCRI a length
of the tube, 8.3e-4 sqrt(Ro t): 2 % of the default preset's node spacing), so that only what a level names
changes. Runs are cached under results/levels/<tube>/ (delete a file to run it again; --cache DIR or $TF_LEVELS
reads another checkout's cache: eval, show and shipped start no run).

    /usr/bin/python3 studies/estimate_levels.py run  --tubes al_11.7_mu0.05,... [--plan grid|estimate|reference] [-j 2]
    /usr/bin/python3 studies/estimate_levels.py show --tubes ...            # values at the reported strokes
    /usr/bin/python3 studies/estimate_levels.py eval --tubes ... [--misses] # candidates' effectivity and alarms
    /usr/bin/python3 studies/estimate_levels.py shipped --tubes ...         # the runs' own estimate (plan preset)
    /usr/bin/python3 studies/estimate_levels.py demand --tubes ... [--target 0.005] [--target-levels N]
                                                                            # accuracy on demand

--update radial runs the level runs and the references with the radial return (cached apart, `_radial`; its
reference's step ladder is s 1, 2, the return being converged in the step there); --presets-update radial (or
tangent, auto) adds that -plastic_update to the preset runs and to `demand`'s (cached apart,
`preset_<preset>_<update>`).

Plans: `directions` runs each preset level's directional companions at s 1 (half the cells through the wall, twice
them where half would be under 2; half the cells around), `orders` the third level of each direction (twice the
run's, or four times through the wall from 2 cells) for an observed order; `preset` runs the tube with
options/preset-fast.opts and preset-default.opts as a user would, its estimate on (what `shipped` judges); `estimate`
runs what the estimate's candidates read (the preset levels (2, 12, 1) and (4, 24, 1) with their step and mesh
companions); `reference` the tube's converged answer (the step ladder s 1, 2, 4 on the mesh (2 nt, 48) and the mesh
(3 nt, 68) at s 1, nt the default preset's); `grid` nt x D at s 1.

`eval` judges CANDIDATES on the preset levels (run; S its steps' companion; M the mesh companion, half the cells
through the wall (at least 2) and around; MS both; MM half M's): (a) signed parts, (b) Richardson per part, (c) the
contact ripple out (FIT_PERIODS) or its worst phase, (d) GCI, steps on the run's mesh, (e) the mesh's part split
into through the wall and around, each at order 1 or its observed order; fitted factors, one tube out; and each
direction's part per tube and stroke. The candidates are in studies/estimate_candidates.py.
"""
import argparse
import concurrent.futures
import json
import math
import os
import pathlib
import re
import sys

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# The helper package python/tubeform_py (python/README.md).
sys.path.insert(0, os.path.join(ROOT, "python"))
from tubeform_py import tfruns, validation  # noqa: E402
from estimate_candidates import A, CANDIDATES, FITTED, at, at_cells, directional, parts  # noqa: E402

# The runs' cache: --cache DIR, else $TF_LEVELS, else results/levels of this checkout (read-only use of another
# checkout's cache: point --cache at its results/levels; eval, show and shipped start no run when the files exist).
OUT = os.environ.get("TF_LEVELS", os.path.join(ROOT, "results", "levels"))
PAPER = {f"paper_{tube}_mu{mu}": f"options/squaring_{tube}_mu{mu}.opts" for tube in ("al_11.67", "al_37", "cu_29")
         for mu in ("0.05", "0.20", "0.35")}
# The friction regularization as a length of the tube: 2 % of the default preset's node spacing sqrt(Ro t) / 24.
VCRI_OF_BENDING_LENGTH = 0.02 / 24


def tube(name):
    """(options of the tube's scene, Ro, t, final stroke)."""
    if name in PAPER:
        opts = ["-options_file", PAPER[name], "-progress", 0, "-output_every", 100000, "-output_stroke", 0]
        text = (open(os.path.join(ROOT, "options", "squaring.opts")).read() +
                open(os.path.join(ROOT, PAPER[name])).read())
        ro, t = float(tfruns.option(text, "-tube_ro")), float(tfruns.option(text, "-tube_t"))
        return [str(o) for o in opts], ro, t, float(tfruns.option(text, "-stroke", 4.2))
    _, ro, t, _, stroke = validation.spec(name)
    return validation.case_options(name), ro, t, stroke


# The plastic update of the level runs and references (--update): the tangent update (the option's default and the
# presets') or the radial return, whose runs are cached under their own names.
UPDATE = "tangent"
# The preset runs' plastic update (--presets-update): "" the preset file's own, else added after it (cached apart).
PRESET_UPDATE = ""


def ladder():
    """The reference's step levels s: the tangent update's first-order ladder, or the return's (converged in the
    step at s 1: its s 2 measures that)."""
    return (1, 2) if UPDATE == "radial" else (1, 2, 4)


def preset_tag(preset):
    return f"preset_{preset}" + (f"_{PRESET_UPDATE}" if PRESET_UPDATE else "")


def label(nt, d, s, element):
    return f"n{nt}_d{d:g}_s{s:g}_{element}" + ("_radial" if UPDATE == "radial" else "")


def run(name, nt, d, s, element):
    """One run (cached): its meta (wall, increments, factorizations, status) and file."""
    _, ro, t, _ = tube(name)
    extra = ["-mesh_nt", nt, "-mesh_ntheta", 0, "-mesh_density", d, "-element", element, "-increments",
             round(100 * s), "-rmin_deps", 0.002 / s, "-rmin_domega", 0.01 / s, "-rmin_yield", "inside",
             "-friction_vcri", VCRI_OF_BENDING_LENGTH * math.sqrt(ro * t), "-unload_increments", 10,
             "-error_estimate", 0, "-rmin_deps_yield", 2 / s, "-plastic_update", UPDATE]
    return cached_run(name, label(nt, d, s, element), [str(o) for o in extra], lambda line: False)


def values(h5, strokes, w=0.0):
    """Load and C/t at the strokes (fitted over +- w mm, `at`), C/t after springback; and the loading curve."""
    with h5py.File(h5, "r") as h:
        H = h["/history"]
        load = H["stage"][:] == 0
        U, P, C = H["stroke"][:][load], H["load"][:][load], H["c_over_t"][:][load]
        spring = float(H["c_over_t"][-1])
    return [at(U, P, u, w) for u in strokes], [at(U, C, u, w) for u in strokes], spring, (U, P, C)


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
    extra = ["-plastic_update", PRESET_UPDATE] if PRESET_UPDATE else []
    return cached_run(name, preset_tag(preset), ["-options_file", f"options/preset-{preset}.opts"] + extra,
                      lambda line: "companion runs" in line)


# A preset level (nt, D)'s directional companions: through (half the cells through the wall; twice where half would
# be under 2: the run is then the coarse end) and around (half the cells around); ORDERS the third level of each.
DIRECTIONS = lambda nt, d: [(nt // 2 if nt >= 4 else 2 * nt, d), (nt, d / 2)]  # noqa: E731
ORDERS = lambda nt, d: [(2 * nt if nt >= 4 else 4 * nt, d), (nt, 2 * d)]  # noqa: E731


# A preset level (nt, D)'s companion at three quarters of its cells through the wall (at least 2) and around.
QUARTER = lambda nt, d: (max(2, round(0.75 * nt)), 0.75 * d)  # noqa: E731


def plan(name, which):
    """The runs (nt, D, s, element) of a plan for a tube."""
    fast_nt, default_nt = preset_nt(name, 0.044, 2), preset_nt(name, 0.022, 4)
    element = "qm6bar" if default_nt >= 5 else "qm6"
    if which == "grid":
        return [(n, d, 1, element) for n in (2, 4, 8) for d in (12, 24, 48)]
    if which == "estimate":
        return [(n, d, s, "qm6bar" if nt >= 5 else "qm6") for nt, e in ((fast_nt, 12), (default_nt, 24))
                for n, d, s in ((nt, e, 1), (nt, e, 0.5), (max(2, nt // 2), e / 2, 1), (max(2, nt // 2), e / 2, 0.5))]
    if which in ("directions", "orders"):  # each preset level's ladders through the wall and around (s 1)
        runs = [(n, d, 1, "qm6bar" if nt >= 5 else "qm6") for nt, e in ((fast_nt, 12), (default_nt, 24))
                for n, d in (DIRECTIONS if which == "directions" else ORDERS)(nt, e)]
        return list(dict.fromkeys(runs))
    if which == "quarter":  # the preset levels' companions at three quarters of the cells (s 1 and 0.5)
        return [(n, d, s, "qm6bar" if nt >= 5 else "qm6") for nt, e in ((fast_nt, 12), (default_nt, 24))
                for n, d in [QUARTER(nt, e)] for s in (1, 0.5)]
    if which == "preset":
        return [("preset", p) for p in PRESETS]
    if which == "reference":
        nt = max(4, default_nt)
        return [(2 * nt, 48, s, element) for s in ladder()] + [(3 * nt, 68, 1, element)]
    raise SystemExit(f"estimate_levels.py: unknown plan {which} (grid, estimate, reference, directions, orders)")


def strokes(name):
    final = tube(name)[3]
    return [u for u in tfruns.LOAD_AT if u < final - 1e-9] + [final]


def done(path):
    """Whether the cached run `path` (no extension) exists and finished."""
    return os.path.exists(path + ".json") and json.loads(pathlib.Path(path + ".json").read_text())["status"] == "done"


def reference(name):
    """The tube's converged answer: the step ladder on the mesh (2 nt, 48) extrapolated as a first-order method's
    limit (2 f(4) - f(2); with the radial return, converged in the step at s 1, 2 f(2) - f(1)), with the mesh's
    remaining error from (3 nt, 68) at s 1 against (2 nt, 48) at s 1; its uncertainty the larger of the two
    corrections (per value; the step's: |f(4) - f(2)|, or |f(2) - f(1)|). None until its runs exist."""
    nt = max(4, preset_nt(name, 0.022, 4))
    element = "qm6bar" if preset_nt(name, 0.022, 4) >= 5 else "qm6"
    got = []
    for n, d, s in [(2 * nt, 48, s) for s in ladder()] + [(3 * nt, 68, 1)]:
        path = os.path.join(OUT, name, label(n, d, s, element))
        if not done(path):
            return None
        P, C, S, _ = values(path + ".h5", strokes(name))
        got.append(np.array(P + C + [S]))
    f1, fine = got[0], got[-1]
    fa, fb = got[-3], got[-2]        # the ladder's last two: s (2, 4), or (1, 2) with the radial return
    step = 2 * fb - fa - f1          # the step's correction at s 1 on the mesh (2 nt, 48)
    mesh = fine - f1                 # the mesh's correction from 48 to 68 around (and 3/2 through the wall)
    return {"value": f1 + step + mesh, "unc": np.maximum(np.abs(fb - fa), np.abs(mesh))}


# The levels of a preset's run the candidates read: divisors of its cells through the wall and around, step level.
LEVELS = {"run": (1, 1, 1), "S": (1, 1, 0.5), "M": (2, 2, 1), "MS": (2, 2, 0.5), "MM": (4, 4, 1)}
# Its directional levels (s 1, plans directions and orders): factors of its cells through the wall and around.
DIRECTIONAL = {"T-": (0.5, 1), "T+": (2, 1), "T++": (4, 1), "A-": (1, 0.5), "A+": (1, 2)}


def record(name, preset):
    """A preset's level run (nt, D, s 1) and its companions, from the cache: per level its C/t after springback and
    loading curve (None where not cached), the element, the cells through the wall, and the contact ripple's period:
    the mesh companion's loading stroke over the times a node of it comes into contact. None without run, M, MS."""
    nt, d = (preset_nt(name, 0.044, 2), 12) if preset == "fast" else (preset_nt(name, 0.022, 4), 24)
    r = {"strokes": strokes(name), "element": "qm6bar" if nt >= 5 else "qm6", "nt": nt, "curves": {}}
    for key, (a, b, s) in LEVELS.items():
        n = nt if a == 1 else max(2, nt // 2) if a == 2 else max(2, nt // 4)
        path = os.path.join(OUT, name, label(n, d / b, s, r["element"]))
        r["curves"][key] = values(path + ".h5", [])[2:] if done(path) else None
        if key == "M" and done(path):
            with h5py.File(path + ".h5", "r") as h:
                gains = np.count_nonzero(np.diff(h["/history/n_contact"][:][h["/history/stage"][:] == 0]) > 0)
            r["period"] = r["curves"]["M"][1][0][-1] / max(1, gains)
    nq, dq = QUARTER(nt, d)
    for key, s in (("Q", 1), ("QS", 0.5)):
        path = os.path.join(OUT, name, label(nq, dq, s, r["element"]))
        r["curves"][key] = values(path + ".h5", [])[2:] if done(path) else None
    r["ratio_t"], r["ratio_a"] = nt / nq, d / dq
    for key, (a, b) in DIRECTIONAL.items():
        path = os.path.join(OUT, name, label(int(nt * a), d * b, 1, r["element"]))
        r["curves"][key] = values(path + ".h5", [])[2:] if nt * a >= 2 and done(path) else None
    return r if all(r["curves"][k] is not None for k in ("run", "M", "MS")) else None


def judge(t, preset, strokes, ref, value, est, c=None):
    """A run's cells (tube, preset, quantity, stroke, error, reference's uncertainty, estimate: the load relative, C/t
    from U = 2 mm on and sprung) and alarm row (tube, preset, largest errors and estimates of load and C/t); `est`
    in the values' units times c, or (c None) relative for the load."""
    n = len(strokes)
    scale = np.array([abs(v) for v in ref["value"][:n]] + [1.0] * (n + 1))
    err, unc, est = (value - ref["value"]) / scale, ref["unc"] / scale, est if c is None else c * est / scale
    ks = [k for k in range(2 * n + 1) if k < n or k == 2 * n or strokes[k - n] >= 2 - 1e-9]
    cells = [(t, preset, "load" if k < n else "C/t", (strokes + strokes + ["sprung"])[k], err[k], unc[k], est[k])
             for k in ks]
    lo, hi = [k for k in ks if k < n], [k for k in ks if k >= n]
    return cells, (t, preset, max(A(err[lo])), max(A(err[hi])), max(est[lo]), max(est[hi]))


def cells_of(tubes, f, c=1.0):
    """Candidate f (times c) on the preset levels of the tubes: their cells and alarm rows (`judge`)."""
    cells, runs = [], []
    for t in tubes:
        ref = reference(t)
        for preset, r in ((p, record(t, p)) for p in (PRESETS if ref is not None else ())):
            est = None if r is None else f(r)
            if est is not None:
                got = judge(t, preset, r["strokes"], ref, at_cells(r, "run"), est, c)
                cells, runs = cells + got[0], runs + [got[1]]
    return cells, runs


# Whether a load error (relative) or a C/t error passes the preset's target.
warns = lambda p, load, ct: load > PRESETS[p][0] or ct > PRESETS[p][1]  # noqa: E731


def scores(cells, runs=()):
    """Bounded share, median effectivity, share within 3 x (bounded and at most 3 x), that share on the cells whose
    error the reference resolves (at least twice its uncertainty); false and missed alarms."""
    e, u, s = (A(np.array([x[k] for x in cells])) for k in (4, 5, 6))
    bounded, eff = s >= e - u, s / np.maximum(e, 1e-12)
    false = [f"{t} {p}" for t, p, ep, ec, sp, sc in runs if warns(p, sp, sc) and not warns(p, 2 * ep, 2 * ec)]
    missed = [f"{t} {p}" for t, p, ep, ec, sp, sc in runs if not warns(p, sp, sc) and warns(p, ep, ec)]
    sharp = bounded & (eff <= 3)
    return bounded.mean(), np.median(eff), sharp.mean(), sharp[e >= 2 * u].mean(), false, missed


HEAD = ("| estimate | cells | bounded | median eff. | within 3x | within 3x, resolved | load: bounded, median, 3x "
        "| C/t | false alarms | missed alarms |\n" + "|---" * 10 + "|")


def table(name, cells, runs, misses):
    """One row of the candidates' table (and its unbounded cells under it); none without cells."""
    if not cells:
        return
    b, m, w, wr, false, missed = scores(cells, runs)
    q = [scores([x for x in cells if x[2] == what])[:3] for what in ("load", "C/t")]
    print(f"| {name.replace('|', '&#124;')} | {len(cells)} | {b:.1%} | {m:.2f} | {w:.1%} | {wr:.1%} | " +
          " | ".join(f"{x[0]:.0%} {x[1]:.1f} {x[2]:.0%}" for x in q) +
          f" | {len(false)} {' '.join(false)} | {len(missed)} {' '.join(missed)} |")
    for x in [x for x in cells if x[6] < A(x[4]) - x[5]] if misses else []:
        print(f"| miss: {x[0]} {x[1]} {x[2]} at {x[3]} | error {x[4]:+.4f} unc {x[5]:.4f} estimate {x[6]:.4f} |")


def evaluate(tubes, misses=False):
    """Each candidate on the preset levels' cells (plan estimate) against the reference: a cell is bounded when the
    estimate reaches the error less the reference's uncertainty; a run warns when an estimate passes its preset's
    target (PRESETS), falsely where its errors are within half of them, and misses where an error passes it."""
    print(HEAD.replace("estimate", "candidate"))
    for name, f in CANDIDATES.items():
        table(name, *cells_of(tubes, f), misses)
    print("\n| base x c | c | bounded | median eff. | within 3x | error / base at 20, 50, 95 % | leave one tube out: "
          "c | bounded | median eff. | within 3x |\n|---|---|---|---|---|---|---|---|---|---|")
    for name in FITTED:
        base = cells_of(tubes, CANDIDATES[name])[0]
        if not base:  # a candidate of the directional runs, not cached: nothing to fit
            print(f"| {name.replace('|', '&#124;')} | (its runs are not cached: --plan directions) |")
            continue
        c, q = fitted(base), np.percentile([A(x[4]) / max(x[6], 1e-15) for x in base], [20, 50, 95])
        cs = [fitted(cells_of([o for o in tubes if o != t], CANDIDATES[name])[0]) for t in tubes]
        held = sum((cells_of([t], CANDIDATES[name], k)[0] for t, k in zip(tubes, cs)), [])
        all_, out = scores(cells_of(tubes, CANDIDATES[name], c)[0]), scores(held)
        print(f"| {name.replace('|', '&#124;')} | {c:.2f} | {all_[0]:.1%} | {all_[1]:.2f} | {all_[2]:.1%} | "
              f"{q[0]:.2f} {q[1]:.2f} {q[2]:.2f} | {min(cs):.2f}-{max(cs):.2f} | {out[0]:.1%} | {out[1]:.2f} | "
              f"{out[2]:.1%} |")
    direction_parts(tubes)


def direction_parts(tubes):
    """Per tube, preset level and quantity: the largest error against the reference and the largest steps' part
    |MS - M|, through-the-wall and around part (p 1; load relative), the direction whose part is the larger at each
    stroke, on how many strokes the two directions' signed errors cancel, and the median observed order through the
    wall and around over the cells where it is believed (those cells / all)."""
    print("\n| tube | preset | quantity | largest error | steps | through | around | larger part per stroke "
          "| opposite signs | p through | p around |\n" + "|---" * 11 + "|")
    for t in tubes:
        ref = reference(t)
        for preset, r in ((p, record(t, p)) for p in (PRESETS if ref is not None else ())):
            d = None if r is None else directional(r, True)
            if d is None:
                continue
            n, p1 = len(r["strokes"]), directional(r)
            scale = np.array([abs(v) for v in ref["value"][:n]] + [1.0] * (n + 1))
            err, steps = A(at_cells(r, "run") - ref["value"]) / scale, A(parts(r)[0]) / scale
            for q, ks in (("load", range(n)), ("C/t", range(n, 2 * n + 1))):
                ks = [k for k in ks if k < n or k == 2 * n or r["strokes"][k - n] >= 2 - 1e-9]
                big = lambda x: f"{x[ks].max():.4f}"  # noqa: E731
                who = " ".join("T" if p1["t"][k] >= p1["a"][k] else "A" for k in ks)
                sure = [[k for k in ks if d["sure_" + x][k]] for x in "ta"]
                po = [f"{np.median(d['p_' + x][k]):.2f} ({len(k)}/{len(ks)})" if k else f"- (0/{len(ks)})"
                      for x, k in zip("ta", sure)]
                opposite = sum(p1["signed_t"][k] * p1["signed_a"][k] < 0 for k in ks)
                print(f"| {t} | {preset} | {q} | {big(err)} | {big(steps)} | {big(p1['t'] / scale)} | "
                      f"{big(p1['a'] / scale)} | {who} | {opposite}/{len(ks)} | {po[0]} | {po[1]} |")


def fitted(cells):
    """The least factor c for which c x estimate bounds 95 % of the cells (nan without cells)."""
    if not cells:
        return float("nan")
    need = np.sort([max(A(x[4]) - x[5], 0) / max(x[6], 1e-15) for x in cells])
    return float(need[math.ceil(0.95 * len(need)) - 1]) * (1 + 1e-9)


def shipped(tubes, misses=False):
    """The runs' own estimate (plan preset; a run not cached is skipped, not started) against the reference, cell by
    cell and run by run as `evaluate` judges a candidate."""
    cells, runs = [], []
    for t in tubes:
        ref = reference(t)
        for preset in PRESETS:
            h5 = os.path.join(OUT, t, preset_tag(preset) + ".h5")
            if ref is None or not done(h5[:-3]):
                print(f"{t} {preset}: no reference or no preset run cached")
                continue
            P, C, S, _ = values(h5, strokes(t))
            with h5py.File(h5, "r") as h:
                a = dict(h["/history"].attrs)
            us = [f"{u:g}" for u in strokes(t)[:-1]]
            est = ([a[f"error_load_at_{u}"] for u in us] + [a["error_loaded_load"]] + [a[f"error_c_over_t_at_{u}"]
                   for u in us] + [a["error_loaded_c_over_t"], a["error_unloaded_c_over_t"]])
            got = judge(t, preset, strokes(t), ref, np.array(P + C + [S]), np.array(est))
            cells, runs = cells + got[0], runs + [got[1]]
    print("| tube | preset | load: largest error | estimate | C/t: largest error | estimate | |\n" + "|---" * 7 + "|")
    for t, p, ep, ec, sp, sc in runs:
        print(f"| {t} | {p} | {100 * ep:.2f} % | {100 * sp:.2f} % | {ec:.4f} | {sc:.4f} | "
              f"{'warns' if warns(p, sp, sc) else ''} |")
    print("\n" + HEAD)
    table("shipped (the preset runs' own)", cells, runs, misses)


def demand(tubes, target, levels=0):
    """Accuracy on demand: the tube with the default preset and -target_load `target` (cached as
    demand_<target>.h5; with `levels`, -target_levels so many, demand_<target>_L<levels>.h5): its levels, wall time,
    and its largest true load error against the reference."""
    print("| tube | -target_load | levels | wall (s) | final mesh | largest load error | its estimate | C/t error |")
    print("|---|---|---|---|---|---|---|---|")
    for t in tubes:
        ref = reference(t)
        update = ["-plastic_update", PRESET_UPDATE] if PRESET_UPDATE else []
        bound = ["-target_levels", str(levels)] if levels else []
        m, h5 = cached_run(t, f"demand_{target:g}" + (f"_{PRESET_UPDATE}" if PRESET_UPDATE else "") +
                           (f"_L{levels}" if levels else ""),
                           ["-options_file", "options/preset-default.opts", "-target_load", str(target)] + update +
                           bound,
                           lambda l: "level" in l or "estimated error" in l or "mesh " in l[:16])
        if m["status"] != "done" or ref is None:
            print(f"| {t} | {target:g} | {m['status']} | | | | | |")
            continue
        n = len(strokes(t))
        P, C, S, _ = values(h5, strokes(t))
        with h5py.File(h5, "r") as h:
            a = dict(h["/history"].attrs)
        err = (np.array(P + C + [S]) - ref["value"])
        ep = np.abs(err[:n] / ref["value"][:n]).max()
        # (the mesh line: "tubeform: mesh N cells (-mesh_nt a through the wall x -mesh_ntheta b around), ...")
        meshes = [re.findall(r"-mesh_nt (\d+) .* -mesh_ntheta (\d+)", l) for l in m["lines"]
                  if l.startswith("tubeform: mesh ")]
        mesh = " x ".join(meshes[-1][0]) if meshes and meshes[-1] else "?"
        print(f"| {t} | {target:g} | {int(a['accuracy_level'])} | {m['wall']:.0f} | {mesh} | {100 * ep:.2f} % | "
              f"{100 * a['error_load']:.2f} % | {np.abs(err[n:]).max():.4f} |")


def main():
    global OUT, UPDATE, PRESET_UPDATE
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("what", choices=("run", "show", "eval", "shipped", "demand"))
    ap.add_argument("--target", type=float, default=0.005, help="demand: the -target_load")
    ap.add_argument("--target-levels", type=int, default=0, help="demand: the -target_levels (0: the default)")
    ap.add_argument("--tubes", required=True)
    ap.add_argument("--plan", default="estimate,reference")
    ap.add_argument("-j", type=int, default=1)
    ap.add_argument("--misses", action="store_true", help="eval, shipped: list the unbounded cells")
    ap.add_argument("--update", choices=("tangent", "radial"), default="tangent",
                    help="the level runs' and references' plastic update")
    ap.add_argument("--presets-update", choices=("", "tangent", "radial", "auto"), default="",
                    help="the preset runs' plastic update (default: the preset file's own)")
    ap.add_argument("--cache", default=OUT, help="the folder of the cached runs (default $TF_LEVELS or results/levels)")
    a = ap.parse_args()
    OUT, UPDATE, PRESET_UPDATE = a.cache, a.update, a.presets_update
    tubes = a.tubes.split(",")
    unknown = [t for t in tubes if t not in PAPER and t not in validation.CASES and t not in validation.HOLDOUT]
    if unknown:
        ap.error(f"--tubes: {', '.join(unknown)} is not a tube of python/tubeform_py/validation.py (CASES, HOLDOUT) "
                 f"or of the paper's ({', '.join(PAPER)})")
    if a.what in ("eval", "shipped"):
        return (evaluate if a.what == "eval" else shipped)(tubes, a.misses)
    if a.what == "demand":
        return demand(tubes, a.target, a.target_levels)
    jobs = [(t, *r) for t in tubes for p in a.plan.split(",") for r in plan(t, p)]
    if a.what == "run":
        one = lambda j: run_preset(j[0], j[2]) if j[1] == "preset" else run(*j)  # noqa: E731
        with concurrent.futures.ThreadPoolExecutor(a.j) as ex:
            for (t, *r), (m, _) in zip(jobs, ex.map(one, jobs)):
                tag = preset_tag(r[1]) if r[0] == "preset" else label(*r)
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
