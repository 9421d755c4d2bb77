"""Lower and side dies of a shape of their own (-lower_die v, -side_die v: the shape registry's V kind, its numbers
read under the die's prefix, -lower_die_angle, -side_die_r_apex, ...; scenes/options/die_shape_options.cpp):

A. -lower_die v with the paper's numbers (its defaults) is the upper die's mirror image: the history of
   -lower_die mirror -model half (both the half model), every column bit for bit. (Here and below the tools' outlines
   as written, /tools/<die>/vertices, are compared too: a number that only the outline shows, an apex fillet the tube
   never reaches, is checked there.)
B. -lower_die v -lower_die_angle 80 -lower_die_r_apex 2: the die the contact sees is the V-die whose geometry is computed here
   (docs/dies.md: flanks touching the tube, the apex fillet's centre on the axis) and written as a profile file given
   to -lower_die: the same history bit for bit (the V kind draws through the profile's construction, which makes that
   possible; any slip of the angle, the apex or the mirroring moves the loads at the 1e-3 level). The tube between two
   different dies: the lower die's vertical force equals the upper one's (the tube's equilibrium) within 1 % of the
   largest load (the run's inertia and equilibrium tolerance, 0.005 of the force scale, are the gap).
C. -side_die v with the paper's numbers is -side_die mirror (the upper die turned to the side), and with -side_die_angle
   120 -side_die_r_apex 4 the profile of that V given to -side_die: bit for bit.
D. A later pass: with no word of its own it takes the first pass's lower V and its numbers, as -pass2_lower_die v
   does (bit for bit); -pass2_lower_die v -pass2_lower_die_angle 80 -pass2_lower_die_r_apex 2 is the profile of that V
   given to -pass2_lower_die, bit for bit.
E. Refused in one line naming the option: a number without the word (-lower_die_angle 80 alone), a number the V
   kind refuses (-side_die v -side_die_angle 200), a later pass's number where its die is no V, the quarter model with
   a lower die that is no mirror.
"""
import math

import h5py
import numpy as np

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
k = Checks("die_shape_own")
RO = 17.5  # options/squaring.opts
BASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-error_estimate", 0, "-progress", 0]
LOADED = ["-stroke", 2.5, "-unload", "none"]
# The tube's equilibrium between the dies: the run ends each increment at R_max <= 0.005 of the force scale and
# carries inertia (-dynamics implicit at the punch speed); 1 % of the largest load bounds both with margin.
BALANCE = 0.01


def press(name, extra):
    """The run's history columns, and its tools' outlines as written (/tools/<die>/vertices) under "tool <k>", k
    their order by name (the upper die's first; a die of its own is named as a file's, a mirror after its die)."""
    run(tf, mpirun, 1, BASE + extra + ["-output", out(name)])
    with h5py.File(out(name), "r") as h:
        cols = {c: h["/history"][c][:] for c in h["/history"]}
        cols.update({f"tool {i}": h["/tools"][t]["vertices"][:] for i, t in enumerate(sorted(h["/tools"]))})
        return cols


def same(a, b):
    """The columns (and tool outlines) of a and b that differ (names, shapes or any bit)."""
    differ = sorted(set(a) ^ set(b))
    for c in set(a) & set(b):
        if a[c].shape != b[c].shape or a[c].tobytes() != b[c].tobytes():
            differ.append(c)
    return differ


def v_profile(angle, r_apex):
    """The V-die of docs/dies.md as a profile, from its geometry: the flanks of `angle` degrees touch the tube
    (they meet on the axis at h = Ro / sin(half)), the apex fillet's centre on the axis r_apex / sin(half) below,
    the flank to x = 1.3 Ro; in the arithmetic of src/tool/shape_v.cpp (1 / sin and 1 / cos first), so that the
    profile's numbers are the V kind's to the last bit."""
    half = angle * math.pi / 360
    qs, qc = 1 / math.sin(half), 1 / math.cos(half)
    h = RO * qs
    cy = h - r_apex * qs
    x0, y0 = r_apex / qc, cy + r_apex / qs
    return f"arc 0 {cy!r} {r_apex!r} 90 {angle / 2!r}\nline {x0!r} {y0!r} {1.3 * RO!r} {h - 1.3 * RO * (qs / qc)!r}\n"


def against_profile(name, base, die, angle, r_apex):
    """The die option `die` (-lower_die, -side_die, -pass2_lower_die) given v with these numbers, and given the profile
    of that V written here, each pressed after `base`: both runs and the columns that differ between them."""
    with open(out(f"{name}.profile"), "w") as f:
        f.write(v_profile(angle, r_apex))
    own = press(f"{name}.h5", base + [die, "v", f"{die}_angle", angle, f"{die}_r_apex", r_apex])
    drawn = press(f"{name}_file.h5", base + [die, out(f"{name}.profile")])
    return own, drawn, same(own, drawn)


# A.
mirror = press("mirror.h5", LOADED + ["-lower_die", "mirror", "-model", "half"])
v90 = press("v90.h5", LOADED + ["-lower_die", "v"])
d = same(mirror, v90)
k.check(not d, f"A: -lower_die v (the paper's numbers) is -lower_die mirror -model half bit for bit "
        f"({len(mirror['load'])} rows; differing: {d[:5]})")

# B.
v80, drawn, d = against_profile("v80", LOADED, "-lower_die", 80, 2.0)
k.check(not d, f"B: -lower_die v -lower_die_angle 80 -lower_die_r_apex 2 is that V-die drawn as a profile here, bit "
        f"for bit (differing: {d[:5]}; end loads {v80['load'][-1]:.6g}, {drawn['load'][-1]:.6g} N/mm)")
# (lower_fy: the force the tube puts on the lower die, the half model's, downwards; the punch load is twice the upper
# die's on the half)
gap = np.max(np.abs(2 * v80["lower_fy"] + v80["load"])) / np.max(np.abs(v80["load"]))
k.check(gap < BALANCE, f"B: the lower die carries the upper one's load: largest gap {gap:.2e} of the largest load "
        f"(< {BALANCE})")

# C.
SIDE = ["-stroke", 1.5, "-unload", "none"]
smirror = press("side_mirror.h5", SIDE + ["-side_die", "mirror"])
sv = press("side_v.h5", SIDE + ["-side_die", "v"])
d = same(smirror, sv)
k.check(not d and np.max(smirror["side_load"]) > 0,
        f"C: -side_die v (the paper's numbers) is -side_die mirror bit for bit (differing: {d[:5]}; side load up to "
        f"{np.max(smirror['side_load']):.4g} N/mm)")
sv120, _, d = against_profile("side_v120", SIDE, "-side_die", 120, 4.0)
k.check(not d and sv120["side_load"].tobytes() != sv["side_load"].tobytes(),
        f"C: -side_die v -side_die_angle 120 -side_die_r_apex 4 is that V-die drawn as a profile here, bit for bit "
        f"(differing: {d[:5]}), and not the paper's")

# D. (a later pass's numbers as the upper die's: from the first pass's die where it is a V, else the paper's)
PASS2 = ["-stroke", 1.5, "-pass2_stroke", 2.5, "-pass2_unload", "none", "-model", "half"]
first80 = ["-lower_die", "v", "-lower_die_angle", 80, "-lower_die_r_apex", 2]
taken = press("pass_taken.h5", PASS2 + first80)
again = press("pass_again.h5", PASS2 + first80 + ["-pass2_lower_die", "v"])
d = same(taken, again)
k.check(not d, f"D: a second pass takes the first pass's lower V with its numbers, as -pass2_lower_die v does "
        f"(differing: {d[:5]})")
p_v80, _, d = against_profile("pass_v80", PASS2, "-pass2_lower_die", 80, 2.0)
p_mirror = press("pass_mirror.h5", PASS2)
k.check(not d and p_v80["load"].tobytes() != p_mirror["load"].tobytes(),
        f"D: -pass2_lower_die v -pass2_lower_die_angle 80 -pass2_lower_die_r_apex 2 is that V-die drawn as a profile "
        f"for the second pass, bit for bit (differing: {d[:5]}), and not the mirror")

# E.
PASS2_NONE = ["-stroke", 1.5, "-pass2_stroke", 2.5, "-pass2_unload", "none"]
for extra, needle in [
        (LOADED + ["-lower_die_angle", 80], "-lower_die_angle: a number of a v die of its own; give -lower_die v"),
        (LOADED + ["-side_die", "v", "-side_die_angle", 200], "-side_die_angle 200"),
        (PASS2_NONE + ["-pass2_lower_die_angle", 80],
         "-pass2_lower_die_angle: a number of a v die of its own; give -pass2_lower_die v"),
        (LOADED + ["-model", "quarter", "-lower_die", "v"], "-model quarter")]:
    p = run(tf, mpirun, 1, BASE + extra + ["-output", out("refused.h5")], check=False)
    lines = [l for l in (p.stderr + p.stdout).splitlines() if l.startswith("tubeform: error")]
    k.check(p.returncode == 1 and len(lines) == 1 and needle in lines[0],
            f"E: {' '.join(map(str, extra))}: exit {p.returncode}, {lines[:1]}")
k.done()
