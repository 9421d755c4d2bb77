"""Turning the tube between passes (-pass2_turn).

The paper's tube (options/squaring.opts, the fast preset): the V-dies press it to U = 3 mm, it springs back (the
paper's unloading), is turned by a quarter turn and pressed again by 3 mm with the same dies, then springs back.
The second pass's dies are drawn turned the other way about the tube's centre; its metrics and tool forces are
in its press's frame (its die moving along -y).

A. Two models, two constructions. The full model turns the dies by -90 degrees (their outlines, pins on the turned
   axis, the springback's pin); the quarter model draws the same press by the reflection about y = x, which keeps
   its symmetry planes (a quarter turn of a tube symmetric about both axes). Load, C1, C2, C/t and C1/C2 along
   each press's stroke, and at the end of each springback, agree within tests/check_squaring.py's 1 vs 2 rank
   bounds (1.3e-8 of the largest value up to U = 2.6 mm of the first press, 3e-5 beyond it and in the second
   press, which starts from the collapsed wall that amplifies round-off; the models sum the same contributions
   in another order; measured 6e-11 and 1.9e-8); the full model's internal work is four times the quarter's
   within the same bounds. A die
   turned the wrong way, a pin left on the first axis or a metric in the tube's frame moves these by O(1e-2) or
   more.
B. Half a turn is the same press (the tube after the first pass is symmetric about the x axis): the full model
   (dies turned by 180 degrees) and the half model (dies drawn by y -> -y: the V-die below, its mirror above)
   against the quarter model that does not turn, within A's bounds; the half model's die force across the press
   and its moment too (its upper die carries the quarter's contacts; the reflection turns the moment around,
   which the press's frame turns back).
C. What the turn does: the second pass's die moves along the tube's -x (its outline in the results: (-3, 0) mm at
   the end); it first touches the tube at the stroke where the V-die's surface (computed here from its
   dimensions) reaches the shape the first springback left, turned into its frame, within 1e-6 mm (10 x the
   contact gap tolerance; measured 7e-13 mm); pressed across its first path the tube yields again, where
   pressing with the same die again retraces the elastic springback and ideally adds no plastic work: the
   retrace's growth (measured +0.04 %, from the contact set's changes over the springback) below 0.1 %, the
   turned press's (measured +0.45 %) above twice that bound, 0.2 %.
D. A checkpoint inside the turned second press of the full model, continued with -restart: the history of the run
   never stopped within 1e-12 of each column's largest value (tests/check_restart.py's bound; a restart that
   left the pins on the first pass's axis, or drew the dies unturned, would differ at O(1)). 1 vs 2 ranks: A's
   bounds.
E. An oval pre-form, then the square die (options/oval_then_square.opts on the fast preset, the quarter model): flat
   plates press the tube 3 mm into an oval, it springs back, turns a quarter turn, and the V-dies press across
   its long axis. On the round tube's circle the V-die would start inside the oval: it starts moved back along
   its motion by the depth computed here from its dimensions and the first springback's shape, within 1e-6 mm
   (C's bound; measured 2.9e-9 mm, the contact set's start tolerance; ClearanceBack's closed forms:
   tests/test_tool.cpp), touching the tube in the second press's first increment; a checkpoint inside that
   press continued as D's; the V-dies square the oval, the process's purpose: after springback the paper's
   deviation ratio min(C1, C2)/max(C1, C2), from x_max and y_max, at least half-way nearer 1 than the oval's
   (measured 0.7695 -> 0.9903). That measure, not C1/C2 = x_max / y_max, because each press measures in its own
   frame and a quarter turn swaps C1 and C2 (the oval's C1/C2 1.2996 across the plates, 0.77 in the V-dies').
F. A quarter turn, then the V-die over a floor (-pass2_lower_die flat): -model auto takes the full model (the
   half's plane x = 0 is no symmetry plane of the turned press), and the displacement after the second
   springback is mirror-symmetric about the turned press's axis, the tube's x axis, within 1e-8 of its largest
   value (tests/check_models.py F's bound: the same sums in another order): the pins on the turned axis carry
   nothing; on the first pass's axis they would hold the tube against the floor's push and it would lean.
"""
from concurrent.futures import ThreadPoolExecutor

import h5py
import numpy as np

from tfcheck import Checks, args, checkpoint_at, history_and_tools, out, run, run_all

tf, mpirun, src = args()
k = Checks("turn")
U = 3.0
BASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-error_estimate", 0, "-progress", 0, "-stroke", U, "-pass2_stroke", U]
EARLY, LATE = 1.3e-8, 3e-5  # tests/check_squaring.py's 1 vs 2 rank bounds (docstring, A)
GRID = np.linspace(0.2, U, 15)


TURNED = ["-pass2_turn", 90, "-model", "full"]
OVAL = ["-options_file", f"{src}/options/oval_then_square.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-error_estimate", 0, "-progress", 0]
# The single-rank runs, two at a time before the checks read them.
RUNS = {"turn_quarter.h5": BASE + ["-pass2_turn", 90], "turn_full.h5": BASE + TURNED, "turn_none.h5": BASE,
        "turn_full_180.h5": BASE + ["-pass2_turn", 180, "-model", "full"],
        "turn_half_180.h5": BASE + ["-pass2_turn", 180, "-model", "half"], "turn_oval.h5": OVAL,
        "turn_floor.h5": BASE + ["-pass2_turn", 90, "-pass2_lower_die", "flat"]}
run_all(tf, mpirun, [opts + ["-output", out(name)] for name, opts in RUNS.items()], timeout=600)


def press(name, n=1):
    """The history and tools of one of RUNS, run already (or on n ranks now)."""
    if n > 1:
        run(tf, mpirun, n, RUNS[name.replace(f"_np{n}", "")] + ["-output", out(name)], timeout=600)
    return history_and_tools(out(name))


def profile(h, stage, col):
    """A press stage's column along its own stroke (the second pass's counted from its start)."""
    s = h["stage"] == stage
    return np.interp(GRID, h["stroke"][s] - (U if stage == 2 else 0), h[col][s])


def end_of(h, stage, col):
    return h[col][h["stage"] == stage][-1]


def agree(a, b, cols, label, scale_b=1.0):
    for col in cols:
        top = max(np.abs(a[col]).max(), 1e-300)
        rel = {st: np.abs(profile(a, st, col) - scale_b * profile(b, st, col)) / top for st in (0, 2)}
        early = rel[0][GRID <= 2.6].max()
        late = max(rel[0].max(), rel[2].max())
        ends = max(abs(end_of(a, st, col) - scale_b * end_of(b, st, col)) / top for st in (0, 1, 2, 3))
        k.check(early < EARLY and max(late, ends) < LATE,
                f"{label}, {col}: the first press within {early:.1e} of its largest value up to U = 2.6 mm "
                f"({EARLY:g}), both presses within {late:.1e}, each stage's end within {ends:.1e} ({LATE:g})")


SHAPE = ("load", "x_max", "y_max", "c_over_t", "deviation_ratio")

# A. The full model against the quarter, turned by 90 degrees.
quarter = press("turn_quarter.h5")
full = press("turn_full.h5")
k.check(sorted(set(full["stage"].astype(int))) == [0, 1, 2, 3] and quarter["load"][quarter["stage"] == 2].max() > 0,
        "two passes: stages 0-3 in the history, the turned second press carries a load")
agree(quarter, full, SHAPE, "turned by 90 degrees, the full model against the quarter")
agree(quarter, full, ("w_int",), "turned by 90 degrees, the full model's internal work against 4 x the quarter's",
      scale_b=0.25)

# B. Half a turn: the press of a pass that does not turn.
plain = press("turn_none.h5")
for model in ("full", "half"):
    turned = press(f"turn_{model}_180.h5")
    agree(plain, turned, SHAPE, f"turned by 180 degrees, the {model} model against the quarter model not turned")
# The half model's upper die carries the quarter's contacts (its right half): its force across the press and its
# moment, which the reflection that draws half a turn turns around, in the press's frame as the quarter's.
agree(plain, turned, ("tool_fx", "tool_moment"), "turned by 180 degrees, the half model's die force across and moment")

# C. Where the turned die moves, where it meets the tube, and what it does to it.
moved = full["tools"]["pass2-V-die"][-1]
k.check(np.abs(moved - [-U, 0]).max() < 1e-12,
        f"the turned second pass's die moves along the tube's -x: its outline at the end displaced by "
        f"({moved[0, 0]:g}, {moved[0, 1]:g}) mm")
# The stroke at which the turned V-die (apex fillet r 3, flanks at 45 degrees touching the round tube's circle)
# first reaches an outer node where the first springback left it, in the second press's frame (the tube's
# coordinates turned by +90 degrees): min over the nodes of the die's lower surface above the node.
OPTS = dict(line.split()[:2] for line in open(f"{src}/options/squaring.opts") if line.startswith("-tube_ro") or
            line.startswith("-die_r_apex"))
RO, R_APEX = float(OPTS["-tube_ro"]), float(OPTS["-die_r_apex"])  # (the paper's 90-degree V-die: its flanks at 45)
with h5py.File(out("turn_full.h5"), "r") as h:
    X, t = h["/geometry/vertices"][:], h["/time"][:, 0]
    p = X + h["/vertex_fields/displacement_u"][int(np.argmin(np.abs(t - 2.0)))]
p = p[np.abs(np.hypot(X[:, 0], X[:, 1]) - RO) < 1e-9]
xs, ys = np.abs(-p[:, 1]), p[:, 0]
apex_h = RO * np.sqrt(2)
surface = np.where(xs >= R_APEX / np.sqrt(2), apex_h - xs,
                   apex_h - R_APEX * np.sqrt(2) + np.sqrt(np.maximum(R_APEX**2 - xs**2, 0)))
s2 = full["stage"] == 2
first = full["stroke"][s2][np.argmax(full["n_contact"][s2] > 0)]  # (the die's position)
miss = abs(first - (surface - ys).min())
k.check(miss < 1e-6,
        f"the turned die first touches the tube at stroke {first:.6f} mm, where its surface reaches the first "
        f"springback's shape within {miss:.1e} mm (1e-6 mm: ten times the contact gap tolerance)")
# Pressed across, the tube yields again; the same die again (the retrace of B's plain run) reloads the elastic
# springback and ideally adds no plastic work.
growth = {n: end_of(h, 2, "w_plastic") / end_of(h, 1, "w_plastic") - 1 for n, h in (("turned", quarter), ("plain", plain))}
k.check(growth["turned"] > 2e-3 and growth["plain"] < 1e-3,
        f"the turned press yields the tube again: plastic work +{growth['turned']:.2%} (more than 0.2 %), the "
        f"same die again +{growth['plain']:.2%} (less than 0.1 %: the reload retraces the elastic springback)")

# D. A checkpoint inside the turned press, continued; 1 vs 2 ranks.
def stop_and_continue(opts, whole, name):
    """The run of `opts` checkpointed half way through its second press (as `whole` counts increments), continued."""
    ck = out(f"{name}_ck.h5")
    every = int(np.sum(whole["stage"] <= 1)) + int(np.sum(whole["stage"] == 2)) // 2
    # (stopped there: the rest, which the restart computes, is not run twice)
    checkpoint_at(tf, mpirun, 1, opts + ["-output", out(f"{name}.h5")], ck, every, timeout=600)
    run(tf, mpirun, 1, opts + ["-output", out(f"{name}.h5"), "-restart", ck], timeout=600)


def continued(whole, name, label):
    """stop_and_continue's run against `whole`."""
    with h5py.File(out(f"{name}_ck.h5"), "r") as c:
        lam = c["/run/lambda"][0]
    part = history_and_tools(out(f"{name}.h5"))
    cols = [c for c in whole if c != "tools"]
    same = all(part[c].shape == whole[c].shape for c in cols)
    worst = max(np.abs(part[c] - whole[c]).max() / max(np.abs(whole[c]).max(), 1e-300) for c in cols) if same else 1
    k.check(same and worst <= 1e-12 and 2 < lam < 3,
            f"{label}, continued from a checkpoint inside the second press (lambda {lam:.3f}): the history within "
            f"{worst:.1e} (1e-12)")


ovl = "turn_oval.h5"
oh = history_and_tools(out(ovl))
with ThreadPoolExecutor(max_workers=2) as pool:  # D's and E's single-rank pairs of runs side by side
    list(pool.map(lambda a: stop_and_continue(*a), ((BASE + TURNED, full, "turn_part"), (OVAL, oh, "turn_oval_part"))))
continued(full, "turn_part", "the full model turned by 90 degrees")
two = press("turn_full_np2.h5", 2)
agree(full, two, SHAPE, "turned by 90 degrees, the full model on 1 vs 2 ranks")

# E. An oval pre-form, then the square die (options/oval_then_square.opts, the quarter model): plates press the
# tube into an oval; turned, the V-dies press across its long axis and start where they touch it.
with h5py.File(out(ovl), "r") as h:
    X, t = h["/geometry/vertices"][:], h["/time"][:, 0]
    p = X + h["/vertex_fields/displacement_u"][int(np.argmin(np.abs(t - 2.0)))]
    # The outline's first point: the apex fillet's end on the die's axis (the profile's arc runs from 90 to 45
    # degrees; the reflection that draws the turn reverses it, so it starts there). Checked: on the axis y = 0.
    apex = h["/tools/pass2-die/vertices"][0]
# The quarter model draws the turned V-die by y = x: in its press's frame a node is at (y, x).
p = p[np.abs(np.hypot(X[:, 0], X[:, 1]) - RO) < 1e-9]
xs, ys = np.abs(p[:, 1]), p[:, 0]
surface = np.where(xs >= R_APEX / np.sqrt(2), apex_h - xs,
                   apex_h - R_APEX * np.sqrt(2) + np.sqrt(np.maximum(R_APEX**2 - xs**2, 0)))
back = max(0.0, -(surface - ys).min())  # how far back the die must start to clear the oval
moved = apex[0] - (apex_h - R_APEX * np.sqrt(2) + R_APEX)
s2 = oh["stage"] == 2
k.check(back > 0.01 and abs(moved - back) < 1e-6 and abs(apex[1]) < 1e-12 and oh["n_contact"][s2][0] > 0,
        f"oval, then the V-dies turned: on the round tube's circle the die would start {back:.4f} mm inside the "
        f"oval; it starts {moved:.4f} mm back along its motion (within {abs(moved - back):.1e} mm; 1e-6), touching "
        f"it ({oh['n_contact'][s2][0]:.0f} nodes in contact in the second press's first increment)")
continued(oh, "turn_oval_part", "oval, then the V-dies turned (the die's start moved back)")
c1_c2 = [end_of(oh, st, "x_max") / end_of(oh, st, "y_max") for st in (1, 3)]
dev = [min(r, 1 / r) for r in c1_c2]  # min(C1, C2)/max(C1, C2): the same in either press's frame
k.check(abs(1 - dev[1]) < 0.5 * abs(1 - dev[0]),
        f"the V-dies square the oval: min(C1, C2)/max(C1, C2) after springback {dev[0]:.4f} after the plates, "
        f"{dev[1]:.4f} after the V-dies, at least half-way nearer 1 (C1/C2 {c1_c2[0]:.4f}, {c1_c2[1]:.4f}, each in "
        f"its press's frame)")

# F. A quarter turn, then the V-die over a floor: the half model cannot draw it (its plane x = 0 is no symmetry
# plane of that press); -model auto takes the full model, which holds the tube on the turned axis.
FLOOR = "turn_floor.h5"
with h5py.File(out(FLOOR), "r") as h:
    X, Uf, tools = h["/geometry/vertices"][:], h["/vertex_fields/displacement_u"][-1], sorted(h["/tools"])
mirror = [np.flatnonzero((np.abs(X[:, 0] - x) < 1e-9) & (np.abs(X[:, 1] + y) < 1e-9)) for x, y in X]
lean = 1.0
if all(len(i) == 1 for i in mirror):
    mirror = np.array([i[0] for i in mirror])
    lean = max(np.abs(Uf[mirror, 0] - Uf[:, 0]).max(), np.abs(Uf[mirror, 1] + Uf[:, 1]).max()) / np.abs(Uf).max()
k.check(tools == ["V-die", "lower-V-die", "pass2-V-die", "pass2-floor"] and np.any(X[:, 0] < -1) and lean < 1e-8,
        f"a quarter turn, then the V-die over a floor: -model auto models the whole tube ({', '.join(tools)}); the "
        f"displacement after the second springback mirror-symmetric about the turned press's axis (the tube's x "
        f"axis) within {lean:.1e} of its largest value (1e-8, as tests/check_models.py's F: pins on the wrong axis "
        f"would make the tube lean)")
k.done()
