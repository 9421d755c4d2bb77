"""Each pass's lower die's motion (-lower_die_motion, -pass<N>_lower_die_motion: mirror or fixed).

The paper's tube (options/squaring.opts, the fast preset) on the half model (both dies modelled), pressed to
U = 1.5 mm with the dies mirroring each other, sprung back, then pressed to U = 2.5 mm and sprung back again:
  MIRROR: the second pass's lower die mirrors the upper one (up by U as the upper die goes down by U);
  FIXED:  -pass2_lower_die_motion fixed: it stays where the pass's dies start, the upper die travels 2 U.
The stroke U is half the dies' closing from the same zero in both, so the two second passes close the dies on the
tube alike and differ by the tube's rigid motion along the press's y (FIXED's tube pushed down through the gap the
first pass left under it).

A. The second pass of FIXED presses as MIRROR's: load, C1, C2, C/t, internal and friction work at the end of each
   stage within 1e-5 of each column's largest value. The bound: the rigid motion costs only the tube's inertia at the
   punch speed (measured 1e-7 in C/t, 2e-8 in the load). A says the two motions give one press; B that FIXED's
   lower die did stay (a pass's motion ignored makes the two runs one, which A alone would pass).
B. The tools' travel at the end of the second pass (results' /tools displacement, exact in floating point: 1e-12
   mm): FIXED's lower die (0, 0), its upper die (0, -2 x 2.5); MIRROR's (0, 2.5) and (0, -2.5). The first pass's
   dies, the same in both runs: (0, 1.5) and (0, -1.5).
C. The run's own energy balance (energy_error, the punch load's work over the upper die's travel against the
   internal and friction work) at the end of FIXED within 1e-3: an upper die's work counted over U rather than its 2 U
   leaves half of the second press's work unmatched (the run stops at its own energy check, 25 %).
D. A first pass's lower die on a path of its own (-lower_die_motion path -lower_die_path 1,0,2,1: it waits to U = 1
   mm, then rises 1 mm by U = 2), then a second pass over one that stays (-pass2_lower_die_motion fixed): the dies'
   outlines at the ends (1e-12 mm) and the run's energy balance from U = 0.1 mm on within 1e-3 (C's; its first
   increments' work is too small to judge it by).
E. A second pass's lower die on a path of its own (-pass2_lower_die_motion path -pass2_lower_die_path U,y,...: its
   strokes from where the pass's dies start, as the upper die's travel in the pass):
   - straight up by its stroke (-pass2_lower_die_path 2.5,2.5) is MIRROR's motion drawn by another kind: every
     history column within 1e-12 of its largest value (check_lower_path.py's A for the first pass; measured 0);
   - waiting, then rising (1.037,0,2.5,1.463: a kink no increment of the pass would end on by chance): at every field
     step of the pass its displacement is the path's at the upper die's travel there (read from the upper die's own
     displacement in the results) within 1e-12 mm, and a field step (every increment's: -output_every 1) lies on
     the kink within 1e-12 mm of travel: the pass's kinks are read when it starts, its travel known then; the run's
     energy balance at its end within C's 1e-3;
   - continued from a checkpoint taken in the second pass before its kink (U = 0.5 mm): every history column within
     1e-12 of the run never stopped (check_restart.py's bound: the pass's kinks are read again on the restart).
F. Dies that start moved back: the ring of options/flattening.opts in the full model, pressed 2 mm, sprung back,
   turned a quarter turn and pressed to 2.5 mm with the second pass's lower plate on a path (1.5,1.5,10,4: a kink
   while it presses): the pass's dies start 0.86 mm back from where they would touch the round tube, so the lower
   plate's strokes run ahead of the history's U by that much. The run's energy balance (each die's work from its
   reported force over its travel) within tests/check_squaring.py's 5e-3 at every increment of the second pass from
   its U = 0.1 mm on (this press with both plates mirroring reads 1.7e-3 there, the plates' node-by-node contact
   on the turned ring; measured 1.7e-3; the lower plate's work read at the history's U instead: 10 %).
Bad input: a path without its word, or the word without a path, a later pass after a lower die on a motion of its
own without its own: tests/check_bad_input.py.
"""
import numpy as np

from tfcheck import Checks, args, checkpoint_at, history_and_tools, out, run_all

tf, mpirun, src = args()
k = Checks("pass_lower_motion")
BASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-error_estimate", 0, "-progress", 0, "-model", "half", "-stroke", 1.5, "-pass2_stroke", 2.5]
KINK = 1.037  # (E: the second pass's lower die waits to this travel, then rises 1.463 mm by its end, 2.5 mm)
WAIT2 = ["-pass2_lower_die_motion", "path", "-pass2_lower_die_path", f"{KINK},0,2.5,1.463", "-output_stroke", 0,
         "-output_every", 1]
RUNS = {"lower_mirror.h5": BASE, "lower_fixed.h5": BASE + ["-pass2_lower_die_motion", "fixed"],
        "lower_own.h5": BASE[:-4] + ["-stroke", 2, "-lower_die_motion", "path", "-lower_die_path", "1,0,2,1",
                                     "-pass2_stroke", 2, "-pass2_lower_die_motion", "fixed"],
        "lower_own2_straight.h5": BASE + ["-pass2_lower_die_motion", "path", "-pass2_lower_die_path", "2.5,2.5"],
        "lower_own2_wait.h5": BASE + WAIT2,
        "lower_own2_back.h5": ["-options_file", f"{src}/options/flattening.opts", "-options_file",
                               f"{src}/options/preset-fast.opts", "-error_estimate", 0, "-progress", 0, "-model",
                               "full", "-stroke", 2, "-unload", "reverse", "-pass2_stroke", 2.5, "-pass2_turn", 90,
                               "-pass2_lower_die_motion", "path", "-pass2_lower_die_path", "1.5,1.5,10,4"]}
run_all(tf, mpirun, [opts + ["-output", out(name)] for name, opts in RUNS.items()], timeout=600)
mirror, fixed = history_and_tools(out("lower_mirror.h5")), history_and_tools(out("lower_fixed.h5"))


def end_of(h, stage, col):
    return h[col][h["stage"] == stage][-1]


# A. The same press up to the tube's rigid motion.
worst, where = 0.0, ""
for col in ("load", "x_max", "y_max", "c_over_t", "w_int", "w_friction"):
    for stage in range(4):
        gap = abs(end_of(fixed, stage, col) - end_of(mirror, stage, col)) / np.abs(mirror[col]).max()
        if gap >= worst:
            worst, where = gap, f"{col} at the end of stage {stage}"
k.check(worst <= 1e-5, f"A. FIXED's second pass presses as MIRROR's: within {worst:.1e} of the largest ({where}; 1e-5)")

# B. Where the dies went.
want = {("lower_fixed.h5", "pass2-lower-V-die"): (0.0, 0.0), ("lower_fixed.h5", "pass2-V-die"): (0.0, -5.0),
        ("lower_mirror.h5", "pass2-lower-V-die"): (0.0, 2.5), ("lower_mirror.h5", "pass2-V-die"): (0.0, -2.5),
        ("lower_fixed.h5", "lower-V-die"): (0.0, 1.5), ("lower_fixed.h5", "V-die"): (0.0, -1.5)}
for (name, tool), (x, y) in want.items():
    moved = {"lower_fixed.h5": fixed, "lower_mirror.h5": mirror}[name]["tools"][tool][-1][0]
    off = max(abs(moved[0] - x), abs(moved[1] - y))
    k.check(off <= 1e-12, f"B. {name[:-3]}: {tool} moved by ({moved[0]:.6g}, {moved[1]:.6g}) mm, ({x:g}, {y:g}) "
            f"within {off:.1e} (1e-12)")

# C. The run's energy balance over the upper die's travel.
err = abs(fixed["energy_error"][-1])
k.check(err <= 1e-3, f"C. FIXED's energy balance at its end: {err:.1e} (1e-3)")

# D. A first pass's lower die on a path of its own, a second pass's staying.
own = history_and_tools(out("lower_own.h5"))
first = own["tools"]["lower-V-die"][-1][0]
second = own["tools"]["pass2-lower-V-die"][-1][0]
err = np.abs(own["energy_error"][(own["stroke"] >= 0.1) | (own["stage"] > 0)]).max()  # (from U = 0.1 mm: its work)
k.check(max(abs(first[0]), abs(first[1] - 1.0), abs(second[0]), abs(second[1])) <= 1e-12 and err <= 1e-3,
        f"D. the first pass's lower die risen by ({first[0]:.6g}, {first[1]:.6g}) mm along its path, the second's by "
        f"({second[0]:.6g}, {second[1]:.6g}) (1e-12); the energy balance within {err:.1e} from U = 0.1 mm (1e-3)")

# E. A second pass's lower die on a path of its own.
straight = history_and_tools(out("lower_own2_straight.h5"))
cols = [c for c in mirror if c != "tools"]
same = all(straight[c].shape == mirror[c].shape for c in cols)
worst = max(np.abs(straight[c] - mirror[c]).max() / max(np.abs(mirror[c]).max(), 1e-300) for c in cols) if same else 1
k.check(same and worst <= 1e-12, f"E. the second pass's lower die on a path straight up by its stroke gives MIRROR's "
        f"history: {len(cols)} columns within {worst:.1e} of their largest values (1e-12)")
wait = history_and_tools(out("lower_own2_wait.h5"))
travel = -wait["tools"]["pass2-V-die"][:, 0, 1]  # (the upper die's travel in the pass: down by its stroke)
lower = wait["tools"]["pass2-lower-V-die"][:, 0, :]
want = np.interp(travel, [0, KINK, 2.5], [0, 0, 1.463])
off = max(np.abs(lower[:, 0]).max(), np.abs(lower[:, 1] - want).max()) if len(travel) > 10 else np.inf
on_kink = np.abs(travel - KINK).min()
err = abs(wait["energy_error"][-1])
k.check(off <= 1e-12 and on_kink <= 1e-12 and err <= 1e-3,
        f"E. waiting, then rising: the lower die's displacement at {len(travel)} field steps the path's at the upper "
        f"die's travel within {off:.1e} mm (1e-12), a field step on the kink within {on_kink:.1e} mm (1e-12), the "
        f"energy balance at the end {err:.1e} (1e-3)")
# (a checkpoint in the second pass before its kink: the restart must end an increment on it)
before = int(np.flatnonzero((wait["stage"] == 2) & (wait["stroke"] > 0.5))[0]) if (wait["stage"] == 2).any() else 1
checkpoint_at(tf, mpirun, 1, BASE + WAIT2 + ["-output", out("lower_own2_part.h5")], out("lower_own2_ck.h5"), before)
run_all(tf, mpirun, [BASE + WAIT2 + ["-output", out("lower_own2_part.h5"), "-restart", out("lower_own2_ck.h5")]])
part = history_and_tools(out("lower_own2_part.h5"))
same = all(part[c].shape == wait[c].shape for c in wait if c != "tools")
worst = max(np.abs(part[c] - wait[c]).max() / max(np.abs(wait[c]).max(), 1e-300) for c in wait if c != "tools") \
    if same else 1
k.check(same and worst <= 1e-12, f"E. continued from a checkpoint at increment {before}, in the second pass before "
        f"its kink: the history within {worst:.1e} of the run never stopped (1e-12)")

# F. Dies that start moved back.
back = history_and_tools(out("lower_own2_back.h5"))
rows = (back["stage"] == 2) & (back["stroke"] >= 0.1)
err = np.abs(back["energy_error"][rows]).max() if rows.any() else np.inf
k.check(err <= 5e-3, f"F. the second pass's dies started moved back, its lower plate on a path: the energy balance "
        f"within {err:.1e} over {rows.sum()} increments (5e-3)")
k.done()
