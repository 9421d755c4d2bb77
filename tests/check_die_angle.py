"""The V-die's angle (-die_angle): the die of any angle between 60 and 150 degrees against its closed
form, and the runs on it (options/squaring.opts, fast preset, 2 ranks).

1. The outline written to the result (/tools/V-die/vertices) at 60, 75, 120 and 150 degrees: the flank's
   points on one line at distance Ro from the tube's centre (the flanks touch the outer circle) at the
   half-angle to the vertical, the apex fillet's points at r_apex from a centre on the axis, tangent to the
   flank (the fillet's end and the flank's start, the same point, on both). Round-off bounds (1e-12 mm).
2. The paper's stroke rule for a rhombic cavity (-stroke_corner_radius 4 t): the stroke the run took leaves a
   cavity whose corners rounded by 4 t have the tube's perimeter 2 pi Ro. Reference computed here by Steiner's
   formula (the rounded rhombus is the inner parallel rhombus, its inradius less rc, grown by a disk: perimeter
   P_inner + 2 pi rc), not the code's corner-cutting sum. Within 1e-12 relative.
3. Frictionless pressing (-friction_mu 0) to U = 1 mm: the contact forces the file holds on nodes on the flank
   are along the flank's normal (within 1e-9 of their magnitude), so the die the contact sees is the one
   written; the run finishes with the self-checks within 5 % (tests/check_extremes.py's bound) at both ends
   of the range.
4. -die_angle 90 is the paper's die: the same history as without the option, bit for bit.
5. A second pass's own V-die (-pass2_die_angle 75 after a first pass at -die_angle 120, frictionless, 1 mm each):
   each pass's outline in the result is its own angle's (/tools/V-die's flank points as in 1 at 120 degrees;
   /tools/pass2-V-die, drawn where it starts, its flank, the longest segment, at 75 degrees' half-angle to the
   vertical within 1e-9 degrees), and at the end of the second press the contact forces on nodes at the second die's flank line (its outline
   moved by its displacement there) are along that flank's normal within 1e-9, so the die the contact sees is the
   pass's own. A pass's numbers default to the first pass's: -pass2_die_r_apex given at the first pass's value
   leaves the history of the run without it, bit for bit (the 120-degree die in both passes).
"""
import math

import h5py
import numpy as np

from tfcheck import Checks, args, out, run, run_all

tf, mpirun, src = args()
k = Checks("die_angle")
RO, T, RA = 17.5, 1.5, 3.0  # options/squaring.opts
BASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-error_estimate", 0, "-progress", 0]


def press(angle, extra, name, np_=2):
    f = out(name)
    if np_ > 1:
        run(tf, mpirun, np_, BASE + ["-die_angle", angle, "-output", f] + list(extra))
    else:
        assert name in SINGLE, name  # (run already, SINGLE below)
    return h5py.File(f, "r")


# The single-rank presses (items 2, 4 and 5 below) two at a time before the checks read them.
TWO = ["-friction_mu", 0, "-stroke", 1.0, "-pass2_stroke", 1.5]
SINGLE = {f"rule_{angle}.h5": [angle, "-stroke_corner_radius", 4 * T, "-friction_mu", 0] for angle in (75, 120)}
SINGLE.update({"die_90.h5": [90], "pass2_default.h5": [120] + TWO + ["-pass2_die_r_apex", RA],
               "pass2_none.h5": [120] + TWO})
run_all(tf, mpirun, [BASE + ["-die_angle", o[0], "-output", out(name)] + o[1:] for name, o in SINGLE.items()] +
        [BASE + ["-output", out("die_default.h5")]])


def outline(V, angle):
    """Which of the outline's points V lie on the flank of a V-die of `angle` (at distance Ro from the tube's centre
    along its normal) and which on the apex fillet's circle."""
    half = math.radians(angle / 2)
    n = np.array([-math.cos(half), -math.sin(half)])
    centre = np.array([0.0, RO / math.sin(half) - RA / math.sin(half)])
    return np.abs(-(V @ n) - RO) < 1e-12, np.abs(np.hypot(*(V - centre).T) - RA) < 1e-12


for angle in (60, 75, 120, 150):
    half = math.radians(angle / 2)
    n = np.array([-math.cos(half), -math.sin(half)])  # the flank's normal, towards the tube
    with press(angle, ["-friction_mu", 0, "-stroke", 1.0], f"die_{angle}.h5") as h:
        V = h["/tools/V-die/vertices"][:]
        j = int(np.flatnonzero(h["/time"][:, 0] <= 1 + 1e-12)[-1])
        X, u = h["/geometry/vertices"][:], h["/vertex_fields/displacement_u"][j]
        F, S = h["/vertex_fields/contact_force"][j], h["/vertex_fields/contact_state"][j]
        U = h["/history/stroke"][:][h["/history/stage"][:] == 0][-1]
        H = h["/history"]
        checks = max(np.abs(H["energy_error"][10:]).max(), np.abs(H["internal_error"][10:]).max())
    # 1. The outline: flank points at distance Ro along n from the centre, the fillet's on its circle.
    on_flank, on_arc = outline(V, angle)
    k.check(on_flank.sum() >= 2 and on_arc.sum() >= 3 and (on_arc | on_flank).all() and (on_arc & on_flank).sum() == 2,
            f"{angle} deg: the outline's {on_flank.sum()} flank points at Ro from the centre along the normal, "
            f"{on_arc.sum()} fillet points on its circle; the fillet's end and the flank's start on both (tangent)")
    # 3. Contact forces along the normal on the flank (nodes at the flank line in the current geometry).
    xc = X + u
    flank_nodes = (S > 0.5) & (np.abs(-(xc @ n) - (RO - U * math.sin(half))) < 1e-6)
    mag = np.hypot(F[:, 0], F[:, 1])
    off = np.abs(F[:, 0] * n[1] - F[:, 1] * n[0])  # the force's component along the flank
    k.check(flank_nodes.any() and (off[flank_nodes] <= 1e-9 * mag[flank_nodes]).all() and checks < 0.05,
            f"{angle} deg, mu 0, U {U:g}: {flank_nodes.sum()} nodes on the flank, their forces along its normal "
            f"(worst {max(off[flank_nodes] / mag[flank_nodes]):.1e}); self-checks within {checks:.2%} (5 %)")

# 2. The stroke rule on a rhombic cavity, by Steiner's formula.
for angle in (75, 120):
    half, rc = math.radians(angle / 2), 4 * T
    with press(angle, ["-stroke_corner_radius", rc, "-friction_mu", 0], f"rule_{angle}.h5", np_=1) as h:
        U = h["/history"].attrs["final_stroke_target"]
    D = RO / math.sin(half) - U  # the cavity's vertical half-diagonal
    rho = D * math.sin(half)  # its inradius
    perimeter = 4 * D / math.cos(half) * (rho - rc) / rho + 2 * math.pi * rc
    k.check(abs(perimeter / (2 * math.pi * RO) - 1) < 1e-12,
            f"{angle} deg: the rule's stroke {U:.6f} mm leaves a rounded rhombus of perimeter {perimeter:.12f}, the "
            f"tube's {2 * math.pi * RO:.12f}")

# 4. 90 degrees given is the default die.
press(90, [], "die_90.h5", np_=1).close()
with h5py.File(out("die_90.h5"), "r") as a, h5py.File(out("die_default.h5"), "r") as b:
    same = all(np.array_equal(a["/history"][c][:], b["/history"][c][:]) for c in a["/history"])
k.check(same, "-die_angle 90: the history of the default die, bit for bit")

# 5. A second pass's own V-die.
with press(120, TWO + ["-pass2_die_angle", 75], "pass2_die_75.h5") as h:
    V1, V2, L2 = h["/tools/V-die/vertices"][:], h["/tools/pass2-V-die/vertices"][:], h["/tools/pass2-V-die/lines"][:]
    j = int(np.flatnonzero(h["/time"][:, 0] <= 3 + 1e-12)[-1])  # (the second press: lambda 2 to 3)
    D2 = h["/tools/pass2-V-die/displacement"][j]
    xc = h["/geometry/vertices"][:] + h["/vertex_fields/displacement_u"][j]
    F, S = h["/vertex_fields/contact_force"][j], h["/vertex_fields/contact_state"][j]
flank1 = outline(V1, 120)[0]
a, b = max(L2, key=lambda e: np.hypot(*(V2[e[1]] - V2[e[0]])))  # the second die's flank
slope = math.degrees(math.atan2(*(V2[b] - V2[a])[::-1]))
k.check(flank1.sum() >= 2 and abs(abs(slope) - (90 - 75 / 2)) < 1e-9,
        f"-die_angle 120, -pass2_die_angle 75: the first outline's {flank1.sum()} flank points on the 120-degree "
        f"flank; the second's flank at {abs(slope):.9f} degrees below the horizontal (75 degrees: 52.5)")
flank2 = np.zeros(len(V2), bool)
flank2[[a, b]] = True
half = math.radians(75 / 2)
n = np.array([-math.cos(half), -math.sin(half)])
line = -((V2 + D2)[flank2] @ n)  # the moved flank's distance from the centre along its normal
on = (S > 0.5) & (np.abs(-(xc @ n) - line.mean()) < 1e-6)
mag, off = np.hypot(F[:, 0], F[:, 1]), np.abs(F[:, 0] * n[1] - F[:, 1] * n[0])
k.check(np.ptp(line) < 1e-9 and on.any() and (off[on] <= 1e-9 * mag[on]).all(),
        f"the second press's end: {on.sum()} nodes on the 75-degree flank, their forces along its normal (worst "
        f"{max(off[on] / mag[on]) if on.any() else float('nan'):.1e})")
press(120, TWO + ["-pass2_die_r_apex", RA], "pass2_default.h5", np_=1).close()
press(120, TWO, "pass2_none.h5", np_=1).close()
with h5py.File(out("pass2_default.h5"), "r") as a, h5py.File(out("pass2_none.h5"), "r") as b:
    same = all(np.array_equal(a["/history"][c][:], b["/history"][c][:]) for c in a["/history"])
    v120 = outline(a["/tools/pass2-V-die/vertices"][:], 120)[0].sum() >= 2
k.check(same and v120, "-pass2_die_r_apex at the first pass's value: the 120-degree die in both passes, the "
        "history without it, bit for bit")
k.done()
