"""A die off the axis and the full model's rotation hold (-die_offset, -full_hold;
docs/dies.md, "A die off the axis").

The paper's tube (options/squaring.opts, fast preset) pressed U = 1.5 mm in the full model by an upper V-die moved
e = 0.5 mm off the axis, over the lower V-die on it. The pins would hold the tube's slide against the die; the
rotation hold moves its two inner axis nodes sideways together by an unknown that leaves them a couple only.
A. The die starts where it touches the tube: a 90-degree V moved e sideways touches the circle e tan 45 = e higher
   (the run's line "starts ... back", within half a unit of its 4th printed digit).
B. Equilibrium of the tube, from the dies' reported forces and moments (tool_*, lower_*, about their frames'
   origins, moved here to the tube's centre) against the hold, at every loading increment:
   - the hold carries no net force: tool_fx + lower_fx = 0;
   - the dies' moment about the centre is the hold's couple (hold_moment, from the body's forces at its nodes).
   Both within what the increment's out-of-balance forces can leave: n_contact (residual + fn_mismatch), the
   tools' forces being the contact nodes' stored forces, each off what the body needs there by at most the
   step's out-of-balance (`residual`, its 2-norm, above its largest entry) plus the bookkeeping's drift
   (`fn_mismatch`), times Ro for the moment (the nodes' arm about the centre). A heuristic bound: out-of-balance
   forces at free nodes away from the contacts are left out (the equilibrium iterations keep them within the
   same tolerance); measured well inside it. On 1 and 2 ranks. Pins in place of the hold carry the die's sideways force (9 N/mm
   here); a couple of the wrong sign leaves twice the hold's moment (28 N mm/mm at U = 0.33 mm).
C. The die 0.5 mm to the left (-die_offset -0.5) is the mirror image over the press (its springback is held by a
   pin right of the axis in both): load, tool_fy, lower_fy, x_max, y_max the
   same and tool_fx, lower_fx, hold_moment of opposite sign, within 1e-6 of each column's largest value (the mesh
   is mirrored to round-off, which the tube's soft sway between the dies (docs/dies.md) amplifies: measured
   1.9e-9 here and 1.0e-8 at U = 2 mm, growing with the stroke as the round-off another CPU's kernels leave
   would; the symmetric press under the hold drifts to 6e-4 from round-off alone, so 1e-6 keeps room for that
   growth; a die moved the wrong way, or a sign of the couple in one direction only, is O(1)).
D. The energy balance (self-check (a): the dies' work from their reported forces against internal work, the hold
   doing none) within 5e-3 at every increment from U = 0.1 mm, the springback's too (tests/check_side_dies.py C's
   bound). The springback releases the hold's couple with the dies' forces (the release's reversed loads): the
   moment the springback's pins carry (hold_moment while it springs back) within B's bound for the press's end,
   pressed to U = 0.33 mm, where the couple is largest (28 N mm/mm; measured 1.7, and 24 with the couple left
   to the pins).
E. 1 vs 2 ranks within C's 1e-6; a checkpoint inside the press, continued: the history within 1e-12
   (tests/check_restart.py's bound).
F. A second pass turned by a quarter turn after a first one over a flat floor (`-lower_die flat -pass2_turn 90
   -pass2_stroke 2`, U = 2 mm each): the first pass leaves the tube symmetric about its y axis only, so the
   second presses it off its press's axis; -full_hold auto holds that pass by the rotation hold (the first by the
   pins). B's balance in the second pass (the dies' frame origins on the press's y axis: the upper die's moved
   back to the tube, the run prints how far, the floor's rising by the pass's stroke), the energy balance of
   both passes as D. The hold's couple there is about twice what the contacts' friction could carry (the
   D-shaped tube is pressed off its centre by dies touching it at a few nodes): the run warns that the real
   tube may turn, at the first row where the history's hold_moment exceeds hold_friction by more than the
   couple the method resolves (1e-3 of the largest load so far times Ro: its equilibrium tolerance).
G. A second pass turned by 45 degrees (`-pass2_turn 45`, U = 2 mm, then the dies from where they touch the turned
   tube, 1.57 mm back, to U = 0.1 mm, on a mesh of 67 elements a quarter
   around so that no node lies on the turned axes: the hold's nodes and the springback's pins are those nearest
   them, with node frames along the turned press): the first pass's V-dies leave the tube symmetric about its x
   and y axes, not its diagonals, so the second presses it off its press's axis. B's balance in that pass (both
   dies moved back to the tube, as the run prints); the energy balance of both passes as D; the turn by -45
   degrees is the mirror image and by 225 the same press (the first pass's tube is symmetric about its y axis
   and under a half turn): at the end of the press and after its springback, load, C1, C2, internal work within
   1e-3 of their values, the sideways forces within 1e-3 of the load and the couple within 1e-3 of the load
   times Ro, each of opposite sign in the mirror (contact events that fall 1e-7 mm apart in the two runs are
   taken in another order after that, as tests/check_side_dies.py B's quarter against the full model); the
   45-degree run on 2 ranks within the same.
   In F and G (and H) the balance is checked on the rows under the hold: at a pass's first touches the hold's
   nodes are fixed, holding the tube's slide too, until the contacts' normals spread over the plane
   (scenes/hold.hpp, FreeSlide); their rows (hold_moment and hold_friction 0: the hold reports nothing) must come
   first in the pass, and are counted and left out.
H. A second pass (U = 2 mm, not turned) after the die off the axis (`-die_offset 0.5`, U = 2 mm): held by the
   rotation hold (the first pass left the tube off its axis). B's balance in that pass, the energy as D; the pass
   takes fewer than 1000 increments (with the hold from the pass's start its first touches, a flank of each die
   facing the other's, left the slide along them to friction alone at a vanishing normal force: 3,534 increments,
   3,342 of them stick-limited at 1e-6 mm of stroke), and the run says where the dies take the slide (the last
   row with the nodes fixed, to half a unit of the 4 printed digits); a checkpoint in that pass after it, continued:
   the history within 1e-12 (E's bound).
I. A second pass's die off the axis (`-pass2_die_offset 0.5`, to U = 0.33 mm) after a first pass on the axis that
   stays elastic (U = 0.02 mm, no Gauss point plastic, its springback leaving the tube round to a few 1e-6 mm): the
   same press as the first pass's die off the axis ("short": D's run), since a pass's zero is where its die
   touches the round tube. The run says the pass's dies start within 1e-4 mm of that zero (the elastic pass leaves
   the tube round to a few 1e-6 mm; a zero taken from the die on the axis is e tan 45 = 0.5 mm off); at the end of
   the press (and C1, C2 after its springback) load, C1, C2 within 1e-3 of their values, the sideways forces
   within 1e-3 of the load and the couple within 1e-3 of the load times Ro (G's bounds: the two runs' contact events fall a few 1e-6 mm
   apart; measured 4e-5). The offset ignored leaves the sideways force about 0.12 of the load; measured from the
   die on the axis touching the round tube, the pass presses 0.5 mm less: O(1). The self-checks through the first
   pass's springback, which gives its work back (the internal work falls to 2e-7 of its largest): (a) and (b), each
   relative to the largest its reference has been, within D's 5e-3 from the 11th row on (as the run's own summary
   line takes them; relative to the work left, (b) read 0.94 there), (b) recomputed from the works' columns.
"""
import re
from concurrent.futures import ThreadPoolExecutor

import h5py
import numpy as np

from tfcheck import COLUMN_TOL, Checks, args, checkpoint_at, out, run, run_all, self_checks

tf, mpirun, src = args()
k = Checks("hold")
E, RO = 0.5, 17.5
BASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-progress", 0, "-error_estimate", 0, "-stroke", 1.5, "-unload", "reverse"]
TWO = BASE[:-4] + ["-stroke", 2, "-pass2_stroke", 2]
# (67 elements a quarter around: a node every 90/67 degrees, none on the 45-degree axis)
# (the second pass's dies start 1.57 mm back, where the turned square's corners reach; they press 1.67 mm to U = 0.1)
ODD = TWO[:-1] + [0.1, "-mesh_ntheta", 67]
RUNS = {"right": BASE + ["-die_offset", E], "left": BASE + ["-die_offset", -E],
        "short": BASE[:-4] + ["-stroke", 0.33, "-die_offset", E],
        "turned": TWO + ["-lower_die", "flat", "-pass2_turn", 90],
        "offset2": TWO + ["-die_offset", E],
        "t45": ODD + ["-pass2_turn", 45], "tm45": ODD + ["-pass2_turn", -45], "t225": ODD + ["-pass2_turn", 225],
        "offset_later": BASE[:-4] + ["-stroke", 0.02, "-output_stroke", 0, "-pass2_stroke", 0.33,
                                     "-pass2_die_offset", E]}


def history(name):
    with h5py.File(out(name), "r") as h:
        return {c: h["/history"][c][:] for c in h["/history"]}


procs = dict(zip(RUNS, run_all(tf, mpirun, [RUNS[n] + ["-output", out(f"{n}.h5")] for n in RUNS], timeout=600)))
right, left = history("right.h5"), history("left.h5")


def stop_and_continue(name, every):
    """RUNS[name] run to increment `every`, its checkpoint written there, then continued from it (E, H)."""
    opts, ck = RUNS[name] + ["-output", out(f"{name}_part.h5")], out(f"{name}_ck.h5")
    checkpoint_at(tf, mpirun, 1, opts, ck, every, timeout=600)
    run(tf, mpirun, 1, opts + ["-restart", ck], timeout=600)


# E's and H's single-rank pairs of runs side by side (before the 2-rank runs): E's checkpoint a few increments before
# the press's end (the press takes most of the run's increments); H's in the second pass, 0.2 mm after the dies took
# the slide (the last row with the hold's nodes fixed).
o2 = history("offset2.h5")
o2_pinned = (o2["stage"] == 2) & (o2["hold_moment"] == 0) & (o2["hold_friction"] == 0)  # (as H below)
o2_last = o2["stroke"][o2_pinned].max() if o2_pinned.any() else -1.0
with ThreadPoolExecutor(max_workers=2) as pool:
    list(pool.map(lambda a: stop_and_continue(*a), (("right", int(np.sum(right["stage"] == 0)) - 5),
                                                    ("offset2", int(np.where(o2["stroke"] > o2_last + 0.2)[0][0])))))

# A. Where the die starts.
m = re.search(r"starts ([0-9.e+-]+) mm back", procs["right"].stdout)
back = float(m.group(1)) if m else -1.0
k.check(abs(back - E) <= 5e-4 * E, f"A. the die {E} mm off the axis starts {back} mm up, where it touches the tube "
        f"(e tan 45 = {E}; 4 digits)")

# B. Equilibrium of the tube.
def balance(h, label):
    """B's two balances over the press (stage 0) of the history h; their largest ratios to the bounds."""
    press, U = h["stage"] == 0, h["stroke"]
    bound = (h["n_contact"] * (h["residual"] + h["fn_mismatch"]))[press]
    force = np.abs(h["tool_fx"] + h["lower_fx"])[press]
    # (the upper die's frame origin: the tube's centre moved by the offset and the start, then down by U; the
    # lower's up by U)
    dies = h["tool_moment"] + E * h["tool_fy"] - (back - U) * h["tool_fx"] + h["lower_moment"] - U * h["lower_fx"]
    moment = np.abs(dies - h["hold_moment"])[press]
    f, mo = np.max(force / np.maximum(bound, 1e-300)), np.max(moment / np.maximum(RO * bound, 1e-300))
    k.check(f <= 1, f"B. {label}: no net force on the hold: |tool_fx + lower_fx| at most {f:.2g} of n_contact "
            f"(residual + fn_mismatch) (1)")
    k.check(mo <= 1, f"B. {label}: the dies' moment about the centre is the hold's couple (largest "
            f"{np.abs(h['hold_moment'][press]).max():.1f} N mm/mm): off by at most {mo:.2g} of Ro n_contact "
            f"(residual + fn_mismatch) (1)")


balance(right, "1 rank")
U = right["stroke"]


# C. The mirror image.
def mirrored(a, b):
    if a["stroke"].shape != b["stroke"].shape:
        return 1.0, ""
    same = ["stroke", "load", "tool_fy", "lower_fy", "x_max", "y_max", "w_int"]
    opposite = ["tool_fx", "lower_fx", "hold_moment"]
    # (over the press: the springback is held by a pin that both runs put right of the axis, not mirrored)
    press = a["stage"] == 0
    rel = {c: np.abs(b[c] - a[c])[press].max() / np.abs(a[c]).max() for c in same}
    rel.update({c: np.abs(b[c] + a[c])[press].max() / np.abs(a[c]).max() for c in opposite})
    worst = max(rel, key=rel.get)
    return rel[worst], worst


worst, col = mirrored(right, left)
k.check(worst <= 1e-6, f"C. the die {E} mm to the left is the mirror image: within {worst:.1e} ({col}; 1e-6)")

# D. Energy.
early = U >= 0.1
k.check(np.abs(right["energy_error"][early]).max() <= 5e-3,
        f"D. energy balance from U = 0.1 mm within {np.abs(right['energy_error'][early]).max():.1e} (5e-3)")

short = history("short.h5")
end, rel = np.where(short["stage"] == 0)[0][-1], short["stage"] == 1
carried = np.abs(short["hold_moment"][rel]).max()
limit = RO * short["n_contact"][end] * (short["residual"][end] + short["fn_mismatch"][end])
k.check(carried <= limit, f"D. the springback releases the hold's couple ({short['hold_moment'][end]:.1f} N mm/mm at "
        f"U = 0.33 mm) with the dies' forces: its pins carry at most {carried:.2g} N mm/mm (B's bound at the "
        f"press's end: {limit:.2g})")

# E. Ranks and a restart.
run(tf, mpirun, 2, RUNS["right"] + ["-output", out("right_np2.h5")], timeout=600)
two = history("right_np2.h5")
balance(two, "2 ranks")
same = two["stroke"].shape == U.shape
worst = max(np.abs(two[c] - right[c]).max() / np.abs(right[c]).max() for c in ("load", "hold_moment", "tool_fx",
                                                                               "x_max")) if same else 1.0
k.check(same and worst <= 1e-6, f"E. 1 vs 2 ranks within {worst:.1e} (1e-6)")
with h5py.File(out("right_ck.h5"), "r") as c:  # (the pair of runs made after the single-rank runs)
    lam = c["/run/lambda"][0]
part = history("right_part.h5")
same = all(part[c].shape == right[c].shape for c in right)
worst = max(np.abs(part[c] - right[c]).max() / max(np.abs(right[c]).max(), 1e-300) for c in right) if same else 1
k.check(same and worst <= 1e-12 and 0.2 < lam < 1.0,
        f"E. continued from a checkpoint inside the press (lambda {lam:.3f}): the history within {worst:.1e} (1e-12)")

# F. A turned second pass off its press's axis.
def second_pass_balance(name, label):
    """B's balance in the second pass of RUNS[name] (U1 = 2 mm), the dies' frame origins on the press's y axis:
    each moved back to the tube as the run printed (0 if not), then along its motion by the pass's travel."""
    t, text = history(f"{name}.h5"), procs[name].stdout
    back = [re.search(rf"pass2-{d} starts at U = [0-9.e+-]+ mm, ([0-9.e+-]+) mm back", text) for d in ("V-die", "lower-V-die")]
    b_up, b_low = (float(m.group(1)) if m else 0.0 for m in back)
    # (the dies' travel; the history's stroke is the upper die's position)
    U2 = t["stroke"] + b_up
    # (the rows the hold holds: before the dies hold the slide the pins do, and the hold reports nothing)
    pinned = (t["stage"] == 2) & (t["hold_moment"] == 0) & (t["hold_friction"] == 0)
    second = (t["stage"] == 2) & ~pinned
    bound = t["n_contact"] * (t["residual"] + t["fn_mismatch"])
    force = np.abs(t["tool_fx"] + t["lower_fx"])
    dies = t["tool_moment"] - (b_up - U2) * t["tool_fx"] + t["lower_moment"] - (U2 - b_low) * t["lower_fx"]
    moment = np.abs(dies - t["hold_moment"])
    first = not pinned.any() or not second.any() or np.where(pinned)[0].max() < np.where(second)[0].min()
    k.check(second.sum() > 0 and first and np.all(force[second] <= bound[second]) and
            np.all(moment[second] <= RO * bound[second]),
            f"{label}: the balance over its {second.sum()} rows under the hold ({pinned.sum()} first with its nodes fixed"
            f"{'' if first else ', NOT all first'}; "
            f"the dies moved back {b_up}, {b_low} mm): net force at most "
            f"{np.max(force[second] / np.maximum(bound[second], 1e-300)):.2g}, moment about the centre off the "
            f"couple (largest {np.abs(t['hold_moment']).max():.0f} N mm/mm) at most "
            f"{np.max(moment[second] / np.maximum(RO * bound[second], 1e-300)):.2g} of their bounds (1)")
    return t


t = second_pass_balance("turned", "F. the quarter-turned second pass")
second = t["stage"] == 2
p = procs["turned"]
late = t["stroke"] >= 0.1
k.check(np.abs(t["energy_error"][late]).max() <= 5e-3,
        f"F. energy balance of both passes within {np.abs(t['energy_error'][late]).max():.1e} (5e-3)")
# (a couple within 1e-3 of the largest load so far times Ro is one the method does not resolve: no warning)
floor = 1e-3 * np.maximum.accumulate(np.abs(t["load"])) * RO
over = np.where(second & (np.abs(t["hold_moment"]) > t["hold_friction"] + floor))[0]
said = re.search(r"warning: at U = ([0-9.e+-]+) mm the rotation hold carries", p.stdout)
k.check(len(over) > 0 and said is not None and abs(float(said.group(1)) - t["stroke"][over[0]]) <= 1e-3,
        f"F. the run warns that the real tube may turn (at U = {said.group(1) if said else '-'} mm), where the "
        f"couple first exceeds the friction's largest ({t['stroke'][over[0]] if len(over) else '-'} mm; "
        f"{np.abs(t['hold_moment'][second]).max() / t['hold_friction'][second].max():.1f} times it at most)")

# G. A second pass turned by 45 degrees.
t45 = second_pass_balance("t45", "G. the second pass turned by 45 degrees")
k.check(np.abs(t45["energy_error"][t45["stroke"] >= 0.1]).max() <= 5e-3,
        f"G. energy balance of both passes within {np.abs(t45['energy_error'][t45['stroke'] >= 0.1]).max():.1e} "
        f"(5e-3)")


def ends(a, b, sign):
    """The largest difference of b from a (b's sideways forces and couple times `sign`) at the end of the second
    pass's press and of its springback: load, C1, C2, internal work relative to their values, sideways forces
    relative to the load, the couple relative to the load times Ro."""
    worst = 0.0
    for stage in (2, 3):
        i, j = (np.where(x["stage"] == stage)[0][-1] for x in (a, b))
        load = abs(a["load"][np.where(a["stage"] == 2)[0][-1]])
        for c in ("load", "x_max", "y_max", "w_int") if stage == 2 else ("x_max", "y_max", "w_int"):
            worst = max(worst, abs(b[c][j] - a[c][i]) / max(abs(a[c][i]), 1e-300))  # (the load is 0 sprung back)
        for c, scale in (("tool_fx", load), ("lower_fx", load), ("hold_moment", load * RO)):
            worst = max(worst, abs(sign * b[c][j] - a[c][i]) / scale)
    return worst


for name, sign, label in (("tm45", -1, "turned by -45 degrees: the mirror image"), ("t225", 1,
                                                                                   "turned by 225: the same press")):
    w = ends(t45, history(f"{name}.h5"), sign)
    k.check(w <= 1e-3, f"G. {label}, at the ends of the press and its springback within {w:.1e} (1e-3)")
run(tf, mpirun, 2, RUNS["t45"] + ["-output", out("t45_np2.h5")], timeout=600)
w = ends(t45, history("t45_np2.h5"), 1)
k.check(w <= 1e-3, f"G. turned by 45 degrees on 1 vs 2 ranks, at the ends of the press and its springback within "
        f"{w:.1e} (1e-3)")
# H. A second pass after the die off the axis.
t = second_pass_balance("offset2", "H. the second pass after the die off the axis")
late = t["stroke"] >= 0.1
k.check(np.abs(t["energy_error"][late]).max() <= 5e-3,
        f"H. energy balance of both passes within {np.abs(t['energy_error'][late]).max():.1e} (5e-3)")
said = re.search(r"slide from U = ([0-9.e+-]+) mm", procs["offset2"].stdout)
n2 = int(np.sum(t["stage"] == 2))
pinned = (t["stage"] == 2) & (t["hold_moment"] == 0) & (t["hold_friction"] == 0)
last = t["stroke"][pinned].max() if pinned.any() else -1.0
digit = 0.5 * 10.0 ** (np.floor(np.log10(max(last, 1e-300))) - 3)  # (half a unit of the printed 4th digit)
k.check(n2 < 1000 and said is not None and abs(float(said.group(1)) - last) <= digit,
        f"H. the pass takes {n2} increments (1000; a crawl of stick-limited steps took 3,534 with the slide free from "
        f"the pass's start), the hold's nodes fixed up to U = {last:.5f} mm, where the run says the dies hold the "
        f"slide ({said.group(1) if said else '-'} mm, 4 digits)")
# (a checkpoint in the second pass after the dies took the slide, continued: the state of the hold's nodes kept; the
# pair of runs made after the single-rank runs)
part = history("offset2_part.h5")
same = all(part[c].shape == t[c].shape for c in t)
worst = max(np.abs(part[c] - t[c]).max() / max(np.abs(t[c]).max(), 1e-300) for c in t) if same else 1
k.check(same and worst <= 1e-12, f"H. continued from a checkpoint in the second pass after the dies took the slide: "
        f"the history within {worst:.1e} (1e-12)")

# I. A second pass's die off the axis: the first pass's press.
later, text = history("offset_later.h5"), procs["offset_later"].stdout
starts = [float(b) for b in re.findall(r"pass2-\S+ starts at U = [0-9.e+-]+ mm, ([0-9.e+-]+) mm back", text)]
# (a die the round tube's zero already touches prints no line: 0 back; the upper die's start is in the results)
with h5py.File(out("offset_later.h5"), "r") as h:
    start = h["/history"].attrs["pass2_start_stroke"]
k.check(np.all(later["n_plastic"][later["stage"] == 0] == 0) and max(starts, default=0.0) <= 1e-4 and
        abs(start) <= 1e-4,
        f"I. after an elastic first pass the second pass's dies start {starts} mm back from its zero, its upper die "
        f"at U = {start:.2e} mm (1e-4)")
worst = 0.0
for a_stage, b_stage in ((0, 2), (1, 3)):
    i, j = np.where(short["stage"] == a_stage)[0][-1], np.where(later["stage"] == b_stage)[0][-1]
    load = abs(short["load"][np.where(short["stage"] == 0)[0][-1]])
    for c in ("load", "x_max", "y_max") if a_stage == 0 else ("x_max", "y_max"):  # (the load is 0 sprung back)
        worst = max(worst, abs(later[c][j] - short[c][i]) / abs(short[c][i]))
    for c, scale in (("tool_fx", load), ("lower_fx", load), ("hold_moment", load * RO)):
        worst = max(worst, abs(later[c][j] - short[c][i]) / scale)
k.check(worst <= 1e-3, f"I. -pass2_die_offset {E} presses as -die_offset {E}: at the ends of the press and its "
        f"springback within {worst:.1e} (1e-3)")
b = self_checks(later)[1]  # ((b) from the works' columns; (a) the run's own, as D)
gap = np.abs(later["internal_error"] - b).max()
fell = later["w_int"][later["stage"] == 1][-1] / later["w_int"].max()
checks = max(np.abs(later["energy_error"][10:]).max(), np.abs(b[10:]).max())
k.check(checks <= 5e-3 and gap <= COLUMN_TOL, f"I. the self-checks through the elastic pass's springback (the internal "
        f"work down to {fell:.1e} of its largest) within {checks:.1e} (5e-3); the run's internal_error column is "
        f"(b) recomputed within {gap:.1e} ({COLUMN_TOL})")
k.done()
