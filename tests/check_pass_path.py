"""A later pass's upper die on a path of its own (-pass2_die_path: the first pass's -die_path, read and made by the
same code under the prefix pass2_die_; docs/passes.md, "A later pass on a path of its own").

The paper's tube (options/squaring.opts, the fast preset), pressed 1.5 mm over a floor that stays (-lower_die flat
-lower_die_motion fixed: the upper die travels 2 U), sprung back (the paper's unloading), pressed again:
A. A second pass by a path straight down is the second pass by the stroke: `-pass2_die_path 0,-3` against
   `-pass2_stroke 1.5`, every /history dataset and attribute (the metrics) the same bit for bit (the same arithmetic
   by construction: the path's parameter runs over half its length, its motion (0, -2) per unit exactly, U = -y / 2
   = its parameter; a later pass's U read from its path, not from its stroke, or its path's length taken whole,
   differs at O(1)).
B. The same after a quarter turn (-pass2_turn 90, the full model): the die then starts moved back along its motion
   to where it touches the tube the springback left (b > 0: pass2_start_stroke = -b), and its path runs from there;
   `-pass2_die_path 0,-2(1.5 + b)` is `-pass2_stroke 1.5` bit for bit (the path mapped into the turned press's frame,
   moved back along its first piece, its U counted from where it starts): every /history dataset and attribute but
   pass2_stroke_target (the path's -y / 2 from where it starts: 1.5 + b).
C. Sideways in the second pass (the full model under the rotation hold, a first pass of 1 mm):
   `-pass2_die_path 0,-2.6,0.5,-2.6,0.5,-3`, down to U = 1.3, 0.5 mm to the right, down to U = 1.5. The die passes
   through the points: its outline in the results (/tools/pass2-V-die/displacement) at the field steps at the
   path's turns and end (lambda 2 + their share of its length: the load path's kinks in the second press) is
   displaced by them within 1e-12 mm, and the history's die_x and U reach each point's x and -y / 2 there (1e-12).
D. Energy in that second press: the run's energy balance (energy_error: the dies' work from their reported forces
   along both of the upper die's motions, tool_fy over 2 U and tool_fx over die_x) within 5e-3 at every row of the
   press (tests/check_die_path.py C's bound), while the sideways work (tool_fx over die_x, from the history) is more
   than 5e-3 of the press's work put in: a balance that left it out, or a die_x that stayed 0, fails.
E. Equilibrium of the tube at every row of the second press, as tests/check_die_path.py D: no net force on the hold
   (tool_fx + lower_fx) and the dies' moment about the centre (the upper die's frame origin at (die_x, -2 U), the
   floor's at the centre) the hold's couple, within n_contact (residual + fn_mismatch) (times Ro for the moment).
F. Bad input, each refused in one line naming -pass2_die_path, a non-zero exit, no results file: with
   -pass2_stroke (the path is in place of it), over a lower die that moves (-lower_die_motion mirror), sideways
   in the half model (-model half) and in the full model held by its pins (-full_hold pins).
G. C's press with neither -model nor -full_hold: `auto` chooses the full model (the run says so) under the rotation
   hold for the sideways pass, and the history is C's within 5e-4 of each column's largest value (load, U, die_x,
   C1, C2, C1/C2, internal work; not C/t, which this shallow press leaves at round-off's 3.5e-8). C holds its
   first pass by the rotation hold, this run by the pins (-full_hold auto: the first pass is symmetric): both exact
   there, the first pass agrees to round-off (7e-13 measured) and the sideways press carries the difference on, as
   it carries any round-off: C's own history moves by up to 4.3e-5 of the load (5.3e-7 on OpenBLAS's Haswell
   kernel, 4.3e-5 on Prescott; U 2.0e-5, the internal work 2.7e-5) under a perturbation of 1.3e-13 in E
   (-material_e 75000.00000000975), and 5e-4 is about ten times that, as tests/check_die_path.py E bounds its
   mirror image (measured 1.1e-6 on Haswell, 4.7e-5 on Prescott). Before `auto` looked at a later pass's path it
   refused the run.
H. The first pass on a path of its own, then a later pass: `-die_path 0,-3 -pass2_stroke 1.5` is A's `-stroke 1.5
   -pass2_stroke 1.5`, every /history dataset and attribute the same bit for bit (the first pass's path straight down
   is its stroke by the same construction as A's; a later pass after it starts from where the first pass's springback
   left the tube, as after any first pass).
"""
import os

import h5py
import numpy as np

from tfcheck import Checks, args, history_and_tools, out, run, run_all

tf, mpirun, src = args()
k = Checks("pass_path")
RO, U = 17.5, 1.5
BASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-progress", 0, "-error_estimate", 0, "-lower_die", "flat", "-lower_die_motion", "fixed", "-stroke", U]
SIDE = [0.0, -2.6, 0.5, -2.6, 0.5, -3.0]
RUNS = {"stroke": ["-pass2_stroke", U], "path": ["-pass2_die_path", f"0,{-2 * U}"],
        "turned_stroke": ["-pass2_turn", 90, "-pass2_stroke", U],
        "side": ["-stroke", 1, "-model", "full", "-full_hold", "rotation", "-pass2_die_path", ",".join(map(str, SIDE))],
        "side_auto": ["-stroke", 1, "-pass2_die_path", ",".join(map(str, SIDE))],
        "first_path": ["-die_path", f"0,{-2 * U}", "-pass2_stroke", U]}
done = run_all(tf, mpirun, [BASE + RUNS[n] + ["-output", out(f"pp_{n}.h5")] for n in RUNS], timeout=600,
               check=False)
for n, p in zip(RUNS, done):
    if n != "side_auto" and p.returncode != 0:
        raise SystemExit(f"{n}: tubeform failed (exit {p.returncode}): {(p.stdout + p.stderr).strip()[-300:]}")


def same_bits(a, b, skip=()):
    """Whether two result files' histories are the same bit for bit, their attributes (the metrics) too but those in
    `skip`: which dataset or attribute differs first, or ""."""
    with h5py.File(a, "r") as fa, h5py.File(b, "r") as fb:
        ha, hb = fa["/history"], fb["/history"]
        if sorted(ha) != sorted(hb):
            return "the datasets' names"
        for c in ha:
            if ha[c].shape != hb[c].shape or ha[c][:].tobytes() != hb[c][:].tobytes():
                return c
        if sorted(ha.attrs) != sorted(hb.attrs):
            return "the attributes' names"
        for c in ha.attrs:
            if c not in skip and np.asarray(ha.attrs[c]).tobytes() != np.asarray(hb.attrs[c]).tobytes():
                return c
    return ""


# A. Straight down.
w = same_bits(out("pp_stroke.h5"), out("pp_path.h5"))
k.check(not w, f"A. -pass2_die_path 0,{-2 * U:g} is -pass2_stroke {U:g}: every history dataset and attribute (the "
        f"metrics: pass2_stroke_target {U:g}, the path's -y / 2) the same bit for bit ({w or 'none differs'})")

# B. Turned, started back.
with h5py.File(out("pp_turned_stroke.h5"), "r") as f:
    back = -f["/history"].attrs["pass2_start_stroke"]
y = repr(-2 * (U + back))
run(tf, mpirun, 1, BASE + ["-pass2_turn", 90, "-pass2_die_path", f"0,{y}", "-output", out("pp_turned_path.h5")],
    timeout=600)
w = same_bits(out("pp_turned_stroke.h5"), out("pp_turned_path.h5"), ("pass2_stroke_target",))
k.check(back > 0 and not w, f"B. -pass2_turn 90: the die starts {back:.4g} mm of U back; -pass2_die_path 0,{y} is "
        f"-pass2_stroke {U:g}: every history dataset and attribute but pass2_stroke_target the same bit for bit "
        f"({w or 'none differs'})")

# C. Sideways: the die through the points.
r = history_and_tools(out("pp_side.h5"))
press = r["stage"] == 2
with h5py.File(out("pp_side.h5"), "r") as f:
    lam, start = f["/time"][:, 0], f["/history"].attrs["pass2_start_stroke"]
points = [(0.0, 0.0)] + [(SIDE[i], SIDE[i + 1]) for i in range(0, len(SIDE), 2)]
pieces = [np.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(points, points[1:])]
at = 2 + np.cumsum([0] + pieces) / sum(pieces)
off = []
for lk, p in zip(at[1:], points[1:]):
    step = np.where(np.abs(lam - lk) <= 1e-12)[0]
    off.append(np.abs(r["tools"]["pass2-V-die"][step[0]] - p).max() if len(step) else 1.0)
k.check(start == 0 and max(off) <= 1e-12, f"C. the second pass's die, started where it touches the round tube (U = "
        f"{start:g}), displaced by the path's points at its turns and end: off by {max(off):.1e} mm (1e-12)")
rows = [np.where(press & (np.abs(r["die_x"] - p[0]) <= 1e-12) & (np.abs(r["stroke"] + 0.5 * p[1]) <= 1e-12))[0]
        for p in points[1:]]
k.check(all(len(i) for i in rows), "C. the history's die_x and U reach each point's x and -y / 2 (" +
        ", ".join(f"{p[0]},{-0.5 * p[1]}: {len(i)} row(s)" for p, i in zip(points[1:], rows)) + ")")

# D. Energy in the second press.
err = np.abs(r["energy_error"][press]).max()
dx, fx, rows = r["die_x"], r["tool_fx"], np.where(press)[0]  # (die_x: 0 until the second press, which moves it)
sideways = abs(np.sum(0.5 * (fx[1:] + fx[:-1]) * np.diff(dx)))
share = sideways / abs(r["w_ext"][rows[-1]] - r["w_ext"][rows[0] - 1])
k.check(err <= 5e-3 and share > 5e-3, f"D. the second press's energy balance within {err:.1e} (5e-3), its sideways "
        f"work {share:.1%} of the work put in")

# E. Equilibrium in the second press.
bound = (r["n_contact"] * (r["residual"] + r["fn_mismatch"]))[press]
force = np.abs(r["tool_fx"] + r["lower_fx"])[press]
dies = r["tool_moment"] + r["die_x"] * r["tool_fy"] + 2 * r["stroke"] * r["tool_fx"] + r["lower_moment"]
moment = np.abs(dies - r["hold_moment"])[press]
f_, m_ = np.max(force / np.maximum(bound, 1e-300)), np.max(moment / np.maximum(RO * bound, 1e-300))
k.check(f_ <= 1 and m_ <= 1, f"E. no net force on the hold ({f_:.2g} of its bound) and the dies' moment about the "
        f"centre the hold's couple (largest {np.abs(r['hold_moment'][press]).max():.0f} N mm/mm; {m_:.2g} of its "
        f"bound)")

# F. Bad input.
BAD = {"with -pass2_stroke": ["-pass2_stroke", U, "-pass2_die_path", "0,-3"],
       "over a lower die that moves": ["-lower_die_motion", "mirror", "-pass2_die_path", "0,-3"],
       "sideways in the half model": ["-model", "half", "-pass2_die_path", "0,-2,0.5,-3"],
       "sideways held by the pins": ["-model", "full", "-full_hold", "pins", "-pass2_die_path", "0,-2,0.5,-3"]}
for label, extra in BAD.items():
    f = out("pp_bad.h5")
    if os.path.exists(f):
        os.remove(f)
    p = run(tf, mpirun, 1, BASE + extra + ["-output", f], check=False, timeout=60)
    lines = [l for l in (p.stdout + p.stderr).splitlines() if "error" in l.lower()]
    k.check(p.returncode != 0 and len(lines) == 1 and "-pass2_die_path" in lines[0] and not os.path.exists(f),
            f"F. {label}: exit {p.returncode}, refused in one line: {lines[0] if lines else '(none)'}")

# G. -model auto, -full_hold auto: C's press.
auto = done[list(RUNS).index("side_auto")]
full = "(the full model" in auto.stdout
gap, col = 1.0, "the run"
if auto.returncode == 0:
    with h5py.File(out("pp_side.h5"), "r") as fc, h5py.File(out("pp_side_auto.h5"), "r") as fa:
        hc, ha = fc["/history"], fa["/history"]
        cols = ("load", "stroke", "die_x", "x_max", "y_max", "deviation_ratio", "w_int")  # (C/t: 0 in this press)
        if all(ha[c].shape == hc[c].shape for c in cols):
            gaps = {c: np.abs(ha[c][:] - hc[c][:]).max() / np.abs(hc[c][:]).max() for c in cols}
            col = max(gaps, key=gaps.get)
            gap = gaps[col]
        else:
            col = "the rows"
k.check(auto.returncode == 0 and full and gap <= 5e-4, f"G. neither -model nor -full_hold: exit {auto.returncode}, "
        f"the full model {'said' if full else 'not said'}, C's history within {gap:.1e} ({col}; 5e-4)")

# H. A first pass on a path, then a later pass.
w = same_bits(out("pp_stroke.h5"), out("pp_first_path.h5"))
k.check(done[list(RUNS).index("first_path")].returncode == 0 and not w, f"H. -die_path 0,{-2 * U:g} then "
        f"-pass2_stroke {U:g} is -stroke {U:g} then -pass2_stroke {U:g}: every history dataset and attribute the same "
        f"bit for bit ({w or 'none differs'})")
k.done()
