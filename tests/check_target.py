"""Accuracy on demand (docs/accuracy.md, "Accuracy on demand"): a run given -target_load goes on at finer levels
until its estimate meets it. The paper's default tube (aluminum 17.5 x 1.5, mu 0.05) from the fast preset, 1 rank:

A. -target_load 0.05: the fast level's estimate passes 5 % (its mesh part), so a second level runs, finer in cells;
   it ends with its estimate within the target (target_met 1, accuracy_level >= 2) and its load within the target
   of CalculiX's converged loads for this tube at U = 1, 2, 3, 4.2 mm (104.93, 124.95, 164.03, 280.11 N/mm: the
   8 x 180 mesh of tools/calculix/converge.py, docs/accuracy.md "Against CalculiX"; its own uncertainty, the
   penalty's, about 0.7 % at the end of the stroke, is added to the tolerance). The first level's copy is removed
   once the second ends. Planted: no finer level ever follows (NextLevel returns none) -> FAILED. Held to the
   demanded load alone: the estimate lines name only its target, target_c_over_t is 0 (planted: the preset's C/t
   expectation kept beside the demand, which no level refines for -> FAILED).
B. -target_levels 1: no second level; the run warns, naming -target_levels, and writes target_met 0.
C. A second level that stops (-rmin_max_increments between the first level's increments and the second's): the
   first level's complete results are kept as <stem>.level1.h5 (its estimate in it, not stopped), the stopped
   level's results so far in -output, exit non-zero. Planted: no copy kept -> FAILED.
D. A level that keeps the last one's increments takes that level as its estimate's mesh companion (driver/refine.hpp,
   kReuseRatio) and its increments' part from a run of that level's cells at twice its increment limits: the radial
   return (converged in the step, so the first level's increments part is small and no increments are refined) with
   -target_load 0.1 and -target_levels 2 on 2 ranks, the companions beside the run. Level 2 says where its mesh part
   comes from, and its estimate at each reported stroke u is D(u) + S(u): D(u) = |P1(u) - P2(u)| / P2(u) / (r - 1)
   (P1 level 1's load, read from a separate run with -target_levels 1; r the ratio of the two levels' cells, from
   their printed meshes) and S(u) = |Q1(u) - P1(u)| / P2(u) (Q1 from a separate run of level 1's options, its element
   and friction regularization named, at twice its increment limits and half its trial increments): exact arithmetic
   on the three histories, 1e-9 for the interpolation's round-off. At the end of loading the estimate is the largest
   over the last trial increment's rows, so that D + S at the end is its lower bound. The 2-rank job's results and
   estimate are the 1-rank job's (the run on half the ranks: the same run), within 1e-9. -target_load 0.1 (level 1
   estimates 11 %) makes level 2 about 1.6 times finer around, not 2, so that the 1 / (r - 1) is seen. Planted: the
   mesh part's 1 / (r - 1) dropped -> FAILED; no reuse (level 2 runs companions of its own) -> FAILED; the
   increments' part read on half of level 1's cells -> FAILED.
   Level 2 differs from level 1 in its cells alone: it keeps level 1's element (qm6, where -element auto would take
   qm6bar at its 4 cells with -element_bar_nt 4) and friction regularization (the attribute friction_vcri, derived
   from level 1's node spacing: the same double). Planted: the element chosen again for level 2's cells -> FAILED;
   level 2's VCRI derived from its own spacing -> FAILED.
F. A level that runs companions of its own (the tangent update named, -target_c_over_t 0.003: its increments are
   refined too, so no reuse), on 2 ranks with the companions beside the run: their ranks start level 2 from level 1's
   own choices as the run does (its element, its friction regularization), so the 2-rank job's level 2 and its
   estimate are the 1-rank job's, within 1e-9 (D's bound). Planted: the companions' side applying the change to the
   options it was given, not to its level's own choices (VCRI derived again from level 2's spacing) -> FAILED.
E. A demanded accuracy chooses the plastic update where -plastic_update names none: the radial return (auto), so
   that A's every level says "radial return" and its level 2 refines the cells alone and takes level 1 as its
   companion (the tangent update's increments part would refine the increments too and run companions); named, it
   is kept (-plastic_update tangent with -target_load: no radial return). Planted: the rule removed -> FAILED; the
   rule overriding a named update -> FAILED.
G. A demanded accuracy is confirmed only by an estimate that reads the wall: the fast level's 2 cells through the wall
   are its mesh companion's too (Answer::wall_covered), so with -target_load 0.2, which its estimate meets, level 2
   follows, saying why, at least kReuseRatio finer (4 cells through), takes level 1 as its companion and meets the
   target (target_met 1, error_covers_wall 1); with -target_levels 1 the run warns that its estimate does not read
   the wall and writes target_met 0. Planted: the wall's coverage left out of NextLevel and Answer::Over -> FAILED.
H. -target_time refuses a level that would bring the job past it: -target_load 0.01 from the fast level (its estimate
   11 %) with -target_time 1 (the fast level alone takes about 2 s): no second level, one warning naming -target_time,
   target_met 0, accuracy_level 1. Planted: the time limit not consulted -> FAILED.
"""
import re
import os
from concurrent.futures import ThreadPoolExecutor

import h5py
import numpy as np

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
k = Checks("target")
BASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-progress", 0, "-output_every", 100000, "-output_stroke", 0]
CCX = {1.0: 104.93, 2.0: 124.95, 3.0: 164.03, 4.2: 280.11}  # N/mm, CalculiX 8 x 180 (docstring)
CCX_UNC = 0.007  # the reference's own uncertainty: its end-of-stroke load's rise with the contact penalty


def attrs(path):
    with h5py.File(path, "r") as h:
        a = dict(h["/history"].attrs)
        H = h["/history"]
        load = H["stage"][:] == 0
        a["_U"], a["_P"] = H["stroke"][:][load], H["load"][:][load]
        a["_cells"] = h["viz/topology/cells"].shape[0]
    return a


def fresh(name):
    path = out(name + ".h5")
    for f in (path, path[:-3] + ".level1.h5", path[:-3] + ".level2.h5", path[:-3] + ".xmf"):
        if os.path.exists(f):
            os.remove(f)
    return path


# The runs two at a time (both cores: PROCESSORS 2 in tests/CMakeLists.txt), D's 2-rank run among them: its second
# rank runs level 1's companions and then waits idle (src/driver/beside.cpp), so it takes about one core. B's first
# (its level's increments set C's stop), beside D's 2-rank run; then D on 1 rank, A, C and D's level 1 alone. Unbound
# from cores: mpirun would bind its first rank to the core a single-rank run beside it may be on.
os.environ["OMPI_MCA_hwloc_base_binding_policy"] = "none"
RADIAL = BASE + ["-plastic_update", "radial"]
D_DEMAND = RADIAL + ["-target_load", 0.1, "-element_bar_nt", 4, "-target_levels", 2]
H5 = {n: fresh(n) for n in ("target_a", "target_b", "target_c", "target_d1", "target_d_np1", "target_d_np2",
                             "target_e", "target_f_np1", "target_f_np2", "target_g", "target_g1", "target_q1",
                             "target_h")}
OWN = BASE + ["-plastic_update", "tangent", "-target_c_over_t", 0.003, "-stroke", 3, "-target_levels", 2]
with ThreadPoolExecutor(max_workers=2) as pool:
    go = lambda n, opts: pool.submit(run, tf, mpirun, n, opts, check=False, timeout=600)  # noqa: E731
    f_d2 = go(2, D_DEMAND + ["-output", H5["target_d_np2"]])
    f_b = go(1, BASE + ["-target_load", 0.05, "-target_levels", 1, "-output", H5["target_b"]])
    f_d, f_a = go(1, D_DEMAND + ["-output", H5["target_d_np1"]]), go(1, BASE + ["-target_load", 0.05, "-output",
                                                                             H5["target_a"]])
    p_b = f_b.result()
    first = int(next((l.split("done, ")[1].split()[0] for l in p_b.stdout.splitlines() if "done, " in l), 0))
    f_c = go(1, BASE + ["-target_load", 0.05, "-rmin_max_increments", first + 20, "-output", H5["target_c"]])
    f_d1 = go(1, D_DEMAND + ["-target_levels", 1, "-output", H5["target_d1"]])
    f_e = go(1, BASE + ["-target_load", 0.05, "-target_levels", 1, "-plastic_update", "tangent", "-stroke", 0.5,
                        "-output", H5["target_e"]])
    f_f1, f_f2 = go(1, OWN + ["-output", H5["target_f_np1"]]), go(2, OWN + ["-output", H5["target_f_np2"]])
    f_g, f_g1 = (go(1, BASE + ["-target_load", 0.2, "-output", H5["target_g"]]),
                 go(1, BASE + ["-target_load", 0.2, "-target_levels", 1, "-output", H5["target_g1"]]))
    f_h = go(1, BASE + ["-target_load", 0.01, "-target_time", 1, "-output", H5["target_h"]])
    p_d1 = f_d1.result()
    # Level 1 at twice its increment limits (the fast preset's: -rmin_deps, -rmin_domega at their defaults), its
    # element and friction regularization as level 1 chose them.
    vcri = attrs(H5["target_d1"]).get("friction_vcri", 0) if p_d1.returncode == 0 else 0
    f_q1 = go(1, RADIAL + ["-error_estimate", 0, "-element", "qm6", "-friction_vcri", repr(float(vcri)),
                          "-increments", 50, "-rmin_deps_yield", 4, "-rmin_deps", 0.004, "-rmin_domega", 0.02,
                          "-output", H5["target_q1"]])
    p_d2, p_d, p_a, p_c, p_e, p_f1, p_f2, p_g, p_g1, p_q1, p_h = (f.result() for f in (f_d2, f_d, f_a, f_c, f_e, f_f1,
                                                                                        f_f2, f_g, f_g1, f_q1, f_h))

# A. Two levels meet the target.
h5, p = H5["target_a"], p_a
a = attrs(h5) if p.returncode == 0 else {}
levels = [l for l in p.stdout.splitlines() if "accuracy on demand, level" in l]
k.check(p.returncode == 0 and levels and a.get("accuracy_level", 0) >= 2,
        f"A: a finer level follows the fast one ({len(levels)} line(s) 'accuracy on demand, level', exit "
        f"{p.returncode}, accuracy_level {a.get('accuracy_level')})")
if a:
    k.check(a.get("target_met") == 1 and a["error_load"] <= 0.05,
            f"A: its estimate meets the target (error_load {100 * a['error_load']:.2f} % <= 5 %, target_met "
            f"{a.get('target_met')})")
    worst = max(abs(np.interp(u, a["_U"], a["_P"]) / ref - 1) for u, ref in CCX.items())
    k.check(worst <= 0.05 + CCX_UNC, f"A: its load within 5 % of CalculiX's at U = 1, 2, 3, 4.2 (largest "
            f"{100 * worst:.2f} %)")
    k.check(not os.path.exists(h5[:-3] + ".level1.h5"), "A: the first level's copy is gone once the second ended")
    # Held to what was demanded alone: every level's estimate line names the load's target and no other (the fast
    # preset's own C/t expectation, 0.05, is not held: no level refines for it, so none may warn of it).
    said = [l for l in p.stdout.splitlines() if "estimated error" in l]
    k.check(said and all(l.endswith("(target load 5 %)") for l in said) and a.get("target_c_over_t") == 0,
            f"A: held to the demanded load alone ({len(said)} estimate line(s), the last ending "
            f"'{said[-1][-28:] if said else ''}', target_c_over_t {a.get('target_c_over_t')})")

# E. The plastic update a demanded accuracy chooses, and the one a user names.
meshes = [l for l in p_a.stdout.splitlines() if l.startswith("tubeform: mesh ")]
reused = [l for l in p_a.stdout.splitlines() if "error estimate's mesh part from level" in l]
k.check(len(meshes) >= 2 and all(l.endswith(", radial return") for l in meshes) and len(reused) == len(meshes) - 1,
        f"E: -target_load without -plastic_update takes the radial return ({sum(l.endswith(', radial return') for l in meshes)}"
        f" of {len(meshes)} levels say so; {len(reused)} finer level(s) taking the last as their mesh companion)")
named = [l for l in p_e.stdout.splitlines() if l.startswith("tubeform: mesh ")]
k.check(p_e.returncode == 0 and len(named) == 1 and not named[0].endswith("radial return"),
        f"E: -plastic_update tangent named beside -target_load is kept (exit {p_e.returncode}: {named})")

# F. A level with companions of its own, on 2 ranks beside the run.
f = {n: attrs(H5[f"target_f_np{n}"]) if p.returncode == 0 else {} for n, p in ((1, p_f1), (2, p_f2))}
own = [l for l in p_f2.stdout.splitlines() if "companion runs for the error estimate" in l and "beside" in l]
if f[1] and f[2]:
    keys = [x for x in f[2] if x.startswith("error_") or x in ("loaded_load", "loaded_c_over_t", "friction_vcri")]
    off = max(abs(f[1][x] - f[2][x]) / max(abs(f[2][x]), 1e-12) for x in keys)
    k.check(f[2].get("accuracy_level") == 2 and len(own) == 2 and off <= 1e-9,
            f"F: level 2 with its own companions beside the run on 2 ranks ({len(own)} companion line(s) 'beside', "
            f"accuracy_level {f[2].get('accuracy_level')}) gives the 1-rank estimate (largest relative difference "
            f"{off:.2g} over {len(keys)} values)")
else:
    k.check(False, f"F: the runs ended (exit {p_f1.returncode}, {p_f2.returncode})")

# B. One level allowed: a warning naming -target_levels.
h5, p = H5["target_b"], p_b
warn = [l for l in p.stdout.splitlines() if "warning" in l and "-target_levels 1" in l]
b = attrs(h5) if p.returncode == 0 else {}
k.check(p.returncode == 0 and len(warn) == 1 and b.get("target_met") == 0 and b.get("accuracy_level") == 1,
        f"B: -target_levels 1: one level, one warning naming it ({len(warn)}), target_met {b.get('target_met')}")

# G. A target the fast level's estimate meets, which does not read its wall of 2 cells: a finer level follows.
unread = "the estimate does not read the wall's 2 cells through"
g, g1 = (attrs(H5[n]) if p.returncode == 0 else {} for n, p in (("target_g", p_g), ("target_g1", p_g1)))
said = [l for l in p_g.stdout.splitlines() if l.startswith(f"tubeform: {unread}: level 2 follows")]
k.check(len(said) == 1 and g.get("accuracy_level") == 2 and g.get("target_met") == 1 and
        g.get("error_covers_wall") == 1 and g.get("error_load", 1) <= 0.2,
        f"G: level 1's estimate within 20 %, its wall unread: level 2 follows ({len(said)} line(s) '{unread}: level 2 "
        f"follows'), accuracy_level {g.get('accuracy_level')}, its estimate reads the wall (error_covers_wall "
        f"{g.get('error_covers_wall')}) and meets the target (target_met {g.get('target_met')})")
warn = [l for l in p_g1.stdout.splitlines() if "warning" in l and unread in l and "-target_levels 1" in l]
k.check(p_g1.returncode == 0 and len(warn) == 1 and g1.get("target_met") == 0 and g1.get("error_load", 1) <= 0.2,
        f"G: one level allowed: its estimate within 20 % ({100 * g1.get('error_load', 1):.2f} %), but unread in the "
        f"wall: one warning saying so ({len(warn)}), target_met {g1.get('target_met')}")

# H. A time limit the next level would pass: the run ends at level 1, warned.
h = attrs(H5["target_h"]) if p_h.returncode == 0 else {}
warn = [l for l in p_h.stdout.splitlines() if "warning" in l and "-target_time 1 s" in l]
k.check(p_h.returncode == 0 and len(warn) == 1 and h.get("accuracy_level") == 1 and h.get("target_met") == 0,
        f"H: -target_time 1 refuses level 2: {len(warn)} warning(s) naming it, accuracy_level "
        f"{h.get('accuracy_level')}, target_met {h.get('target_met')} (exit {p_h.returncode})")

# C. The second level stops: the first level's results are kept.
h5, p = H5["target_c"], p_c
kept = h5[:-3] + ".level1.h5"
c = attrs(kept) if os.path.exists(kept) else {}
stopped = attrs(h5) if os.path.exists(h5) else {}
k.check(p.returncode != 0 and c.get("stopped") == 0 and "error_load" in c and c.get("accuracy_level") == 1 and
        stopped.get("stopped") == 1 and stopped.get("accuracy_level") == 2,
        f"C: level 2 stopped (exit {p.returncode}, -rmin_max_increments {first + 20}): level 1's complete results "
        f"kept in {os.path.basename(kept)} ({'present' if c else 'absent'}), level 2's so far in -output")
# D. Level 2 from level 1: its mesh part from level 1's run, its increments' part from level 1's cells.
h5, p1 = H5["target_d1"], p_d1
l1 = attrs(h5) if p1.returncode == 0 else {}
q1 = attrs(H5["target_q1"]) if p_q1.returncode == 0 else {}
k.check(bool(l1) and bool(q1), f"D: level 1 alone and at twice its increment limits ran (exit {p1.returncode}, "
        f"{p_q1.returncode})")
got = {}
for n in (1, 2):
    h5 = H5[f"target_d_np{n}"]
    p = p_d if n == 1 else p_d2
    meshes = [tuple(map(int, m)) for m in re.findall(r"-mesh_nt (\d+) through the wall x -mesh_ntheta (\d+)", p.stdout)]
    reused = [l for l in p.stdout.splitlines() if "mesh part from level 1's run" in l]
    steps = [l for l in p.stdout.splitlines() if "increments part: level 1's" in l]
    a = attrs(h5) if p.returncode == 0 else {}
    k.check(p.returncode == 0 and a.get("accuracy_level") == 2 and len(reused) == 1 and len(steps) == 1 and
            len(meshes) == 2,
            f"D ({n} rank(s)): level 2 follows, takes level 1 as its estimate's mesh companion and its increments' "
            f"part from level 1's cells ({len(reused)}, {len(steps)} line(s), exit {p.returncode}, accuracy_level "
            f"{a.get('accuracy_level')})")
    got[n] = (a, meshes)
a, meshes = got[2]
if l1 and q1 and a and len(meshes) == 2:
    r = min(meshes[1][0] / meshes[0][0], meshes[1][1] / meshes[0][1])
    for value, error in [(f"load_at_{u}", f"error_load_at_{u}") for u in (1, 2, 3)] + [("loaded_load",
                                                                                        "error_loaded_load")]:
        p1_, p2_, q1_, e2 = l1[value], a[value], q1[value], a[error]
        d = abs(p1_ - p2_) / abs(p2_) / (r - 1) + abs(q1_ - p1_) / abs(p2_)
        exact = value != "loaded_load"  # (the end: the largest over its last trial increment, D + S its least)
        ok = abs(e2 - d) <= 1e-9 if exact else e2 >= d - 1e-9
        k.check(ok, f"D: level 2's {error} {100 * e2:.4f} % {'is' if exact else 'at least'} level 1's difference "
                f"over r - 1 plus its increments' part, {100 * d:.4f} % (cells {r:g} times as large)")
if l1 and a and len(meshes) == 2:
    elements = re.findall(r"cells \(.*\), (\w+) elements", p_d2.stdout)
    k.check(elements == ["qm6", "qm6"] and a.get("friction_vcri") == l1.get("friction_vcri"),
            f"D: level 2 keeps level 1's element ({elements}) and friction regularization (friction_vcri "
            f"{l1.get('friction_vcri')} -> {a.get('friction_vcri')})")
if got[1][0] and a:
    keys = [x for x in a if x.startswith("error_") or x in ("loaded_load", "loaded_c_over_t")]
    off = max(abs(got[1][0][x] - a[x]) / max(abs(a[x]), 1e-12) for x in keys)
    k.check(off <= 1e-9, f"D: 1 and 2 ranks (the companions beside) give the same level 2 and estimate "
            f"(largest relative difference {off:.2g} over {len(keys)} values)")
k.done()
