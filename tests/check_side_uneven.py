"""Side dies on a tube whose two sides differ (-side_die with a die off the axis), and side dies beside passes of other
kinds: a pass pressed by a force before one held by the rotation hold or one with side dies, a pass on its own path
after one with side dies.

The paper's tube (options/squaring.opts, the fast preset); RIGHT, LEFT and MIXED on the full model:
  RIGHT: side plates (-side_die flat) beside the V-dies, the upper die 0.5 mm off the axis (-die_offset 0.5, the
         rotation hold), pressed to U = 1.5 mm: the tube leans on one plate more than on the other;
  LEFT:  the same with -die_offset -0.5;
  MIXED: side plates pressing with 20 N/mm (-side_force 20) to U = 1.5 mm, then a second pass with its upper die off
         the axis (-pass2_die_offset 0.5, held by the rotation hold) and the plates by the stroke to U = 2 mm.
The runs go on past their own energy check (-max_energy_error 1) so that this test's checks judge them.

A. The energy balance from the history's columns: the punch load over the stroke (the full model carries all of it),
   the lower die's force over its rise (it mirrors the upper one), the side plates' reported force (`side_load`, the
   mean of the two, which travel alike) over their travel (`side_stroke`, two plates), and the loads at the nodes
   (w_ext - w_tool) against the internal, friction, kinetic and damped work, relative to the largest work put in so
   far, within 5e-3 from 0.1 mm past the dies' first load (tests/check_side_dies.py C's bound) on every row of RIGHT
   and of both presses of MIXED. One plate's force counted for both misses by 0.28 on RIGHT and 0.11 in MIXED's
   second press.
B. LEFT is RIGHT's mirror image: load, side load, C1, C2, internal work within 1e-6 of each column's largest
   (tests/check_hold.py C's bound), the upper die's sideways force opposite.
C. MIXED's first pass: the plates' force follows the force's ramp, 20 N/mm at its end within 1e-6 N/mm
   (tests/check_side_dies.py E's bound); its second pass held by the rotation hold (hold_moment set in its press).
D. Passes of other kinds beside side dies: FORCED, a first pass pressed by a force (-die_force 80, the quarter model)
   then a second with side plates (-pass2_side_die flat) by the stroke to U = 2 mm; PATH, a first pass with side
   plates to 1.5 mm then a second on a path of its own (-pass2_die_path 0,-3 over a lower die that stays, the half
   model) without them. FORCED's two presses' balance as A's (its second's side plates start from where the
   force left the die); PATH's second press's (the rule that let it run is its pass's: it has no side plates). A
   second pass's side plates whose travel starts from the first pass's -stroke rather than where its force left the
   die misses by 0.27 in FORCED's second press.
"""
import h5py
import numpy as np

from tfcheck import Checks, args, history_and_tools, out, run_all

tf, mpirun, src = args()
k = Checks("side_uneven")
BASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-error_estimate", 0, "-progress", 0, "-max_energy_error", 1, "-side_die", "flat"]
RUNS = {"uneven_right.h5": BASE + ["-stroke", 1.5, "-die_offset", 0.5],
        "uneven_left.h5": BASE + ["-stroke", 1.5, "-die_offset", -0.5],
        "uneven_mixed.h5": BASE + ["-side_force", 20, "-stroke", 1.5, "-pass2_stroke", 2, "-pass2_die_offset", 0.5],
        "uneven_forced.h5": BASE[:-2] + ["-die_force", 80, "-pass2_stroke", 2, "-pass2_side_die", "flat"],
        "uneven_path.h5": BASE + ["-stroke", 1.5, "-pass2_side_die", "none", "-pass2_lower_die_motion", "fixed",
                                  "-pass2_die_path", "0,-3"]}
run_all(tf, mpirun, [opts + ["-output", out(name)] for name, opts in RUNS.items()], timeout=600)
H = {name: history_and_tools(out(name)) for name in RUNS}
for name in RUNS:
    with h5py.File(out(name), "r") as f:
        H[name]["attrs"] = dict(f["/history"].attrs)


def balance(h, rows, start, share=1.0, lower=1.0, sides=2.0):
    """The energy balance's error at each of `rows` (one pass's press, in order), relative to the largest work put in
    so far, from the pass's start (its upper die at `start`, the state the row before it left; the first pass's row
    0). The model's share of the punch load, of the lower die's force (0: none modelled) and the side dies in it:
    the full model's 1, 1, 2 (the quarter's 0.5, 0, 0.5)."""
    r = np.concatenate(([rows[0] - 1], rows)) if rows[0] > 0 else rows
    stroke = h["stroke"][r].copy()
    stroke[0] = start
    dU, dS = np.diff(stroke), np.diff(h["side_stroke"][r])
    mid = {c: 0.5 * (h[c][r][1:] + h[c][r][:-1]) for c in ("load", "lower_fy", "side_load")}
    put = np.cumsum(share * mid["load"] * dU - lower * mid["lower_fy"] * dU + sides * mid["side_load"] * dS)
    rest = {c: h[c][r][1:] - h[c][r][0] for c in ("w_ext", "w_tool", "w_int", "w_friction", "w_kinetic", "w_damped")}
    w_in = put + rest["w_ext"] - rest["w_tool"]
    err = (w_in - rest["w_int"] - rest["w_friction"] - rest["w_kinetic"] - rest["w_damped"])
    return np.abs(err) / np.maximum(np.maximum.accumulate(np.abs(w_in)), 1e-300), stroke[1:]


# A. Energy, with the plates' mean force over their common travel.
for name, stage in (("uneven_right.h5", 0), ("uneven_mixed.h5", 0), ("uneven_mixed.h5", 2)):
    h = H[name]
    rows = np.where(h["stage"] == stage)[0]
    err, U = balance(h, rows, h["stroke"][0] if stage == 0 else H[name]["attrs"]["pass2_start_stroke"])
    touched = U[np.argmax(h["load"][rows] > 0)]  # (a later pass's dies reach the sprung-back tube on their way)
    worst = err[U - touched >= 0.1].max()
    spread = "" if stage else f", side loads {h['side_load'][rows].min():.3g} to {h['side_load'][rows].max():.3g}"
    k.check(worst <= 5e-3, f"A. {name[:-3]}, press {stage // 2 + 1}: energy balance within {worst:.1e} from 0.1 mm "
            f"past the dies' first load (5e-3){spread}")

# D. Side dies in a pass after one pressed by a force (the quarter model), and a pass on a path of its own after one
# with side dies (the half model, its lower die staying in the second pass): each press's balance.
for name, stage, shares in (("uneven_forced.h5", 0, (0.5, 0.0, 0.5)), ("uneven_forced.h5", 2, (0.5, 0.0, 0.5)),
                            ("uneven_path.h5", 2, (1.0, 0.0, 1.0))):
    # (the path over a lower die that stays: the half model's half of the load over the upper die's 2 U)
    h = H[name]
    rows = np.where(h["stage"] == stage)[0]
    err, U = balance(h, rows, h["stroke"][0] if stage == 0 else H[name]["attrs"]["pass2_start_stroke"], *shares)
    touched = U[np.argmax(h["load"][rows] > 0)]
    worst = err[U - touched >= 0.1].max()
    k.check(worst <= 5e-3, f"D. {name[:-3]}, press {stage // 2 + 1}: energy balance within {worst:.1e} from 0.1 mm "
            f"past the dies' first load (5e-3)")

# B. The mirror image.
right, left = H["uneven_right.h5"], H["uneven_left.h5"]
same = len(right["stroke"]) == len(left["stroke"])
worst = max(np.abs(right[c] - left[c]).max() / np.abs(right[c]).max()
            for c in ("load", "side_load", "x_max", "y_max", "w_int")) if same else 1.0
sideways = np.abs(right["tool_fx"] + left["tool_fx"]).max() / np.abs(right["tool_fx"]).max() if same else 1.0
k.check(worst <= 1e-6 and sideways <= 1e-6 and np.abs(right["tool_fx"]).max() > 1,
        f"B. LEFT mirrors RIGHT: load, side load, C1, C2, internal work within {worst:.1e}, the sideways force "
        f"opposite within {sideways:.1e} (1e-6)")

# C. The forced pass, then the held one.
mixed = H["uneven_mixed.h5"]
first, second = mixed["stage"] == 0, mixed["stage"] == 2
miss = abs(mixed["side_load"][first][-1] - 20)
k.check(miss <= 1e-6 and np.abs(mixed["hold_moment"][second]).max() > 0 and
        np.abs(mixed["hold_moment"][first]).max() == 0,
        f"C. MIXED: the plates at 20 N/mm at the first pass's end within {miss:.1e} (1e-6); the second pass held "
        f"(largest couple {np.abs(mixed['hold_moment'][second]).max():.3g} N mm/mm), the first not")
k.done()
