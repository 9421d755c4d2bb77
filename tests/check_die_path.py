"""The upper die's own path (-die_path: a prescribed path in time, piecewise linear; docs/motions.md, "The die's
own path").

The paper's tube (options/squaring.opts, fast preset), the lower V-die staying (-lower_die_motion fixed), the upper
one through the given points in turn; its stroke parameter runs along half the path's length, and U = -y / 2.
A. A path straight down in pieces is the press the stroke takes (-stroke_path): `-die_path 0,-1,0,-3` against
   `-stroke_path 0.5,1.5` the same history to 1e-12 of each column's largest value (the same arithmetic by
   construction: the parameter is U and the motion (0, -2) exactly; measured 0). A path that backs off,
   `0,-1,0,-0.6,0,-3` against `-stroke_path 0.5,0.3,1.5`, within 1e-4: after the turn the friction iterations
   start from the slip per unit stroke of the piece before (the stroke path's runs on with its sign, the die
   path's parameter does not turn back), so they stop at another iterate within the preset's -friction_tol
   (1e-3 of mu f_n on each node's force; measured 7.7e-7 of the load): U, load, C/t, C1, C2, the works (the
   increments' other columns, the nodes that limited them, may differ).
B. Sideways: `0,-2,0.5,-2,0.5,-2.6` (down to U = 1, 0.5 mm to the right at that height, down to U = 1.3) in the
   full model under the rotation hold. The die passes through the given points: its outline in the results
   (/tools/V-die/displacement) at the output steps at the path's turns and end is displaced by them, within
   1e-12 mm; the history's die_x and U there are the points' x and -y / 2 (within 1e-12 mm).
C. The energy balance (self-check (a): the upper die's work from its reported forces along both of its motions,
   tool_fy over 2 U and tool_fx over die_x) within 5e-3 at every increment from U = 0.1 mm (tests/check_hold.py
   D's bound); the sideways work is more than that share of the work put in (1.8 % here), so a balance without
   it fails.
D. Equilibrium of the tube at every loading increment, as tests/check_hold.py B: no net force on the hold
   (tool_fx + lower_fx) and the dies' moment about the centre (the upper die's frame origin at (die_x, -2 U),
   the lower one's at the centre) the hold's couple, within n_contact (residual + fn_mismatch) (times Ro for the
   moment); on 1 and 2 ranks.
E. The path mirrored (x -> -x) is the mirror image, and 2 ranks the same press, at the path's turns, its end and
   the springback's: load, C1, C2, internal work the same, the sideways forces and the couple of opposite sign
   in the mirror, within 1e-3 of the load (of the load times Ro for the couple, of Ro for C1 and C2): ten times
   what a perturbation of 1.3e-13 in E moves them (1.1e-4 of the load at U = 1 mm: -material_e
   75000.00000000975 and 74999.99999999025; the full model under the hold sways by round-off, which the
   contact events then take in another order: tests/check_hold.py G's bound). Measured: the mirror 6.7e-5, 2
   ranks 2.3e-4.
F. A checkpoint inside the sideways piece, continued: the history within 1e-12 (tests/check_restart.py's bound):
   the piece a step runs on follows from the stroke, not from a state.
"""
import h5py
import numpy as np

from die_press import at_rows, balance
from tfcheck import Checks, args, checkpoint_at, out, run, run_all

tf, mpirun, src = args()
k = Checks("die_path")
RO = 17.5
BASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-progress", 0, "-error_estimate", 0, "-unload", "reverse", "-lower_die_motion", "fixed"]
SIDE = [0.0, -2.0, 0.5, -2.0, 0.5, -2.6]
RUNS = {"path": ["-die_path", "0,-1,0,-3"], "stroke": ["-stroke_path", "0.5,1.5"],
        "path_back": ["-die_path", "0,-1,0,-0.6,0,-3"], "stroke_back": ["-stroke_path", "0.5,0.3,1.5"],
        "right": ["-die_path", ",".join(map(str, SIDE))],
        "left": ["-die_path", ",".join(str(-v if i % 2 == 0 else v) for i, v in enumerate(SIDE))]}


def history(name):
    with h5py.File(out(name), "r") as h:
        return {c: h["/history"][c][:] for c in h["/history"]}


run_all(tf, mpirun, [BASE + RUNS[n] + ["-output", out(f"{n}.h5")] for n in RUNS], timeout=600)
run(tf, mpirun, 2, BASE + RUNS["right"] + ["-output", out("right_np2.h5")], timeout=600)
h = {n: history(f"{n}.h5") for n in list(RUNS) + ["right_np2"]}


# A. Straight down in pieces.
def worst(a, b, columns=None):
    if a["stroke"].shape != b["stroke"].shape:
        return 1.0, f"rows {a['stroke'].shape[0]} and {b['stroke'].shape[0]}"
    rel = {c: np.abs(a[c] - b[c]).max() / max(np.abs(a[c]).max(), 1e-300) for c in columns or a}
    c = max(rel, key=rel.get)
    return rel[c], c


w, c = worst(h["stroke"], h["path"])
k.check(w <= 1e-12, f"A. -die_path 0,-1,0,-3 is -stroke_path 0.5,1.5: within {w:.1e} ({c}; 1e-12)")
w, c = worst(h["stroke_back"], h["path_back"], ["stroke", "load", "x_max", "y_max", "c_over_t", "w_int", "w_ext"])
k.check(w <= 1e-4, f"A. -die_path 0,-1,0,-0.6,0,-3 is -stroke_path 0.5,0.3,1.5: within {w:.1e} ({c}; 1e-4)")

# B. The die through the points.
r = h["right"]
points = [(0.0, 0.0)] + [(SIDE[i], SIDE[i + 1]) for i in range(0, len(SIDE), 2)]
length = sum(np.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(points, points[1:]))
at = np.cumsum([0] + [np.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(points, points[1:])]) / length
with h5py.File(out("right.h5"), "r") as f:
    lam, disp = f["/time"][:, 0], f["/tools/V-die/displacement"][:, 0, :]
off = []
for lk, p in zip(at[1:], points[1:]):
    step = np.where(np.abs(lam - lk) <= 1e-12)[0]
    off.append(np.hypot(*(disp[step[0]] - p)) if len(step) else 1.0)
k.check(max(off) <= 1e-12, f"B. the die's outline in the results passes through the path's points at its turns "
        f"and end: off by {max(off):.1e} mm (1e-12)")
press = r["stage"] == 0
rows = [np.where(press & (np.abs(r["die_x"] - p[0]) <= 1e-12) & (np.abs(r["stroke"] + 0.5 * p[1]) <= 1e-12))[0]
        for p in points[1:]]
k.check(all(len(i) for i in rows), "B. the history's die_x and U reach each point's x and -y / 2 (" +
        ", ".join(f"{p[0]},{-0.5 * p[1]}: {len(i)} row(s)" for p, i in zip(points[1:], rows)) + ")")

# C. Energy.
late = r["stroke"] >= 0.1
err = np.abs(r["energy_error"][late]).max()
dx, fx = r["die_x"], r["tool_fx"]
share = abs(np.sum(0.5 * (fx[1:] + fx[:-1]) * np.diff(dx))) / abs(r["w_ext"][press][-1])
k.check(err <= 5e-3 and share > 5e-3, f"C. energy balance from U = 0.1 mm within {err:.1e} (5e-3), the sideways "
        f"work {share:.1%} of the work put in")


# D. Equilibrium.
for t, label in ((r, "1 rank"), (h["right_np2"], "2 ranks")):
    f, mo, hold = balance(t, RO)
    k.check(f <= 1 and mo <= 1, f"D. {label}: no net force on the hold ({f:.2g} of its bound) and the dies' moment "
            f"about the centre the hold's couple (largest {hold:.0f} N mm/mm; {mo:.2g} of its bound)")


# E. Mirror and ranks, at the path's turns, its end and the springback's.
def marks(t):
    p = t["stage"] == 0
    first = np.where(p & (np.abs(t["die_x"]) <= 1e-12))[0][-1]
    side = np.where(p & (np.abs(np.abs(t["die_x"]) - 0.5) <= 1e-12))[0][0]
    return [first, side, np.where(p)[0][-1], len(p) - 1]


for name, sign, label in (("left", -1, "the path mirrored is the mirror image"), ("right_np2", 1, "2 ranks")):
    w, c = at_rows(r, h[name], marks(r), marks(h[name]), sign, RO)
    k.check(w <= 1e-3, f"E. {label}: within {w:.1e} ({c}; 1e-3)")

# F. A restart inside the sideways piece.
ck = out("right_ck.h5")
opts = BASE + RUNS["right"] + ["-output", out("right_part.h5")]
inside = int(np.where(press & (r["die_x"] > 0.1) & (r["die_x"] < 0.4))[0][0])
checkpoint_at(tf, mpirun, 1, opts, ck, inside, timeout=600)
with h5py.File(ck, "r") as c:
    lam_ck = c["/run/lambda"][0]
run(tf, mpirun, 1, opts + ["-restart", ck], timeout=600)
w, c = worst(r, history("right_part.h5"))
k.check(w <= 1e-12 and at[1] < lam_ck < at[2], f"F. continued from a checkpoint inside the sideways piece (lambda "
        f"{lam_ck:.3f}): the history within {w:.1e} ({c}; 1e-12)")
k.done()
