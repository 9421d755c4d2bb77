"""Three passes (-pass3_stroke, -pass3_turn): the scene's passes are a list, each after the springback before it.

The paper's tube (options/squaring.opts, the fast preset, the quarter model), pressed 1.5 mm by the V-dies, sprung
back (the paper's unloading), turned a quarter turn (-pass2_turn 90) and pressed again to U = 1.5 mm, sprung back,
then pressed a third time to U = 1.5 mm (pass k presses over stage 2k, releases over 2k + 1):
  SAME:   -pass3_turn 0: the third pass is the second's press again (the same dies, the same axis, the same
          closure);
  TURNED: -pass3_turn 90: the tube turned on by another quarter turn (180 degrees from the first press: its
          axis, which the quarter model draws unturned).

A. Re-pressing to the same closure (SAME): every springback is elastic (no Gauss point yields back: the release
   columns), so the third press retraces the second pass's springback. Its end load is the second pass's within
   1 % of it, and C1 and C2 at its end the second pass's within 5 % of that springback's change of each. The
   bounds: what the re-press cannot recover exactly is friction's path (the slips of the release and the re-press
   differ): friction's share of the third press's work (w_friction, measured 4.4 %) bounds the load's change, the
   1 % is a quarter of it; the shape returns as far as the elastic retrace does, the 5 % a twentieth of what the
   springback moved (measured: load 2e-5, C1 and C2 3e-5 mm of springbacks of 0.08 and 0.03 mm). A third pass
   pressed from the first pass's stage (its stroke over lambda 2 to 3, already past) jumps to its closure in one
   increment and ends elsewhere.
B. Energy in each press of both runs, from the history's columns: the model's share of the punch load (half, in
   the quarter model) integrated over the stroke (trapezoids on the rows) equals the internal work's and the
   friction's growth over the stage within 5e-3 of that work (tests/check_hold.py D's bound for the energy
   balance; measured 6e-5): a load read in another pass's frame, or a stroke from another pass's zero, moves it
   by O(1).
C. TURNED on 1 and 2 ranks: load, C1, C2, C/t and internal work along each press's stroke (on a grid) and at each
   stage's end within 3e-5 of each column's largest value (tests/check_turn.py's bound for a second press from a
   pressed tube: the ranks sum the same contributions in another order).
D. What the third turn does: TURNED's third die moves along the tube's -y by its stroke (its outline in the
   results displaced by (0, -1.5) mm at the end: two quarter turns are the first press's axis), SAME's along -x
   (the second's), within 1e-9 mm (a die's displacement is its stroke along its motion, exact in floating point).
E. A checkpoint half way through the third press, continued with -restart (TURNED with side plates in the third
   pass, -pass3_side_die flat, whose travel goes on from the passes before): the history of the run never stopped
   within 1e-12 of each column's largest value (tests/check_restart.py's bound); a restart that lost where the
   third pass's side plates started, or its dies' start, differs at O(1).
F. Bad input: -pass4_stroke without -pass3_stroke, and -pass3_turn without -pass3_stroke, are refused in one line
   naming the option, a non-zero exit, no results file.
"""
import os

import h5py
import numpy as np

from tfcheck import Checks, args, checkpoint_at, history_and_tools, out, run, run_all

tf, mpirun, src = args()
k = Checks("passes")
U = 1.5
BASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-error_estimate", 0, "-progress", 0, "-stroke", U, "-pass2_stroke", U, "-pass2_turn", 90, "-pass3_stroke", U]
RUNS = {"passes_same.h5": BASE, "passes_turned.h5": BASE + ["-pass3_turn", 90],
        "passes_side.h5": BASE + ["-pass3_turn", 90, "-pass3_side_die", "flat"]}
run_all(tf, mpirun, [opts + ["-output", out(name)] for name, opts in RUNS.items()], timeout=600)
same, turned = history_and_tools(out("passes_same.h5")), history_and_tools(out("passes_turned.h5"))


def end_of(h, stage, col):
    return h[col][h["stage"] == stage][-1]


# A. The third pass re-presses to the second's closure.
k.check(sorted(set(same["stage"].astype(int))) == [0, 1, 2, 3, 4, 5] and same["release_yielded"].max() == 0,
        "three passes: stages 0-5 in the history, every springback elastic (no Gauss point yields back)")
load2, load3 = end_of(same, 2, "load"), end_of(same, 4, "load")
k.check(abs(load3 - load2) <= 0.01 * load2,
        f"A. the third pass's end load {load3:.6g} N/mm is the second's {load2:.6g} within "
        f"{abs(load3 - load2) / load2:.1e} of it (0.01)")
for col in ("x_max", "y_max"):
    back = abs(end_of(same, 3, col) - end_of(same, 2, col))
    gap = abs(end_of(same, 4, col) - end_of(same, 2, col))
    k.check(gap <= 0.05 * back, f"A. {col} at the third pass's end is the second's within {gap:.2e} mm, "
            f"{gap / back:.1e} of the second springback's {back:.3g} mm (0.05)")

# B. Energy in each press.
for name, h in (("SAME", same), ("TURNED", turned)):
    for stage in (0, 2, 4):
        rows = np.where(h["stage"] == stage)[0]
        before = rows[0] - 1 if rows[0] > 0 else None
        stroke = np.concatenate(([0.0] if before is None else [h["stroke"][rows[0]]], h["stroke"][rows]))
        load = np.concatenate(([0.0], h["load"][rows]))
        work = 0.5 * np.sum(0.5 * (load[1:] + load[:-1]) * np.diff(stroke))  # (the quarter's half of the load)
        grown = sum(h[c][rows[-1]] - (0.0 if before is None else h[c][before]) for c in ("w_int", "w_friction"))
        k.check(abs(grown - work) <= 5e-3 * work,
                f"B. {name}, press {stage // 2 + 1}: internal and friction work grow by {grown:.6g}, the punch "
                f"load's work is {work:.6g}: within {abs(grown - work) / work:.1e} (5e-3)")

# C. 1 vs 2 ranks.
run(tf, mpirun, 2, RUNS["passes_turned.h5"] + ["-output", out("passes_turned_np2.h5")], timeout=600)
two = history_and_tools(out("passes_turned_np2.h5"))
worst = 0.0
for col in ("load", "x_max", "y_max", "c_over_t", "w_int"):
    top = max(np.abs(turned[col]).max(), 1e-300)
    for stage in range(6):
        a, b = turned["stage"] == stage, two["stage"] == stage
        grid = np.linspace(turned["stroke"][a].min(), turned["stroke"][a].max(), 15)
        if stage % 2 == 0:
            rel = np.abs(np.interp(grid, turned["stroke"][a], turned[col][a]) -
                         np.interp(grid, two["stroke"][b], two[col][b])).max() / top
            worst = max(worst, rel)
        worst = max(worst, abs(end_of(turned, stage, col) - end_of(two, stage, col)) / top)
k.check(worst <= 3e-5, f"C. TURNED on 2 ranks: load, C1, C2, C/t, internal work along each press and at each stage's "
        f"end within {worst:.1e} of the largest value (3e-5)")

# D. The third turn's axis.
for name, h, want in (("TURNED", turned, (0.0, -U)), ("SAME", same, (-U, 0.0))):
    moved = h["tools"]["pass3-V-die"][-1]
    off = np.abs(moved - np.array(want)).max()
    k.check(off <= 1e-9, f"D. {name}: the third pass's die moved by ({moved[0][0]:.6g}, {moved[0][1]:.6g}) mm, "
            f"({want[0]:g}, {want[1]:g}) within {off:.1e} mm (1e-9)")

# E. A checkpoint inside the third press, continued.
whole = history_and_tools(out("passes_side.h5"))
ck = out("passes_side_ck.h5")
every = int(np.sum(whole["stage"] <= 3)) + int(np.sum(whole["stage"] == 4)) // 2
checkpoint_at(tf, mpirun, 1, RUNS["passes_side.h5"] + ["-output", out("passes_part.h5")], ck, every, timeout=600)
cont = run(tf, mpirun, 1, RUNS["passes_side.h5"] + ["-output", out("passes_part.h5"), "-restart", ck], check=False,
           timeout=600)
with h5py.File(ck, "r") as c:
    lam = c["/run/lambda"][0]
part = history_and_tools(out("passes_part.h5"))
cols = [c for c in whole if c != "tools"]
same_shape = all(part[c].shape == whole[c].shape for c in cols)
worst = max(np.abs(part[c] - whole[c]).max() / max(np.abs(whole[c]).max(), 1e-300) for c in cols) if same_shape else 1
k.check(cont.returncode == 0 and same_shape and worst <= 1e-12 and 4 < lam < 5 and whole["side_load"][whole["stage"] == 4].max() > 0,
        f"E. side plates in the third pass, continued from a checkpoint inside its press (lambda {lam:.3f}, exit "
        f"{cont.returncode}): the history within {worst:.1e} (1e-12)")

# F. A pass needs the one before it.
for extra, option in ((["-pass4_stroke", 1], "-pass4_stroke"), (["-pass3_turn", 90], "-pass3_turn")):
    f = out("passes_bad.h5")
    if os.path.exists(f):
        os.remove(f)
    p = run(tf, mpirun, 1, BASE[:-2] + extra + ["-output", f], check=False, timeout=60)
    lines = [l for l in (p.stdout + p.stderr).splitlines() if "error" in l.lower()]
    k.check(p.returncode != 0 and len(lines) == 1 and option in lines[0] and not os.path.exists(f),
            f"F. {' '.join(map(str, extra))} without -pass3_stroke: exit {p.returncode}, refused in one line naming "
            f"{option}: {lines[0] if lines else '(none)'}")
k.done()
