"""Side dies (-side_die; issue 23, item 2: more tools than the two of a press).

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
   other within tests/check_squaring.py's 1 vs 2 rank bounds, 1.3e-8 of the largest value up to U = 1.5 mm and
   3e-5 beyond, where round-off grows as the flat contacts spread node by node (the same press summed in another
   order; measured 8.8e-9 and 1.3e-7), and against the quarter at the end of the press within 1e-3 (measured 6.9e-5:
   the quarter takes the simultaneous first touches of the two plates in another order, one increment fewer,
   and the elastic-plastic path follows its steps). Their side plates' outlines move by (-U, 0) and (U, 0). The
   half model on 1 vs 2 ranks within the same bounds as half vs full.
C. The paper's V-dies with side plates (options/squaring.opts, fast preset, U = 3 mm): the plates stop the tube's
   widening: touching the round tube from the start, they hold its half-width at their x = Ro - U within 1e-4 mm
   at every increment (tests/check_squaring.py's penetration bound for steps accepted with a residual; measured 6.7e-6 mm in the
   increment a node first touches the plate), where the V-dies alone widen it to 18.8 mm.
"""
import math

import h5py
import numpy as np

from tfcheck import Checks, args, history_and_tools, out, run

tf, mpirun, src = args()
k = Checks("side_dies")
RING = ["-options_file", f"{src}/options/flattening.opts", "-side_die", "flat", "-progress", 0, "-error_estimate", 0]


def press(name, extra, n=1):
    run(tf, mpirun, n, RING + extra + ["-output", out(name)], timeout=600)
    return history_and_tools(out(name))


# A. Four plates.
four = press("side_four.h5", ["-stroke", 3])
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
half = press("side_half.h5", ["-stroke", 2, "-model", "half"])
full = press("side_full.h5", ["-stroke", 2, "-model", "full"])
quarter = press("side_quarter.h5", ["-stroke", 2])
cols = ("load", "side_load", "x_max", "y_max")
same = all(half[c].shape == full[c].shape for c in cols)
rel = [np.abs(half[c] - full[c]) / np.abs(half[c]).max() for c in cols] if same else [np.ones(1)]
early = max(r[half["stroke"] <= 1.5].max() for r in rel) if same else 1
late = max(r.max() for r in rel)
k.check(early < 1.3e-8 and late < 3e-5, f"side plates, the half model against the full: every row within {early:.1e} "
        f"up to U = 1.5 mm (1.3e-8), {late:.1e} to the end (3e-5)")
end = max(abs(quarter[c][-1] / full[c][-1] - 1) for c in cols)
k.check(end < 1e-3, f"side plates, the quarter against the full model at the end of the press: within {end:.1e} (1e-3)")
moved = {n: full["tools"][n][-1][0] for n in ("side-plate", "left-side-plate")}
k.check(np.abs(moved["side-plate"] - [-2, 0]).max() < 1e-12 and np.abs(moved["left-side-plate"] - [2, 0]).max() < 1e-12,
        f"the full model's side plates move by ({moved['side-plate'][0]:g}, {moved['side-plate'][1]:g}) and "
        f"({moved['left-side-plate'][0]:g}, {moved['left-side-plate'][1]:g}) mm")

two = press("side_half_np2.h5", ["-stroke", 2, "-model", "half"], 2)
rel = [np.abs(half[c] - two[c]) / np.abs(half[c]).max() for c in cols] if two["load"].shape == half["load"].shape \
    else [np.ones(1)]
early, late = max(r[half["stroke"] <= 1.5].max() if len(r) > 1 else 1 for r in rel), max(r.max() for r in rel)
k.check(early < 1.3e-8 and late < 3e-5, f"side plates, the half model on 1 vs 2 ranks: every row within {early:.1e} up "
        f"to U = 1.5 mm (1.3e-8), {late:.1e} to the end (3e-5)")

# C. V-dies and side plates.
SQ = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
      "-progress", 0, "-error_estimate", 0, "-stroke", 3, "-unload", "none"]
run(tf, mpirun, 1, SQ + ["-side_die", "flat", "-output", out("side_v.h5")], timeout=600)
run(tf, mpirun, 1, SQ + ["-output", out("side_v_alone.h5")], timeout=600)
walled, alone = history_and_tools(out("side_v.h5")), history_and_tools(out("side_v_alone.h5"))
RO = 17.5
over = np.abs(walled["x_max"] - (RO - walled["stroke"])).max()
k.check(over < 1e-4 and alone["x_max"][-1] > RO + 1,
        f"V-dies with side plates: the plates hold the tube's half-width at their Ro - U at every increment within "
        f"{over:.1e} mm (1e-4); without them it grows to {alone['x_max'][-1]:.3f} mm")
k.done()
