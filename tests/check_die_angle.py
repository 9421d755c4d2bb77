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
"""
import math

import h5py
import numpy as np

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
k = Checks("die_angle")
RO, T, RA = 17.5, 1.5, 3.0  # options/squaring.opts
BASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-error_estimate", 0, "-progress", 0]


def press(angle, extra, name, np_=2):
    f = out(name)
    run(tf, mpirun, np_, BASE + ["-die_angle", angle, "-output", f] + list(extra))
    return h5py.File(f, "r")


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
    dist = -(V @ n)  # the distance of each point's line normal to n from the origin
    centre = np.array([0.0, RO / math.sin(half) - RA / math.sin(half)])
    on_arc = np.abs(np.hypot(*(V - centre).T) - RA) < 1e-12
    on_flank = np.abs(dist - RO) < 1e-12
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
run(tf, mpirun, 1, BASE + ["-output", out("die_default.h5")])
with h5py.File(out("die_90.h5"), "r") as a, h5py.File(out("die_default.h5"), "r") as b:
    same = all(np.array_equal(a["/history"][c][:], b["/history"][c][:]) for c in a["/history"])
k.check(same, "-die_angle 90: the history of the default die, bit for bit")
k.done()
