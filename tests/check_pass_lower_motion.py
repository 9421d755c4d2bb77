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
Bad input: a word of its own kind (path) or the option without its pass's stroke, a later pass after a lower die
on a motion of its own without its own: tests/check_bad_input.py.
"""
import numpy as np

from tfcheck import Checks, args, history_and_tools, out, run_all

tf, mpirun, src = args()
k = Checks("pass_lower_motion")
BASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-error_estimate", 0, "-progress", 0, "-model", "half", "-stroke", 1.5, "-pass2_stroke", 2.5]
RUNS = {"lower_mirror.h5": BASE, "lower_fixed.h5": BASE + ["-pass2_lower_die_motion", "fixed"],
        "lower_own.h5": BASE[:-4] + ["-stroke", 2, "-lower_die_motion", "path", "-lower_die_path", "1,0,2,1",
                                     "-pass2_stroke", 2, "-pass2_lower_die_motion", "fixed"]}
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
k.done()
