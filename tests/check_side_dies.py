"""Side dies (-side_die: more tools than the two of a press).

A. Four plates: the ring of options/flattening.opts (Rm/t = 20, elastic-perfectly plastic, frictionless) crushed by
   the top plate and a side plate (`-side_die flat`, the quarter model: four plates around the ring) to U = 3 mm.
   - The press is symmetric about the diagonal y = x: the side plate's force equals the top plate's and C1 = C2 at
     every increment, within 1e-9 of the load and 1e-9 mm (the quarter mesh is symmetric about the diagonal, so
     only round-off separates them; measured 2.6e-11). A side die drawn or moved wrongly breaks it at
     O(1).
   - Collapse: rigid-plastic ring theory with loads at 0, 90, 180 and 270 degrees has hinges at the loads and
     half way between them; a 45-degree segment turns about the crossing of the normals to its ends' motions,
     ((sqrt 2 - 1) Rm, Rm) for the top load, so P = 4 Mp / ((sqrt 2 - 1) Rm) per plate (2.41 times the two
     plates' 4 Mp / Rm). The plateau's onset by tests/check_flattening.py's two-tangent construction within its
     10 % (measured 0.92 of it; the two plates' 0.95).
   - The energy balance with the side plates' work from their reported force (`side_load`) within 1 % of the
     external work at every increment, as tests/check_flattening.py's (measured 6.5e-3 at its largest; without
     the side work the run stops at its own energy check, -99.7 %).
B. The half and the full model (the right plate whole, its mirror on the left in the full model) against each
   other within 1e-7 of the largest value up to U = 1.5 mm and tests/check_squaring.py's 3e-5 beyond (the same
   press summed in another order; measured 8.8e-9 and 1.2e-8 on two machines, and 1.3e-7). The early bound is
   this press's own, derived as check_squaring.py derives its 3e-5: ten times what a perturbation of 1.3e-13 in
   E moves the half model's load, side load, C1, C2 up to 1.5 mm (9.8e-9: -material_e 75000.00000000975 and
   74999.99999999025 against 75000, `-options_file options/flattening.opts -side_die flat -model half -stroke
   2`). Flat plates spread their contact node by node from the first increment, so the ring's path amplifies
   round-off a thousand times more than the V-dies' before their collapse (whose 1.3e-8 this check borrowed
   before: too close to what another CPU's round-off gives here). Against the quarter at the end of the press within 1e-3 (measured 6.9e-5:
   the quarter takes the simultaneous first touches of the two plates in another order, one increment fewer,
   and the elastic-plastic path follows its steps). Their side plates' outlines move by (-U, 0) and (U, 0). The
   half model on 1 vs 2 ranks within the same bounds as half vs full.
C. The paper's V-dies with side plates (options/squaring.opts, fast preset, U = 3 mm): the plates stop the tube's
   widening: touching the round tube from the start, they hold its half-width at their x = Ro - U within 1e-4 mm
   at every increment (tests/check_squaring.py's penetration bound for steps accepted with a residual; measured 6.7e-6 mm in the
   increment a node first touches the plate), where the V-dies alone widen it to 18.8 mm. Over a floor that rises
   with the stroke (`-lower_die flat`, the half model) the side plates take some of the vertical force by
   friction, so the floor carries less than the die: the energy balance, each die's work from its own force over
   its own travel, within 5e-3 from U = 0.5 mm (as A; tests/check_models.py C reads it from there too: the first
   steps' trapezoidal work is a large part of a small total, 6.4e-3 at U = 0.03 mm here; measured 1.2e-4; the
   floor's work counted as the die's reads 2 %).
D. Side dies in a second pass (-pass2_side_die): the paper's tube pressed 2 mm by the V-dies, then 2 mm more with
   a V-die and a side plate, drawn two ways (fast preset, the quarter model):
   - turned: `-pass2_turn 90 -pass2_side_die flat` (the press's upper die, the V, drawn at the tube's right by the
     reflection about y = x; its side plate at the top);
   - not turned: `-pass2_die_profile options/dies/plate.profile -pass2_side_die options/dies/v90_r3.profile` (the
     plate the upper die, the V from its profile file the side die).
   The same tools on the same tube: the turned run's load, C1 and C2 are the other's side_load, C2 and C1, and
   their internal work the same, in every row of the second pass within 1e-10 of the largest value (both sum the
   same contacts in the same node order, only the tools are listed in another order; measured 0). A side force
   read in the tube's frame instead of the turned press's gives the other die's O(1); the turned run's energy
   balance, from its reported load and side load, within 5e-3 (tests/check_squaring.py's (a); the side force in
   the tube's frame stops it at -25 %). The turned run on 1 vs 2 ranks within 1.3e-8 of the largest value in the
   first pass and 3e-5 in the second (tests/check_squaring.py's bounds: the first pass ends at U = 2 mm, before
   the 2.6 mm where its round-off starts to grow, and its springback is elastic).
E. Force-controlled side dies (-side_force F: each side plate presses with a force rising from 0 to F over the
   press, its travel an unknown of each increment), beside the V-dies (the paper's tube, fast preset, U = 3 mm):
   - with the paper's exact linear steps (-equilibrium_tol 0), F = 20 N/mm: each side plate's force at the end
     of every loading increment is lambda F within 1e-6 N/mm (the bound for a pad in equilibrium with its force;
     measured 2e-11), and the plate rides the tube: the half-width C1 is at the plate, Ro minus its travel,
     within 1e-4 mm at every increment (C's bound; measured 4e-15);
   - the energy balance with the plates' work from their reported force and their own travel (`side_stroke`)
     within 5e-3 at every increment (as C; the default equilibrium steps; the plates' work counted with the
     die's stroke instead breaks it);
   - the force's share in each model (the quarter carries half of one plate, the half model one, the full model
     two): the half model against the quarter within tests/check_squaring.py's bounds (1.3e-8 of the largest
     value to U = 2.6 mm, 3e-5 beyond), and the half model on 1 vs 2 ranks within the same; the full model
     against the quarter at the end within 1e-3 (B's bound: contact events grouped in another order);
   - a checkpoint inside the press, continued: the history within 1e-12 (tests/check_restart.py's bound);
   - a force the tube cannot carry sideways (500 N/mm: the four-plate collapse of A is some 20 N/mm a plate):
     the run stops where the plates' force stops growing, exit 1, one line naming the side plate, the results up
     to there written.
F. A later pass's force-controlled side dies (-pass2_side_die flat -pass2_side_force 20): after a first pass that
   stays elastic (U = 0.02 mm, no side dies; its springback leaves the tube round to a few 1e-6 mm), the second
   pass to U = 1.5 mm presses as the first pass with -side_die flat -side_force 20 does (one pass to 1.5 mm, both
   sprung back by -unload reverse): at the end of the press the load, C1, C2 and the plates' force (and C1, C2
   after its springback) within 1e-3 of their values, and the plates' travel in the pass (side_stroke less the 0.02
   mm the first pass put before it) within 1e-3 of the one pass's, 8e-4 mm, the size of the C1 it moves with
   (tests/check_hold.py G's bound: the two increment sequences take contact events in another order; measured
   9e-5, the travel 5e-4); the pass ends at its -pass2_stroke (the plates' own travel not counted in the upper
   die's). A forced first pass followed by a second pass by the
   stroke, its plates taken over (-pass2_stroke 2.5): the energy balance of both passes within C's 5e-3, the
   plates' work counted from their force over their own travel in the first pass and over the stroke's in the
   second; their travel (side_stroke) goes on from their own at the first pass's end, by the upper die's travel
   in the pass from where the run says it starts (within 1e-9 mm: the same numbers added).
"""
import math
import re
from concurrent.futures import ThreadPoolExecutor

import h5py
import numpy as np

from tfcheck import Checks, args, checkpoint_at, history_and_tools, out, run, run_all

tf, mpirun, src = args()
k = Checks("side_dies")
RING = ["-options_file", f"{src}/options/flattening.opts", "-side_die", "flat", "-progress", 0, "-error_estimate", 0]


SQ = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
      "-progress", 0, "-error_estimate", 0, "-stroke", 3, "-unload", "none"]
TWO = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
       "-progress", 0, "-error_estimate", 0, "-stroke", 2, "-pass2_stroke", 2]
TURNED = TWO + ["-pass2_turn", 90, "-pass2_side_die", "flat"]
# The single-rank runs, two at a time before the checks read them.
RUNS = {"side_four.h5": RING + ["-stroke", 3], "side_half.h5": RING + ["-stroke", 2, "-model", "half"],
        "side_full.h5": RING + ["-stroke", 2, "-model", "full"], "side_quarter.h5": RING + ["-stroke", 2],
        "side_v.h5": SQ + ["-side_die", "flat"], "side_v_alone.h5": SQ,
        "side_v_floor.h5": SQ + ["-side_die", "flat", "-lower_die", "flat"], "side_pass2_turned.h5": TURNED,
        "side_pass2_plain.h5": TWO + ["-pass2_die_profile", f"{src}/options/dies/plate.profile", "-pass2_side_die",
                                      f"{src}/options/dies/v90_r3.profile"],
        "side_force_exact.h5": SQ + ["-side_die", "flat", "-side_force", 20, "-equilibrium_tol", 0],
        "side_force.h5": SQ + ["-side_die", "flat", "-side_force", 20],
        "side_force_half.h5": SQ + ["-side_die", "flat", "-side_force", 20, "-model", "half"],
        "side_force_full.h5": SQ + ["-side_die", "flat", "-side_force", 20, "-model", "full"],
        "side_force_one.h5": SQ[:-4] + ["-stroke", 1.5, "-unload", "reverse", "-side_die", "flat", "-side_force", 20],
        "side_force_later.h5": SQ[:-4] + ["-stroke", 0.02, "-output_stroke", 0, "-unload", "reverse", "-pass2_stroke",
                                          1.5, "-pass2_side_die", "flat", "-pass2_side_force", 20],
        "side_force_then.h5": SQ[:-4] + ["-stroke", 1.5, "-unload", "reverse", "-side_die", "flat", "-side_force", 20,
                                         "-pass2_stroke", 2.5]}
procs = dict(zip(RUNS, run_all(tf, mpirun, [opts + ["-output", out(name)] for name, opts in RUNS.items()],
                               timeout=600)))


def stop_and_continue(name, every):
    """RUNS[name] run to increment `every`, its checkpoint written there, then continued from it."""
    ck = out(f"{name}_ck.h5")
    opts = RUNS[f"{name}.h5"] + ["-output", out(f"{name}_part.h5")]
    checkpoint_at(tf, mpirun, 1, opts, ck, every, timeout=600)
    run(tf, mpirun, 1, opts + ["-restart", ck], timeout=600)


def limit_run():
    """A side force the tube cannot carry (E's last check)."""
    return run(tf, mpirun, 1, SQ + ["-side_die", "flat", "-side_force", 500, "-output", out("side_force_limit.h5")],
               check=False, timeout=600)


# The single-rank runs that read the pool's results, two at a time before any 2-rank run: D's and E's checkpoints
# (inside the turned second pass; inside the force-controlled press, before U = 1.5 mm), each continued, and E's
# side force the tube cannot carry.
turned, held = history_and_tools(out("side_pass2_turned.h5")), history_and_tools(out("side_force.h5"))
with ThreadPoolExecutor(max_workers=2) as pool:
    pairs = [pool.submit(stop_and_continue, "side_pass2_turned",
                         int(np.sum(turned["stage"] <= 1)) + int(np.sum(turned["stage"] == 2)) // 2),
             pool.submit(stop_and_continue, "side_force", int(np.sum(held["stroke"] < 1.5)))]
    limit = pool.submit(limit_run)
    [f.result() for f in pairs]
    limit = limit.result()


def continued(name, whole, inside, label):
    """RUNS[name] continued from its checkpoint (stop_and_continue), which must lie inside the load factors `inside`
    (a checkpoint at the run's end would restart nothing), against `whole`."""
    with h5py.File(out(f"{name}_ck.h5"), "r") as c:
        lam = c["/run/lambda"][0]
    part = history_and_tools(out(f"{name}_part.h5"))
    cols = [c for c in whole if c != "tools"]
    same = all(part[c].shape == whole[c].shape for c in cols)
    worst = max(np.abs(part[c] - whole[c]).max() / max(np.abs(whole[c]).max(), 1e-300) for c in cols) if same else 1
    k.check(same and worst <= 1e-12 and inside[0] < lam < inside[1],
            f"{label} (lambda {lam:.3f}): the history within {worst:.1e} (1e-12)")


def agreement(a, b, cols, early):
    """The largest difference of b's columns from a's, relative to each column's largest value in a: over the
    rows where `early` (a mask of a's rows) holds, and over all; 1 and 1 where the two have different rows."""
    if a["stroke"].shape != b["stroke"].shape:
        return 1.0, 1.0
    rel = [np.abs(b[c] - a[c]) / np.abs(a[c]).max() for c in cols]
    return max(r[early].max() for r in rel), max(r.max() for r in rel)


def press(name, n=1):
    """The history and tools of one of RUNS, run already (or on n ranks now)."""
    if n > 1:
        run(tf, mpirun, n, RUNS[name.replace(f"_np{n}", "")] + ["-output", out(name)], timeout=600)
    return history_and_tools(out(name))


# A. Four plates.
four = press("side_four.h5")
U, P, S = four["stroke"], four["load"], four["side_load"]
diag = max(np.abs(P - S).max() / P.max(), np.abs(four["x_max"] - four["y_max"]).max())
k.check(diag < 1e-9, f"four plates: the side plate's force equals the top one's, C1 = C2, at every increment within "
        f"{diag:.1e} (1e-9)")
E, sy, t, Rm = 75000.0, 165.3, 1.0, 20.0
P4 = 4 * (2 / math.sqrt(3)) * sy * t * t / 4 / ((math.sqrt(2) - 1) * Rm)
late = U >= 0.75 * U[-1]
slope, icpt = np.polyfit(U[late], P[late], 1)
k_el = P[1] / U[1]
onset = k_el * icpt / (k_el - slope)
k.check(abs(onset / P4 - 1) < 0.10, f"four plates: the plateau's onset {onset:.3f} N/mm against 4 Mp / ((sqrt 2 - 1) "
        f"Rm) = {P4:.3f} ({onset / P4 - 1:+.1%}; 10 %)")
e = np.abs(four["energy_error"][1:]).max()
k.check(e < 0.01, f"four plates: the energy balance with the side plates' work within {e:.1e} (1 %)")

# B. The half and the full model.
RING_EARLY = 1e-7  # ten times the ring's response to a 1.3e-13 perturbation of E up to U = 1.5 mm (docstring, B)
half = press("side_half.h5")
full = press("side_full.h5")
quarter = press("side_quarter.h5")
cols = ("load", "side_load", "x_max", "y_max")
same = all(half[c].shape == full[c].shape for c in cols)
rel = [np.abs(half[c] - full[c]) / np.abs(half[c]).max() for c in cols] if same else [np.ones(1)]
early = max(r[half["stroke"] <= 1.5].max() for r in rel) if same else 1
late = max(r.max() for r in rel)
k.check(early < RING_EARLY and late < 3e-5, f"side plates, the half model against the full: every row within "
        f"{early:.1e} up to U = 1.5 mm ({RING_EARLY:.0e}), {late:.1e} to the end (3e-5)")
end = max(abs(quarter[c][-1] / full[c][-1] - 1) for c in cols)
k.check(end < 1e-3, f"side plates, the quarter against the full model at the end of the press: within {end:.1e} (1e-3)")
moved = {n: full["tools"][n][-1][0] for n in ("side-plate", "left-side-plate")}
k.check(np.abs(moved["side-plate"] - [-2, 0]).max() < 1e-12 and np.abs(moved["left-side-plate"] - [2, 0]).max() < 1e-12,
        f"the full model's side plates move by ({moved['side-plate'][0]:g}, {moved['side-plate'][1]:g}) and "
        f"({moved['left-side-plate'][0]:g}, {moved['left-side-plate'][1]:g}) mm")

two = press("side_half_np2.h5", 2)
rel = [np.abs(half[c] - two[c]) / np.abs(half[c]).max() for c in cols] if two["load"].shape == half["load"].shape \
    else [np.ones(1)]
early, late = max(r[half["stroke"] <= 1.5].max() if len(r) > 1 else 1 for r in rel), max(r.max() for r in rel)
k.check(early < RING_EARLY and late < 3e-5, f"side plates, the half model on 1 vs 2 ranks: every row within "
        f"{early:.1e} up to U = 1.5 mm ({RING_EARLY:.0e}), {late:.1e} to the end (3e-5)")

# C. V-dies and side plates.
walled, alone = history_and_tools(out("side_v.h5")), history_and_tools(out("side_v_alone.h5"))
RO = 17.5
over = np.abs(walled["x_max"] - (RO - walled["stroke"])).max()
k.check(over < 1e-4 and alone["x_max"][-1] > RO + 1,
        f"V-dies with side plates: the plates hold the tube's half-width at their Ro - U at every increment within "
        f"{over:.1e} mm (1e-4); without them it grows to {alone['x_max'][-1]:.3f} mm")

floor = press("side_v_floor.h5")
e = np.abs(floor["energy_error"][floor["stroke"] >= 0.5]).max()
k.check(e < 5e-3, f"a V-die over a floor rising with it, side plates: energy balance with each die's own force over "
        f"its travel within {e:.1e} from U = 0.5 mm (5e-3)")

# D. Side dies in a second pass, drawn turned and not.
turned, plain = press("side_pass2_turned.h5"), press("side_pass2_plain.h5")
continued("side_pass2_turned", turned, (2, 3), "side dies in the turned second pass (more tools than the first pass's), continued from a "
          "checkpoint inside it")
s2 = turned["stage"] == 2
same = len(turned["stage"]) == len(plain["stage"]) and (turned["stage"] == plain["stage"]).all()
worst = 1.0
if same:
    worst = max(np.abs(turned[a][s2] - plain[b][s2]).max() / np.abs(turned[a][s2]).max()
                for a, b in (("load", "side_load"), ("side_load", "load"), ("x_max", "y_max"), ("y_max", "x_max"),
                             ("w_int", "w_int")))
k.check(same and worst < 1e-10 and turned["side_load"][s2].max() > 10,
        f"side dies in the second pass, turned and drawn as the other die: load and side load swapped, C1 and C2 "
        f"swapped, internal work, every row of the second pass within {worst:.1e} (1e-10)")
e = np.abs(turned["energy_error"][1:]).max()
k.check(e < 5e-3, f"side dies in the turned second pass: energy balance from the reported load and side load within "
        f"{e:.1e} (5e-3)")
two = press("side_pass2_turned_np2.h5", 2)
early, late = agreement(turned, two, ("load", "side_load", "x_max", "y_max"), turned["stage"] <= 1)
k.check(early < 1.3e-8 and late < 3e-5, f"side dies in the turned second pass, 1 vs 2 ranks: the first pass within "
        f"{early:.1e} (1.3e-8), both within {late:.1e} (3e-5)")

# E. Force-controlled side dies.
exact = press("side_force_exact.h5")
on = exact["stroke"] > 0
miss = np.abs(exact["side_load"][on] - 20 * np.minimum(exact["stroke"][on] / 3, 1)).max()
ride = np.abs(exact["x_max"] - (RO - exact["side_stroke"])).max()
k.check(miss < 1e-6 and ride < 1e-4 and exact["side_stroke"][-1] < 0,
        f"force-controlled side plates (20 N/mm): their force lambda F at every increment within {miss:.1e} N/mm "
        f"(1e-6); they ride the tube, C1 at Ro less their travel within {ride:.1e} mm (1e-4), pushed back "
        f"{-exact['side_stroke'][-1]:.3f} mm")
held = press("side_force.h5")
e = np.abs(held["energy_error"][1:]).max()
k.check(e < 5e-3, f"force-controlled side plates: energy balance with their work over their own travel within "
        f"{e:.1e} (5e-3)")
PAD = ("load", "side_load", "side_stroke", "x_max")
half = press("side_force_half.h5")
worst_early, worst = agreement(held, half, PAD, held["stroke"] <= 2.6)
k.check(worst_early < 1.3e-8 and worst < 3e-5, f"force-controlled side plates, the half model against the quarter: "
        f"within {worst_early:.1e} to U = 2.6 mm (1.3e-8), {worst:.1e} to the end (3e-5)")
two = press("side_force_half_np2.h5", 2)
worst_early, worst = agreement(half, two, PAD, half["stroke"] <= 2.6)
k.check(worst_early < 1.3e-8 and worst < 3e-5, f"force-controlled side plates, the half model on 1 vs 2 ranks: "
        f"within {worst_early:.1e} to U = 2.6 mm (1.3e-8), {worst:.1e} to the end (3e-5)")
full = press("side_force_full.h5")
end = max(abs(full[c][-1] / held[c][-1] - 1) for c in ("load", "side_load", "side_stroke", "x_max"))
k.check(end < 1e-3, f"force-controlled side plates, the full model (two plates sharing one travel) against the "
        f"quarter at the end of the press: within {end:.1e} (1e-3, as B)")
continued("side_force", held, (0, 1), "force-controlled side plates, continued from a checkpoint inside the press")
p = limit
lines = [line for line in (p.stdout + p.stderr).splitlines() if "error" in line]
with h5py.File(out("side_force_limit.h5"), "r") as h:
    rows, stopped = len(h["/history/stroke"]), h["/history"].attrs["stopped"]
k.check(p.returncode == 1 and len(lines) == 1 and "force-controlled side-plate" in lines[0] and rows > 10 and stopped,
        f"a side force the tube cannot carry: exit {p.returncode}, one line ({lines[0][:70] if lines else ''}...), "
        f"{rows} rows written, flagged stopped")

# F. A later pass's force-controlled side dies.
one, later = press("side_force_one.h5"), press("side_force_later.h5")
worst, where = 0.0, ""
for a_stage, b_stage in ((0, 2), (1, 3)):
    i, j = np.where(one["stage"] == a_stage)[0][-1], np.where(later["stage"] == b_stage)[0][-1]
    cols = ("load", "x_max", "y_max", "side_load") if a_stage == 0 else ("x_max", "y_max")
    for c in cols:
        rel = abs(later[c][j] - one[c][i]) / abs(one[c][i])
        worst, where = max((worst, where), (rel, f"{c}, stage {b_stage}"))
i, j = np.where(one["stage"] == 0)[0][-1], np.where(later["stage"] == 2)[0][-1]
travel = abs(later["side_stroke"][j] - 0.02 - one["side_stroke"][i]) / abs(one["side_stroke"][i])
k.check(max(worst, travel) <= 1e-3 and abs(later["stroke"][j] - 1.5) <= 1e-9,
        f"F. -pass2_side_force 20 after an elastic first pass presses as -side_force 20: "
        f"the ends within {worst:.1e} ({where}), the plates' travel {later['side_stroke'][j] - 0.02:.4f} against "
        f"{one['side_stroke'][i]:.4f} mm ({travel:.1e}; 1e-3); the pass ends at U = {later['stroke'][j]} "
        f"(1.5 within 1e-9)")
then = press("side_force_then.h5")
e = np.abs(then["energy_error"][1:]).max()
k.check(e < 5e-3 and (then["stage"] == 2).sum() > 10, f"F. force-controlled plates in the first pass, by the stroke "
        f"in the second: energy balance of both passes within {e:.1e} (5e-3)")
said = re.search(r"the upper die from U = ([0-9.e+-]+) to", procs["side_force_then.h5"].stdout)
j0, end = np.where(then["stage"] == 2)[0][0], np.where(then["stage"] == 1)[0][-1]
jump = then["side_stroke"][j0] - then["side_stroke"][end]
moved = then["stroke"][j0] - float(said.group(1)) if said else float("nan")
k.check(abs(jump - moved) <= 1e-9, f"F. the plates' travel goes on from their own at the first pass's end "
        f"({then['side_stroke'][end]:.4f} mm) by the stroke's in the second ({jump:.6f} against {moved:.6f} mm, 1e-9)")
k.done()
