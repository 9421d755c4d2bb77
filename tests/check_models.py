"""The half model and the lower die (-model, -lower_die, -lower_die_motion).

The paper's tube (options/squaring.opts, the fast preset, U = 4.2 mm and the paper's springback):

A. Half against quarter. `-model half` presses the half tube x >= 0 between the upper V-die and its mirror
   image moving up: the quarter model's symmetry about the x axis is then a result, not a support. Load, C1,
   C2, C/t and C1/C2 along the stroke and after springback agree with the quarter within the bounds of
   tests/check_squaring.py's 1 vs 2 ranks (1.3e-8 of the largest value up to U = 2.6 mm, 3e-5 beyond, where
   the wall's collapse amplifies round-off): the half model sums the same contributions in another order
   (measured 4e-11 with the default preset). Its internal work, friction work and kinetic energy are twice the
   quarter's (the same bounds): the lower die does the work the y = 0 support stood in for. A lower die left
   in place, or one pressing on the wrong side of its mirrored segments, changes the load at 1e-2 or more.
B. A fixed lower die (`-lower_die_motion fixed`, the upper die travelling 2 U): the same press seen from the
   lower die, so load, C/t, C1 and the half height C2 agree with A's half model within 1e-6 of the largest
   value (the tube now moves down at the punch speed: inertia starting it, measured 3.6e-8 with the default
   preset; a die moving by U instead of 2 U would halve the squaring), and the nodes that started on the x
   axis have come down by U at the end of loading (the middle of the closed cavity) within 1e-6 mm (measured
   4e-10 mm; a rigid drift of the tube would show).
C. The V-die over a flat floor (`-lower_die flat`, fixed): no symmetry about the x axis. Each step balanced
   tightly (-equilibrium_tol 1e-6), so that the tube's vertical balance shows the forces the two dies carry:
   the floor's force against the die's within 1e-3 of the punch force at every increment (measured 7.9e-5,
   where the stored normal forces drift from the body's by fn_mismatch 3.5e-3 N/mm; at the fast preset's
   tolerance 5e-3 q_avg per dof the residuals alone sum to 5e-3; a floor force lost, doubled or given to the
   die would be O(1)). The energy balance (the press's work from the reported punch load, the upper die
   travelling 2 U, against internal work + friction + inertia) within 5e-3 at every increment, as
   tests/check_squaring.py's (a) (measured 3.0e-3 in the first increment, the trapezoidal work of its
   first step, 1.1e-4 past U = 0.5 mm); the floor's outline stays in place and the die's moves by
   (0, -2 U) in the results. (1 vs 2 ranks with a floor: D.)
D. Two passes (-pass2_stroke): press, the paper's springback, press again with the second pass's dies from
   their start, spring back again (stages 0-3 of the history).
   - Retrace: frictionless, the same die and stroke again. The springback is linear elastic, so pressing back
     to the same stroke returns to the loaded state of the first pass: load within 2 % (measured 0.83 %: the
     contact set and geometry change over the springback), C/t within 2e-3 (measured 2.7e-4), C1 and C2
     within 2e-3 mm (measured 3.5e-4 mm). A second die placed where the first one ended, or the stresses lost
     between the passes, would move these by O(1).
   - V-dies, then the V-die over a flat floor (the half model in both passes, the floor under the tube's
     lowest point): the second press yields the tube again (plastic work up by more than 5 %: a body left
     elastic after the first springback would not); a checkpoint between the stages (at the end of the first
     springback) and one inside the second press, each continued with -restart: the history of the run never
     stopped within 1e-12 of each column's largest value (tests/check_restart.py's bound; measured 0; a
     restart that took the first pass's dies would press on the V instead of the floor); 1 vs 2 ranks within
     the bounds of A; the .xmf shows each pass's dies from the field step it starts at.
F. The full model (`-model full`): the whole tube, both V-dies across the y axis, its rotation and motion along x
   held by the x of its two outer nodes on the y axis. The quarter's press again: load, C1, C2, C/t and C1/C2
   within the bounds of A (measured 1.2e-10), its internal, friction and external work four times the quarter's;
   the displacement field mirror-symmetric about the y axis within 1e-8 of its largest value (the same sums in
   another order; measured 2.4e-13): a pin that carried a force, or a die's left half drawn on the wrong side,
   would make the tube lean. The V-die over a flat floor (C's press) in the full model against C's half: the
   same bounds (measured 3.2e-6 to U = 4.2 mm, where each step is balanced to C's -equilibrium_tol 1e-6).
E. The guide's example, options/own_die.opts (the shipped DXF die over a floor, then the V-die), runs on the
   fast preset: four stages, the dies of both passes in the results.
"""
import re
from concurrent.futures import ThreadPoolExecutor

import h5py
import numpy as np

from tfcheck import Checks, args, checkpoint_at, history_and_tools, out, run, run_all

tf, mpirun, src = args()
k = Checks("models")
U = 4.2
BASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-error_estimate", 0, "-progress", 0, "-stroke", U]
EARLY, LATE = 1.3e-8, 3e-5  # tests/check_squaring.py's 1 vs 2 rank bounds (docstring, A)
GRID = np.linspace(0.2, U, 22)


MIXED = ["-pass2_stroke", 3.0, "-pass2_lower_die", "flat"]
FLOOR = ["-lower_die", "flat", "-lower_die_motion", "fixed", "-equilibrium_tol", 1e-6]
# The single-rank presses, run two at a time before the checks read them, the longest first (a long one started
# last would leave the other core idle: the full model over a floor takes 21 s, the next 10 s, the rest 1-5 s).
RUNS = {"models_full_floor.h5": ["-model", "full"] + FLOOR, "models_floor.h5": FLOOR,
        "models_full.h5": ["-model", "full"], "models_mixed_np1.h5": MIXED, "models_half.h5": ["-model", "half"],
        "models_fixed.h5": ["-model", "half", "-lower_die_motion", "fixed"], "models_quarter.h5": [],
        "models_twice.h5": ["-friction_mu", 0, "-pass2_stroke", U]}
OWN_DIE = ["-options_file", f"{src}/options/own_die.opts", "-options_file", f"{src}/options/preset-fast.opts",
           "-error_estimate", 0, "-progress", 0, "-output", out("models_own_die.h5")]
run_all(tf, mpirun, [BASE + extra + ["-output", out(name)] for name, extra in RUNS.items()] + [OWN_DIE], timeout=600)


def press(name, n=1):
    """The results of a press: one of RUNS (run already), or RUNS' entry of that name on n ranks."""
    f = out(name)
    if n > 1:
        run(tf, mpirun, n, BASE + RUNS[name.replace(f"_np{n}", "_np1")] + ["-output", f], timeout=600)
    r = history_and_tools(f)
    with h5py.File(f, "r") as h:
        r["X"] = h["/geometry/vertices"][:]
        r["time"] = h["/time"][:]
        r["U"] = h["/vertex_fields/displacement_u"][:]
    return r


def along(h, col):
    s = h["stage"] == 0
    return np.interp(GRID, h["stroke"][s], h[col][s])


def agree(a, b, cols, label, scale_b=1.0, early=EARLY, late=LATE):
    """a's and scale_b x b's columns along the stroke, and at the end (after springback)."""
    for col in cols:
        ca, cb = along(a, col), scale_b * along(b, col)
        rel = np.abs(ca - cb) / max(np.abs(ca).max(), 1e-300)
        before = GRID <= 2.6
        k.check(rel[before].max() < early and rel.max() < late,
                f"{label}, {col}(U): {rel[before].max():.1e} of its largest value up to U = 2.6 mm ({early:g}), "
                f"{rel.max():.1e} to {U} mm ({late:g})")
    for col in ("x_max", "y_max", "c_over_t", "deviation_ratio"):
        if col not in cols:
            continue
        rel = abs(a[col][-1] - scale_b * b[col][-1]) / max(abs(a[col][-1]), 1e-12)
        k.check(rel < late, f"{label} after springback, {col}: {rel:.1e} ({late:g})")


SHAPE = ("load", "x_max", "y_max", "c_over_t", "deviation_ratio")

# A. Half against quarter.
quarter = press("models_quarter.h5")
half = press("models_half.h5")
k.check(sorted(half["tools"]) == sorted(["V-die", "lower-V-die"]) and list(quarter["tools"]) == ["V-die"],
        f"the half model presses with two dies ({', '.join(sorted(half['tools']))}), the quarter with one")
agree(quarter, half, SHAPE, "half against quarter")
agree(quarter, half, ("w_int", "w_friction", "w_ext"), "half = 2 x quarter", scale_b=0.5)

# B. The lower die fixed, the upper travelling 2 U.
fixed = press("models_fixed.h5")
agree(half, fixed, SHAPE, "fixed lower die against the moving one", early=1e-6, late=1e-6)
end = int(np.flatnonzero(np.isclose(fixed["time"], 1.0))[0])
axis = np.abs(fixed["X"][:, 1]) < 1e-12
drop = np.abs(fixed["U"][end][axis, 1] + U).max()
k.check(axis.sum() >= 2 and drop < 1e-6,
        f"fixed lower die: the {axis.sum()} nodes that started on the x axis come down by U: within {drop:.1e} mm "
        f"(1e-6)")
fd = fixed["tools"]
k.check(np.abs(fd["lower-V-die"]).max() == 0 and np.abs(fd["V-die"][end][:, 1] + 2 * U).max() < 1e-12,
        "fixed lower die: it stays in the results, the upper die moves by 2 U")

# C. The V-die over a flat floor.
h = press("models_floor.h5")
e = np.abs(h["energy_error"]).max()
k.check(e < 5e-3, f"floor: press work from the reported load = internal + friction + inertia work within {e:.2e} "
        f"(5e-3)")
s = h["stage"] == 0
balance = (np.abs(h["tool_fy"][s] + h["lower_fy"][s]) / np.abs(h["tool_fy"][s]).max()).max()
k.check(balance < 1e-3 and np.abs(h["lower_fy"][s]).max() > 0,
        f"floor: the floor's vertical force balances the die's within {balance:.1e} of the punch force (1e-3)")
k.check(np.abs(h["tools"]["floor"]).max() == 0 and np.abs(h["tools"]["V-die"][-1][:, 1] + 2 * U).max() < 1e-12,
        "floor: it stays in the results, the die moves by 2 U")
print(f"       U = {U}: load quarter {along(quarter, 'load')[-1]:.2f}, half {along(half, 'load')[-1]:.2f}, "
      f"V over floor {along(h, 'load')[-1]:.2f} N/mm")

# F. The full model.
full = press("models_full.h5")
agree(quarter, full, SHAPE, "full against quarter")
agree(quarter, full, ("w_int", "w_friction", "w_ext"), "full = 4 x quarter", scale_b=0.25)
X, Uf = full["X"], full["U"][-1]
mirror = np.array([np.flatnonzero((np.abs(X[:, 0] + x) < 1e-9) & (np.abs(X[:, 1] - y) < 1e-9))[0] for x, y in X])
lean = max(np.abs(Uf[mirror, 0] + Uf[:, 0]).max(), np.abs(Uf[mirror, 1] - Uf[:, 1]).max()) / np.abs(Uf).max()
k.check(lean < 1e-8, f"full model: the displacement after springback mirror-symmetric about the y axis within "
        f"{lean:.1e} of its largest value (1e-8)")
full_floor = press("models_full_floor.h5")
agree(h, full_floor, ("load", "y_max", "c_over_t"), "V over floor, full against half")
with h5py.File(out("models_full.h5"), "r") as f:
    spans = {t: (f["/tools"][t]["vertices"][:, 0].min(), f["/tools"][t]["vertices"][:, 0].max()) for t in f["/tools"]}
k.check(sorted(spans) == ["V-die", "lower-V-die"] and all(lo < -U and hi > U for lo, hi in spans.values()),
        "full model: both dies in the results, each across the y axis")

# D. Two passes.
def stage_end(h, stage, col):
    return h[col][h["stage"] == stage][-1]


twice = press("models_twice.h5")
k.check(sorted(set(twice["stage"].astype(int))) == [0, 1, 2, 3] and abs(twice["stroke"][-1] - U) < 1e-12,
        "two passes: stages 0-3 in the history, the second pass's stroke the die's position, ending at -pass2_stroke")
dl = abs(stage_end(twice, 2, "load") / stage_end(twice, 0, "load") - 1)
dc = abs(stage_end(twice, 2, "c_over_t") - stage_end(twice, 0, "c_over_t"))
dx = max(abs(stage_end(twice, 2, c) - stage_end(twice, 0, c)) for c in ("x_max", "y_max"))
k.check(dl < 0.02 and dc < 2e-3 and dx < 2e-3,
        f"two passes, frictionless, the same die and stroke again: the loaded state returns (load {dl:.1e} relative "
        f"(0.02), C/t {dc:.1e} (2e-3), C1 and C2 {dx:.1e} mm (2e-3))")


mixed = {n: press(f"models_mixed_np{n}.h5", n) for n in (1, 2)}
m = mixed[1]
grow = stage_end(m, 2, "w_plastic") / stage_end(m, 1, "w_plastic") - 1
k.check(grow > 0.05 and m["n_plastic"][m["stage"] == 2].max() > 0,
        f"V-dies, then a V-die over a floor: the second press yields the tube again (plastic work +{grow:.1%}; "
        f"more than 5 %)")


def stop_and_continue(every):
    """The mixed press run to increment `every`, its checkpoint written there, then continued from it."""
    name, ck = f"models_part_{every}.h5", out(f"models_ck_{every}.h5")
    checkpoint_at(tf, mpirun, 1, BASE + MIXED + ["-output", out(name)], ck, every, timeout=600)
    run(tf, mpirun, 1, BASE + MIXED + ["-output", out(name), "-restart", ck], timeout=600)


def restart_from(every, label):
    name, ck = f"models_part_{every}.h5", out(f"models_ck_{every}.h5")
    with h5py.File(ck, "r") as c:
        lam = c["/run/lambda"][0]
    with h5py.File(out(name), "r") as h:
        part = {c: h["/history"][c][:] for c in h["/history"]}
    same = all(part[c].shape == m[c].shape for c in part)
    worst = max(np.abs(part[c] - m[c]).max() / max(np.abs(m[c]).max(), 1e-300) for c in part) if same else 1
    k.check(same and worst <= 1e-12,
            f"V-dies, then a V-die over a floor: continued from a checkpoint {label} (lambda {lam:.3f}): the "
            f"history within {worst:.1e} (1e-12)")


first = int(np.sum(m["stage"] <= 1)) - 1  # the increments up to the end of the first springback
points = {"between the stages": first, "inside the second press": first + int(np.sum(m["stage"] == 2)) // 2}
with ThreadPoolExecutor(max_workers=2) as pool:  # the two single-rank pairs of runs side by side
    list(pool.map(stop_and_continue, points.values()))
for label, every in points.items():
    restart_from(every, label)
k.check(sorted(m["tools"]) == sorted(["V-die", "lower-V-die", "pass2-V-die", "pass2-floor"]),
        f"V-dies, then a V-die over a floor: the dies of both passes in the results ({', '.join(sorted(m['tools']))})")
worst = 0.0
for col in ("load", "x_max", "y_max", "c_over_t"):
    a, b = mixed[1][col], mixed[2][col]
    if a.shape != b.shape:
        worst = 1.0
        break
    worst = max(worst, np.abs(a - b).max() / np.abs(a).max())
k.check(worst < LATE, f"V-dies, then a V-die over a floor, 1 vs 2 ranks: every row within {worst:.1e} ({LATE:g})")
xmf = open(out("models_mixed_np1.xmf")).read()
steps = re.findall(r'<Grid Name="step(\d+)"(.*?)\n </Grid>\n(?= <Grid Name="step|</Grid>)', xmf, re.S)
shown = {t: [int(i) for i, body in steps if f'<Grid Name="{t}"' in body] for t in m["tools"]}
with h5py.File(out("models_mixed_np1.h5"), "r") as h:
    starts = {t: int(h["/tools"][t]["displacement"].attrs.get("first_step", 0)) for t in h["/tools"]}
switch = starts["pass2-V-die"]
k.check(len(steps) == len(m["time"]) and 0 < switch < len(steps) and
        shown["V-die"] == list(range(switch)) and shown["pass2-V-die"] == list(range(switch, len(steps))) and
        shown["pass2-floor"] == shown["pass2-V-die"],
        f"the .xmf shows the first pass's dies in steps 0-{switch - 1}, the second's from step {switch} to "
        f"{len(steps) - 1}")

# E. The guide's example (docs/guide.md, section 8): the shipped DXF die over a floor, then the V-die over it.
with h5py.File(out("models_own_die.h5"), "r") as h:
    stages, tools = set(h["/history/stage"][:].astype(int)), sorted(h["/tools"])
k.check(stages == {0, 1, 2, 3} and tools == ["die", "floor", "pass2-die", "pass2-floor"],
        f"options/own_die.opts: two passes, the DXF die and the V-die over floors ({', '.join(tools)})")
k.done()
