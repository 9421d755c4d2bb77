"""The upper die turning along its own path (-die_path_turn about -die_pivot: a prescribed path in
time, translation and rotation, piecewise linear; docs/motions.md, "A die that turns").

The paper's tube (options/squaring.opts, fast preset), the lower V-die staying, the upper one down to U = 1 mm,
then 0.3 mm to the right while turning 3 degrees counter-clockwise about its apex (the pivot 0,24.75: ro sqrt 2
above the centre), then down again while turning back to -1 degree: `-die_path 0,-2,0.3,-2.4,0.3,-2.8
-die_path_turn 0,3,-1 -die_pivot 0,24.75`, in the full model under the rotation hold.
A. Turns of 0 change nothing: the sideways path with `-die_path_turn 0,0,0` and a pivot is the history without
   them to 1e-12 of each column's largest value but tool_moment (the pivot is the point it is taken about; it is
   checked against the other's moved there, within 1e-9 of the load times ro: the shift's round-off).
B. The die where the path puts it: its outline in the results (/tools/V-die/displacement) at the output steps at
   the path's points is the drawing turned about the pivot by the point's angle and moved by its x, y, within
   1e-12 mm; the history's die_turn, die_x and U there are the point's (1e-12).
C. The energy balance (self-check (a): the upper die's work from its reported forces along its motions and its
   moment about the pivot over its turn, tool_moment over die_turn) within 5e-3 at every increment from U = 0.1 mm
   (tests/check_hold.py D's bound); the turn's work is more than that share of the work put in, so a balance
   without it fails.
D. Equilibrium of the tube at every loading increment, as tests/check_die_path.py D, the upper die's moment taken
   about the centre from its pivot (at (die_x, 24.75 - 2 U)): no net force on the hold, the dies' moment the hold's
   couple, within n_contact (residual + fn_mismatch) (times ro for the moment); on 1 and 2 ranks.
E. The mirrored press (x -> -x and the turns' signs flipped) is the mirror image, and 2 ranks the same press, at
   the path's points and the springback's end: load, extents, internal work the same, the sideways force, the
   die's moment and the hold's couple of opposite sign in the mirror, within 7e-3 of the load (of the load times
   ro for the moments, of ro for the extents): ten times what a perturbation of 1.3e-13 in E moves this press
   (-material_e 75000.00000000975 and 74999.99999999025: 9.9e-5 and 6.4e-4, the hold's couple; the full model
   under the hold sways by round-off, as in tests/check_die_path.py E, more here where the die turns). Measured:
   the mirror 4.6e-4, 2 ranks 3.7e-4 (1.1e-3 on another OpenBLAS kernel).
F. A checkpoint inside the turning piece, continued: the history within 1e-12 (tests/check_restart.py's bound):
   the turn follows from the stroke, not from a state.
G. Each increment turns the die by at most -rmin_domega (the tool's turn is linear in a step, as the body's
   rotations are): with -rmin_domega 1e-3, below the 2.4e-3 rad the press's other events leave, die_turn's steps
   within it (1e-9 of it: the step's round-off). Here the tube's elements under the die turn faster than it, so
   the body's r3 binds first (the tool's own bound is checked in tests/test_contact.cpp). The penetration the linear
   turn leaves (a second-order chord) below the gap a turn of 1e-2 rad leaves over the die's reach,
   0.5 (1e-2)^2 x 2 ro.
H. A frictionless roller (an arc of radius 5 mm about 0,22.5 under a rising line) pressed to U = 1 mm, then turned
   in place about its centre by 10 degrees, both ways (10 trial increments: a trial step would turn it by 2.9e-2
   rad): its surface does not move, so the tool's own r3 cuts the turn's increments at 1e-2 rad (1e-9 of it; the
   tube's elements do not turn, so nothing else can); the two ways give the same press (load, extents, works,
   C/t within 5e-11 of each column's largest value: nothing may depend on the way a frictionless roller turns but
   round-off, bounded by ten times the press's response to a 1.3e-13 perturbation of E, 4.6e-12; measured
   1.4e-13, 5.5e-12 with OPENBLAS_CORETYPE=Haswell); over the turn the load moves by no more than the equilibrium iterations may still settle
   (-equilibrium_tol 0.005 of q_avg at each contact node; measured 2.7e-6 N/mm against 0.17) and the die does no
   work (1e-12 of the work: the normal forces pass through the centre). A centre taken wrong pushes the tube.
"""
import h5py
import numpy as np

from die_press import at_rows, balance
from tfcheck import Checks, args, checkpoint_at, out, run, run_all

tf, mpirun, src = args()
k = Checks("die_turn")
RO = 17.5
PIVOT = (0.0, 24.75)
DOMEGA = 1e-2  # -rmin_domega's default (rad)
FINE = 1e-3  # a bound the press's other events do not keep the die's turn within (its steps reach 2.4e-3 rad)
# H's two ways of turning differ by the round-off of the turned geometry (cos and sin of +-theta): ten times what a
# perturbation of 1.3e-13 in E moves the roller's press (-material_e 75000.00000000975 and 74999.99999999025: the
# load, works and lower_fy by up to 4.6e-12 of their largest values).
ROUND_OFF = 5e-11
SWAY = 7e-3  # E: ten times this press's response to that perturbation of E (6.4e-4 of the load x ro, hold_moment)
BASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-progress", 0, "-error_estimate", 0, "-unload", "reverse", "-lower_die_motion", "fixed"]
SIDE = [0.0, -2.0, 0.3, -2.4, 0.3, -2.8]
TURNS = [0.0, 3.0, -1.0]


def csv(v):
    return ",".join(map(str, v))


MIRROR = [-v if i % 2 == 0 else v for i, v in enumerate(SIDE)]
RUNS = {"turn": ["-die_path", csv(SIDE), "-die_path_turn", csv(TURNS), "-die_pivot", csv(PIVOT)],
        "mirror": ["-die_path", csv(MIRROR), "-die_path_turn", csv(-t for t in TURNS), "-die_pivot", csv(PIVOT)],
        "still": ["-die_path", csv(SIDE)],
        "still0": ["-die_path", csv(SIDE), "-die_path_turn", "0,0,0", "-die_pivot", csv(PIVOT)]}
RUNS["fine"] = RUNS["turn"] + ["-rmin_domega", FINE]
# H: a roller (a convex arc of radius 5 under a rising 45-degree line) down to U = 1, then turning in place about its
# centre, frictionless, both ways; 10 trial increments, so that a trial step would turn it by 2.9e-2 rad.
ROLLER = ["-die_profile", out("roller.profile"), "-friction_mu", 0, "-increments", 10, "-die_pivot", "0,22.5",
          "-die_path", "0,-2,0,-2"]
RUNS["roller+"] = ROLLER + ["-die_path_turn", "0,10"]
RUNS["roller-"] = ROLLER + ["-die_path_turn", "0,-10"]
with open(out("roller.profile"), "w") as f:
    f.write("arc 0 22.5 5 270 315\nline 3.5355339059327378 18.964466094067262 20 35.42893218813452\n")


def history(name):
    with h5py.File(out(name), "r") as h:
        return {c: h["/history"][c][:] for c in h["/history"]}


run_all(tf, mpirun, [BASE + RUNS[n] + ["-output", out(f"{n}.h5")] for n in RUNS], timeout=600)
run(tf, mpirun, 2, BASE + RUNS["turn"] + ["-output", out("turn_np2.h5")], timeout=600)
h = {n: history(f"{n}.h5") for n in list(RUNS) + ["turn_np2"]}
r = h["turn"]
press = r["stage"] == 0
load = np.abs(r["load"]).max()


def worst(a, b, columns):
    if a["stroke"].shape != b["stroke"].shape:
        return 1.0, f"rows {a['stroke'].shape[0]} and {b['stroke'].shape[0]}"
    rel = {c: np.abs(a[c] - b[c]).max() / max(np.abs(a[c]).max(), 1e-300) for c in columns}
    c = max(rel, key=rel.get)
    return rel[c], c


# A. Turns of 0.
a, b = h["still"], h["still0"]
w, c = worst(a, b, [c for c in a if c != "tool_moment"])
moved = a["tool_moment"] + PIVOT[1] * a["tool_fx"]  # (about the pivot: minus its y times the force along x)
wm = np.abs(moved - b["tool_moment"]).max() / (load * RO) if a["stroke"].shape == b["stroke"].shape else 1.0
k.check(w <= 1e-12 and wm <= 1e-9, f"A. -die_path_turn 0,0,0 changes nothing: within {w:.1e} ({c}; 1e-12), the "
        f"die's moment about the pivot {wm:.1e} (1e-9)")

# B. The die where the path puts it.
points = [(0.0, 0.0, 0.0)] + [(SIDE[i], SIDE[i + 1], TURNS[i // 2]) for i in range(0, len(SIDE), 2)]
with h5py.File(out("turn.h5"), "r") as f:
    lam, disp, drawn = f["/time"][:, 0], f["/tools/V-die/displacement"][:], f["/tools/V-die/vertices"][:]
pieces = [np.hypot(np.hypot(q[0] - p[0], q[1] - p[1]), RO * np.radians(q[2] - p[2]))
          for p, q in zip(points, points[1:])]
at = np.cumsum(pieces) / sum(pieces)  # (the load factor at each point: a turn counts as its arc at ro)
off, found = [], []
for lk, p in zip(at, points[1:]):
    rows = np.where(press & (np.abs(r["die_x"] - p[0]) <= 1e-12) & (np.abs(r["stroke"] + 0.5 * p[1]) <= 1e-12) &
                    (np.abs(r["die_turn"] - p[2]) <= 1e-12))[0]
    found.append(len(rows))
    t = np.radians(p[2])
    rot = np.array([[np.cos(t), -np.sin(t)], [np.sin(t), np.cos(t)]])
    placed = (drawn - PIVOT) @ rot.T + PIVOT + p[:2]
    step = np.where(np.abs(lam - lk) <= 1e-12)[0]
    off.append(np.abs(disp[step[0]] - (placed - drawn)).max() if len(step) else 1.0)
k.check(max(off) <= 1e-12, f"B. the die's outline in the results is the drawing turned about the pivot and moved "
        f"to the path's points at their output steps: off by {max(off):.1e} mm (1e-12)")
k.check(all(found), "B. the history's die_x, U and die_turn reach each point's x, -y / 2 and turn (" +
        ", ".join(f"{p[0]},{-0.5 * p[1]},{p[2]}: {n} row(s)" for p, n in zip(points[1:], found)) + ")")

# C. Energy.
late = r["stroke"] >= 0.1
err = np.abs(r["energy_error"][late]).max()
m, th = r["tool_moment"], np.radians(r["die_turn"])
share = abs(np.sum(0.5 * (m[1:] + m[:-1]) * np.diff(th))) / abs(r["w_ext"][press][-1])
k.check(err <= 5e-3 and share > 5e-3, f"C. energy balance from U = 0.1 mm within {err:.1e} (5e-3), the turn's "
        f"work {share:.1%} of the work put in")


# D. Equilibrium.
for t, label in ((r, "1 rank"), (h["turn_np2"], "2 ranks")):
    f, mo, hold = balance(t, RO, PIVOT)
    k.check(f <= 1 and mo <= 1, f"D. {label}: no net force on the hold ({f:.2g} of its bound) and the dies' moment "
            f"about the centre the hold's couple (largest {hold:.0f} N mm/mm; {mo:.2g} of its bound)")


# E. Mirror and ranks, at the path's points and the springback's end.
def marks(t):
    p = t["stage"] == 0
    at = [p & (np.abs(np.abs(t["die_x"]) - abs(q[0])) <= 1e-12) & (np.abs(t["stroke"] + 0.5 * q[1]) <= 1e-12)
          for q in points[1:]]
    rows = [np.where(a)[0][0] for a in at]
    return rows + [len(p) - 1]


for name, sign, label in (("mirror", -1, "the press mirrored is the mirror image"), ("turn_np2", 1, "2 ranks")):
    w, c = at_rows(r, h[name], marks(r), marks(h[name]), sign, RO,
                   ("tool_fx", "lower_fx", "tool_moment", "hold_moment"))
    k.check(w <= SWAY, f"E. {label}: within {w:.1e} ({c}; {SWAY:g})")

# F. A restart inside the turning piece.
ck = out("turn_ck.h5")
opts = BASE + RUNS["turn"] + ["-output", out("turn_part.h5")]
inside = int(np.where(press & (r["die_turn"] > 0.5) & (r["die_turn"] < 2.5))[0][0])
checkpoint_at(tf, mpirun, 1, opts, ck, inside, timeout=600)
run(tf, mpirun, 1, opts + ["-restart", ck], timeout=600)
w, c = worst(r, history("turn_part.h5"), list(r))
k.check(w <= 1e-12, f"F. continued from a checkpoint inside the turning piece (row {inside}): the history within "
        f"{w:.1e} ({c}; 1e-12)")

# G. The step's turn and what its chord leaves.
fine = h["fine"]
steps = np.abs(np.diff(np.radians(fine["die_turn"])))
r3 = (fine["limiter"] == 4).sum()
pen = r["penetration"][press].max()
chord = 0.5 * DOMEGA ** 2 * 2 * RO
k.check(steps.max() <= FINE * (1 + 1e-9), f"G. -rmin_domega {FINE:g}: the die turns by at most {steps.max():.3e} rad "
        f"an increment ({r3} increments cut by r3)")
k.check(pen <= chord, f"G. penetration {pen:.1e} mm (below {chord:.1e}: a turn of {DOMEGA:g} rad's chord over 2 ro)")

# H. A frictionless roller turning in place about its centre.
a, b = h["roller+"], h["roller-"]
t = np.radians(a["die_turn"])
turning = np.where(np.diff(t) > 0)[0] + 1  # (the turn's rows)
cut = (a["limiter"][turning] == 4) & (a["limiter_where"][turning] == -1)
at_bound = np.abs(np.diff(t)[turning - 1] - DOMEGA) <= 1e-9 * DOMEGA
k.check(cut.sum() >= len(turning) - 1 and (cut == at_bound).all(), f"H. the roller's turn: {cut.sum()} of its "
        f"{len(turning)} increments cut by its own r3 at {DOMEGA:g} rad (the rest the piece's end)")
w, c = worst(a, b, ["load", "x_max", "y_max", "w_int", "w_ext", "lower_fy", "c_over_t"])
k.check(w <= ROUND_OFF, f"H. turning it the other way changes nothing: within {w:.1e} ({c}; {ROUND_OFF:g})")
s, e = turning[0] - 1, turning[-1]
settle = a["n_contact"][s] * 0.005 * a["q_avg"][s]  # (-equilibrium_tol 0.005 of q at each contact node)
dload, dwork = abs(a["load"][e] - a["load"][s]), abs(a["w_ext"][e] - a["w_ext"][s]) / a["w_ext"][s]
k.check(dload <= settle and dwork <= 1e-12, f"H. over the turn the load moves by {dload:.1e} N/mm (at most what the "
        f"equilibrium iterations may still settle, {settle:.2g}) and the die does no work ({dwork:.0e} of the work; "
        f"1e-12)")
k.done()
