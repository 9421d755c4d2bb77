"""A die of one's own from a profile file (-die_profile, src/tool/profile.cpp):

1. The paper's V-die written as a profile (its numbers from the V-die's geometry of docs/dies.md, computed here) presses the
   tube exactly as the built-in V-die: the same history, bit for bit (both go through one construction).
2. A flat-bottomed die (a flat face over the tube, a concave fillet, a 45-degree flank) pressed frictionless
   to U = 1 mm: the contact forces the file holds on nodes on the flat face are vertical (within 1e-9 of
   their magnitude): the die the contact sees is the profile's; 1 vs 2 ranks within 1.3e-8 of the largest
   load (tests/check_squaring.py's bound).
3. Bad profiles: a gap, a start off the axis, the tube on the wrong side, an arc not tangent to its
   neighbour, a word that is no number, a missing file: one error line naming the file (and line), exit 1,
   on 1 rank and (the gap) on 2.
4. DXF (written here, group codes by hand: what CAD exports): the V-die as a LINE listed first and walked
   the wrong way and an ARC, read through dxflib and chained from the axis, is the built-in die bit for bit;
   the flat-bottomed die as one LWPOLYLINE whose fillet is a bulge gives the text profile's history within
   1e-9 of each column's largest value (the bulge's centre and angles are computed, to round-off); bad
   drawings (a piece not joined, two pieces going on from one point, none on the axis, not DXF) are refused
   in one line naming the file and the entity.
"""
import math
import os
from concurrent.futures import ThreadPoolExecutor

import h5py
import numpy as np

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
k = Checks("profile")
RO, RA = 17.5, 3.0  # options/squaring.opts
BASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-error_estimate", 0, "-progress", 0, "-stroke", 1.5]


def write(name, text):
    with open(out(name), "w") as f:
        f.write(text)
    return out(name)


def history(name):
    with h5py.File(out(name), "r") as h:
        return {c: h["/history"][c][:] for c in h["/history"]}


# 1. The V-die as a profile: apex fillet from 90 to 45 degrees, the flank x + y = Ro sqrt2 to x = 1.3 Ro; the
# shipped file (options/dies/v90_r3.profile) holds these numbers.
s2 = math.sqrt(2.0)
h, cy = RO * s2, RO * s2 - RA * s2
mine = f"arc 0 {cy!r} {RA!r} 90 45\nline {RA / s2!r} {cy + RA / s2!r} {1.3 * RO!r} {h - 1.3 * RO!r}\n"
v90 = f"{src}/options/dies/v90_r3.profile"
shipped = "".join(l for l in open(v90) if not l.startswith("#"))
k.check(shipped == mine, "options/dies/v90_r3.profile holds the V-die's numbers computed here from its geometry")

# The die files of 2-4, and the runs: the single-rank ones two at a time (the machine's two cores), the longest
# first, then the 2-rank ones one after another; the checks below read them.
A, R = 7.0, 3.0  # (2's flat-bottomed die)
flat = f"{src}/options/dies/flat_bottom.profile"
BAD = [("gap.profile", "line 0 20 5 20\nline 5.1 20 20 5\n", "gap.profile:2: a gap"),
       ("offaxis.profile", "line 1 20 20 20\n", "offaxis.profile:1: the profile must start on the axis"),
       ("reversed.profile", "line 0 20 -20 20\n", "reversed.profile:1: the tube is on the wrong side"),
       # (the arc starts where the face ends, turned by 19.5 degrees from it)
       ("kink.profile", f"line 0 {RO} {A} {RO}\narc {A - 1} {RO - math.sqrt(8)!r} {R} "
                        f"{math.degrees(math.atan2(math.sqrt(8), 1))!r} 45\n", "kink.profile:2: the arc is not tangent"),
       ("word.profile", "line 0 20 five 20\n", "word.profile:1: not a number"),
       ("missing.profile", None, "missing.profile: cannot read the file")]


def dxf(name, entities):
    lines = ["0", "SECTION", "2", "ENTITIES"] + [w for e in entities for w in e] + ["0", "ENDSEC", "0", "EOF"]
    return write(name, "\n".join(lines) + "\n")


def dline(x0, y0, x1, y1):
    return ["0", "LINE", "8", "0", "10", repr(x0), "20", repr(y0), "30", "0.0", "11", repr(x1), "21", repr(y1),
            "31", "0.0"]


def darc(cx, cy, r, a1, a2):  # counter-clockwise from a1 to a2, as DXF has it
    return ["0", "ARC", "8", "0", "10", repr(cx), "20", repr(cy), "30", "0.0", "40", repr(r), "50", repr(a1),
            "51", repr(a2)]


def dpoly(points):  # (x, y, bulge to the next vertex)
    e = ["0", "LWPOLYLINE", "8", "0", "90", str(len(points)), "70", "0"]
    for x, y, bulge in points:
        e += ["10", repr(x), "20", repr(y), "42", repr(bulge)]
    return e


v90_dxf = dxf("v90.dxf", [dline(1.3 * RO, h - 1.3 * RO, RA / s2, cy + RA / s2), darc(0.0, cy, RA, 45.0, 90.0)])
end = (A + R / s2, RO - R + R / s2)
flat_dxf = dxf("flat.dxf", [dpoly([(0.0, RO, 0.0), (A, RO, -math.tan(math.radians(45) / 4)), (end[0], end[1], 0.0),
                                   (1.3 * RO, end[1] - (1.3 * RO - end[0]), 0.0)])])
BAD_DXF = [("apart.dxf", [dline(0.0, 20.0, 5.0, 20.0), dline(5.5, 20.0, 20.0, 5.0)], "is not joined to the chain"),
           ("branch.dxf", [dline(0.0, 20.0, 5.0, 20.0), dline(5.0, 20.0, 20.0, 5.0), dline(5.0, 20.0, 20.0, 10.0)],
            "both go on from"),
           ("offaxis.dxf", [dline(1.0, 20.0, 5.0, 20.0)], "0 entities touch the axis")]
paths = {"notdxf.dxf": write("notdxf.dxf", "this is no drawing\n")}
for name, text, _ in BAD:
    paths[name] = write(name, text) if text is not None else out(name)
    if text is None and os.path.exists(paths[name]):
        os.remove(paths[name])
paths.update({name: dxf(name, entities) for name, entities, _ in BAD_DXF})
FLAT = ["-die_profile", flat, "-friction_mu", 0, "-stroke", 1.0]
GOOD = {"builtin.h5": [], "v90.h5": ["-die_profile", v90], "flat_np1.h5": FLAT,
        "v90_dxf.h5": ["-die_profile", v90_dxf], "flat_dxf.h5": ["-die_profile", flat_dxf] + FLAT[2:]}
# (key, options, check); each refused run its own -output, as two run at once
ONE = [((name, 1), BASE + extra + ["-output", out(name)], True) for name, extra in GOOD.items()] + \
      [((name, 1), BASE + ["-die_profile", paths[name], "-output", out(f"bad_{name}.h5")], False)
       for name in [b[0] for b in BAD] + [b[0] for b in BAD_DXF]]
with ThreadPoolExecutor(max_workers=2) as pool:
    ran = dict(zip([key for key, _, _ in ONE], pool.map(lambda j: run(tf, mpirun, 1, j[1], check=j[2]), ONE)))
run(tf, mpirun, 2, BASE + FLAT + ["-output", out("flat_np2.h5")])
for name in ("gap.profile", "notdxf.dxf"):
    ran[(name, 2)] = run(tf, mpirun, 2, BASE + ["-die_profile", paths[name], "-output", out("bad.h5")], check=False)

a, b = history("builtin.h5"), history("v90.h5")
same = a.keys() == b.keys() and all(np.array_equal(a[c], b[c]) for c in a)
k.check(same, f"the V-die as a profile file: the built-in die's history bit for bit ({len(a['stroke'])} rows)")

# 2. A flat-bottomed die: the face y = Ro from the axis to x = 7, a fillet of 3 mm turning down to 45 degrees
# (options/dies/flat_bottom.profile; A >= 6.01 keeps the flank x + y = A + Ro - R + R sqrt2 at least Ro from
# the tube's centre)
with h5py.File(out("flat_np1.h5"), "r") as hf:
    j = int(np.flatnonzero(hf["/time"][:, 0] <= 1 + 1e-12)[-1])
    X, u = hf["/geometry/vertices"][:], hf["/vertex_fields/displacement_u"][j]
    F, S = hf["/vertex_fields/contact_force"][j], hf["/vertex_fields/contact_state"][j]
    U = hf["/history/stroke"][:][hf["/history/stage"][:] == 0][-1]
xc = X + u
on_face = (S > 0.5) & (np.abs(xc[:, 1] - (RO - U)) < 1e-6) & (xc[:, 0] < A)
mag = np.hypot(F[:, 0], F[:, 1])
k.check(on_face.any() and (np.abs(F[on_face, 0]) <= 1e-9 * mag[on_face]).all(),
        f"flat-bottomed die, mu 0, U {U:g}: {on_face.sum()} nodes on the flat face, their forces vertical")
l1, l2 = history("flat_np1.h5")["load"], history("flat_np2.h5")["load"]
diff = np.abs(l1 - l2).max() / np.abs(l1).max() if l1.shape == l2.shape else math.inf
k.check(diff < 1.3e-8, f"flat-bottomed die: 1 vs 2 ranks, loads within {diff:.1e} of the largest (1.3e-8)")

# 3. Bad profiles.
for name, text, want in BAD:
    for np_ in ((1, 2) if name == "gap.profile" else (1,)):
        p = ran[(name, np_)]
        lines = [l for l in (p.stdout + p.stderr).splitlines() if l.startswith("tubeform: error")]
        k.check(p.returncode != 0 and len(lines) == 1 and want in lines[0] and "-die_profile" in lines[0],
                f"{name} on {np_} rank(s): exit {p.returncode}, {len(lines)} error line: "
                f"{lines[0][:110] if lines else '(none)'}")


# 4. DXF.
c = history("v90_dxf.h5")
k.check(c.keys() == a.keys() and all(np.array_equal(a[col], c[col]) for col in a),
        "the V-die as DXF (LINE walked backwards, ARC): the built-in die's history bit for bit")
d, t1 = history("flat_dxf.h5"), history("flat_np1.h5")
worst = max(np.abs(d[col] - t1[col]).max() / max(np.abs(t1[col]).max(), 1e-300) for col in t1
            if np.isfinite(t1[col]).all()) if d.keys() == t1.keys() and len(d["stroke"]) == len(t1["stroke"]) else math.inf
k.check(worst <= 1e-9, f"the flat-bottomed die as an LWPOLYLINE with a bulge: the text profile's history within "
        f"{worst:.1e} (1e-9)")
for name, entities, want in BAD_DXF:
    p = ran[(name, 1)]
    lines = [l for l in (p.stdout + p.stderr).splitlines() if l.startswith("tubeform: error")]
    k.check(p.returncode != 0 and len(lines) == 1 and want in lines[0] and name in lines[0],
            f"{name}: exit {p.returncode}, {len(lines)} error line: {lines[0][:120] if lines else '(none)'}")
p = ran[("notdxf.dxf", 2)]
lines = [l for l in (p.stdout + p.stderr).splitlines() if l.startswith("tubeform: error")]
k.check(p.returncode != 0 and len(lines) == 1 and "notdxf.dxf" in lines[0],
        f"a text file named .dxf on 2 ranks: exit {p.returncode}, {len(lines)} error line: "
        f"{lines[0][:120] if lines else '(none)'}")
k.done()
