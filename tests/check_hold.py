"""A die off the axis and the full model's rotation hold (-die_offset, -full_hold; issue 23, item 3: "a die
offset from the axis"; docs/dies.md, "The rotation hold").

The paper's tube (options/squaring.opts, fast preset) pressed U = 1.5 mm in the full model by an upper V-die moved
e = 0.5 mm off the axis, over the lower V-die on it. The pins would hold the tube's slide against the die; the
rotation hold moves its two inner axis nodes sideways together by an unknown that leaves them a couple only.
A. The die starts where it touches the tube: a 90-degree V moved e sideways touches the circle e tan 45 = e higher
   (the run's line "starts ... back", within its 4 printed digits).
B. Equilibrium of the tube, from the dies' reported forces and moments (tool_*, lower_*, about their frames'
   origins, moved here to the tube's centre) against the hold, at every loading increment:
   - the hold carries no net force: tool_fx + lower_fx = 0;
   - the dies' moment about the centre is the hold's couple (hold_moment, from the body's forces at its nodes).
   Both within what the increment's out-of-balance forces can leave: n_contact (residual + fn_mismatch), the
   tools' forces being the contact nodes' stored forces, each off what the body needs there by at most the
   step's largest out-of-balance force (`residual`) plus the bookkeeping's drift (`fn_mismatch`), times Ro for
   the moment (the nodes' arm about the centre). Pins in place of the hold carry the die's sideways force (9 N/mm
   here); a couple of the wrong sign leaves twice the hold's moment (28 N mm/mm at U = 0.33 mm).
C. The die 0.5 mm to the left (-die_offset -0.5) is the mirror image: load, tool_fy, lower_fy, x_max, y_max the
   same and tool_fx, lower_fx, hold_moment of opposite sign, within 1e-6 of each column's largest value (the mesh
   is mirrored to round-off, which the tube's soft sway between the dies (docs/dies.md) amplifies: measured
   1.9e-9 here and 1.0e-8 at U = 2 mm, growing with the stroke as the round-off another CPU's kernels leave
   would; the symmetric press under the hold drifts to 6e-4 from round-off alone, so 1e-6 keeps room for that
   growth; a die moved the wrong way, or a sign of the couple in one direction only, is O(1)).
D. The energy balance (self-check (a): the dies' work from their reported forces against internal work, the hold
   doing none) within 5e-3 at every loading increment from U = 0.1 mm (tests/check_side_dies.py C's bound).
E. 1 vs 2 ranks within C's 1e-6; a checkpoint inside the press, continued: the history within 1e-12
   (tests/check_restart.py's bound).
F. A second pass turned by a quarter turn after a first one over a flat floor (`-lower_die flat -pass2_turn 90
   -pass2_stroke 2`, U = 2 mm each): the first pass leaves the tube symmetric about its y axis only, so the
   second presses it off its press's axis; -full_hold auto holds that pass by the rotation hold (the first by the
   pins). B's balance in the second pass (the dies' frame origins on the press's y axis: the upper die's moved
   back to the tube, the run prints how far, the floor's rising by the pass's stroke), the energy balance of
   both passes as D. The hold's couple there is about twice what the contacts' friction could carry (the
   D-shaped tube is pressed off its centre by dies touching it at a few nodes): the run warns that the real
   tube would turn, at the first row where the history's hold_moment exceeds hold_friction.
"""
import re

import h5py
import numpy as np

from tfcheck import Checks, args, out, run, run_all

tf, mpirun, src = args()
k = Checks("hold")
E, RO = 0.5, 17.5
BASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-progress", 0, "-error_estimate", 0, "-stroke", 1.5, "-unload", "none"]
RUNS = {"right": BASE + ["-die_offset", E], "left": BASE + ["-die_offset", -E]}


def history(name):
    with h5py.File(out(name), "r") as h:
        return {c: h["/history"][c][:] for c in h["/history"]}


procs = run_all(tf, mpirun, [RUNS[n] + ["-output", out(f"{n}.h5")] for n in RUNS], timeout=600)
right, left = history("right.h5"), history("left.h5")

# A. Where the die starts.
m = re.search(r"starts ([0-9.e+-]+) mm back", procs[0].stdout)
back = float(m.group(1)) if m else -1.0
k.check(abs(back - E) <= 5e-5 * E, f"A. the die {E} mm off the axis starts {back} mm up, where it touches the tube "
        f"(e tan 45 = {E}; 4 digits)")

# B. Equilibrium of the tube.
U = right["stroke"]
bound = right["n_contact"] * (right["residual"] + right["fn_mismatch"])
force = np.abs(right["tool_fx"] + right["lower_fx"])
# (the upper die's frame origin: the tube's centre moved by the offset and the start, then down by U; the lower's
# up by U)
dies = (right["tool_moment"] + E * right["tool_fy"] - (back - U) * right["tool_fx"] + right["lower_moment"] -
        U * right["lower_fx"])
moment = np.abs(dies - right["hold_moment"])
k.check(np.all(force <= bound), f"B. no net force on the hold: |tool_fx + lower_fx| at most "
        f"{np.max(force / np.maximum(bound, 1e-300)):.2g} of n_contact (residual + fn_mismatch) (1)")
k.check(np.all(moment <= RO * bound), f"B. the dies' moment about the centre is the hold's couple (largest "
        f"{np.abs(right['hold_moment']).max():.1f} N mm/mm): off by at most "
        f"{np.max(moment / np.maximum(RO * bound, 1e-300)):.2g} of Ro n_contact (residual + fn_mismatch) (1)")


# C. The mirror image.
def mirrored(a, b):
    if a["stroke"].shape != b["stroke"].shape:
        return 1.0, ""
    same = ["stroke", "load", "tool_fy", "lower_fy", "x_max", "y_max", "w_int"]
    opposite = ["tool_fx", "lower_fx", "hold_moment"]
    rel = {c: np.abs(b[c] - a[c]).max() / np.abs(a[c]).max() for c in same}
    rel.update({c: np.abs(b[c] + a[c]).max() / np.abs(a[c]).max() for c in opposite})
    worst = max(rel, key=rel.get)
    return rel[worst], worst


worst, col = mirrored(right, left)
k.check(worst <= 1e-6, f"C. the die {E} mm to the left is the mirror image: within {worst:.1e} ({col}; 1e-6)")

# D. Energy.
early = U >= 0.1
k.check(np.abs(right["energy_error"][early]).max() <= 5e-3,
        f"D. energy balance from U = 0.1 mm within {np.abs(right['energy_error'][early]).max():.1e} (5e-3)")

# E. Ranks and a restart.
run(tf, mpirun, 2, RUNS["right"] + ["-output", out("right_np2.h5")], timeout=600)
two = history("right_np2.h5")
same = two["stroke"].shape == U.shape
worst = max(np.abs(two[c] - right[c]).max() / np.abs(right[c]).max() for c in ("load", "hold_moment", "tool_fx",
                                                                               "x_max")) if same else 1.0
k.check(same and worst <= 1e-6, f"E. 1 vs 2 ranks within {worst:.1e} (1e-6)")
ck = out("right_ck.h5")
opts = RUNS["right"] + ["-output", out("right_part.h5")]
run(tf, mpirun, 1, opts + ["-checkpoint", ck, "-checkpoint_every", len(U) // 2], timeout=600)
with h5py.File(ck, "r") as c:
    lam = c["/run/lambda"][0]
run(tf, mpirun, 1, opts + ["-restart", ck], timeout=600)
part = history("right_part.h5")
same = all(part[c].shape == right[c].shape for c in right)
worst = max(np.abs(part[c] - right[c]).max() / max(np.abs(right[c]).max(), 1e-300) for c in right) if same else 1
k.check(same and worst <= 1e-12 and 0.2 < lam < 0.9,
        f"E. continued from a checkpoint inside the press (lambda {lam:.3f}): the history within {worst:.1e} (1e-12)")

# F. A turned second pass off its press's axis.
p = run(tf, mpirun, 1, BASE[:-4] + ["-stroke", 2, "-lower_die", "flat", "-pass2_turn", 90, "-pass2_stroke", 2,
                                    "-output", out("turned.h5")], timeout=600)
t = history("turned.h5")
m = re.search(r"pass2-V-die starts ([0-9.e+-]+) mm back", p.stdout)
back2 = float(m.group(1)) if m else float("nan")
second = t["stage"] == 2
U2 = t["stroke"] - 2.0
bound = t["n_contact"] * (t["residual"] + t["fn_mismatch"])
force = np.abs(t["tool_fx"] + t["lower_fx"])
dies = t["tool_moment"] - (back2 - U2) * t["tool_fx"] + t["lower_moment"] - U2 * t["lower_fx"]
moment = np.abs(dies - t["hold_moment"])
k.check(np.all(force[second] <= bound[second]) and np.all(moment[second] <= RO * bound[second]),
        f"F. the turned second pass's balance (the upper die moved back {back2} mm): net force at most "
        f"{np.max(force[second] / np.maximum(bound[second], 1e-300)):.2g}, moment about the centre off the couple "
        f"(largest {np.abs(t['hold_moment']).max():.0f} N mm/mm) at most "
        f"{np.max(moment[second] / np.maximum(RO * bound[second], 1e-300)):.2g} of their bounds (1)")
late = t["stroke"] >= 0.1
k.check(np.abs(t["energy_error"][late]).max() <= 5e-3,
        f"F. energy balance of both passes within {np.abs(t['energy_error'][late]).max():.1e} (5e-3)")
over = np.where(second & (np.abs(t["hold_moment"]) > t["hold_friction"]))[0]
said = re.search(r"warning: at U = ([0-9.e+-]+) mm the rotation hold carries", p.stdout)
k.check(len(over) > 0 and said is not None and abs(float(said.group(1)) - t["stroke"][over[0]]) <= 1e-3,
        f"F. the run warns that the real tube would turn (at U = {said.group(1) if said else '-'} mm), where the "
        f"couple first exceeds the friction's largest ({t['stroke'][over[0]] if len(over) else '-'} mm; "
        f"{np.abs(t['hold_moment'][second]).max() / t['hold_friction'][second].max():.1f} times it at most)")
k.done()
