"""The answer a run prints, pass by pass, against its own definitions (docs/output.md, docs/passes.md).

A. Two passes (options/oval_then_square.opts, fast preset: plates press the paper's tube 3 mm into an oval, it
   springs back and turns a quarter turn, the V-dies press it across its long axis to -pass2_stroke 4):
   - the second pass's stroke is its dies' position from the same zero as the first pass's (a V-die touching the
     round tube): where the die ends is read from the die's own outline in the result file (its nearest point
     to the tube's centre along the press, at the end of the pass) against the V-die's drawing, Ro sqrt 2 -
     r (sqrt 2 - 1) - 4 mm from the centre, within 1e-9 mm (round-off of the outline's points), at mu 0.05
     and 0.2, whose dies start at different places (they start where they touch the oval; the attribute
     pass2_start_stroke, negative: moved back). Planted: the stroke counted from the die's start, as before
     -> the die ends 0.1 mm short, FAILED.
   - each pass's printed answer is its history's: the load at the end of the pass's loading (its stage's last
     row), C/t, C1, C2 loaded and after springback (the last row of its release), to the printed digits; C1 is
     the half-extent across the press (x_max) and C2 along it (y_max), C1/C2 their ratio: the plates flatten
     the tube along their motion, so the first pass's C1/C2 is above 1 (planted: the smaller over the larger
     -> 0.73, FAILED).
   - the estimate covers both passes: its line gives the second pass's errors and the file its pass2_error_*
     attributes (planted: the first pass's alone -> FAILED).
B. A mesh file (meshes/quarter_tube.geo through gmsh, 2 x 24 cells): the companion keeps the mesh, so the
   estimate covers the increments alone; its line says so, no warning weighs it against the preset's targets,
   and the attribute error_covers_mesh is 0 (a generated mesh: 1). Planted: the old line, "an upper bound",
   and its warning -> FAILED. The line names where the largest load and C/t errors are and the largest at the
   other reported strokes: the file's error_*_at_U and error_loaded_* attributes, to the printed digits (planted:
   the largest elsewhere taken over every stroke -> FAILED). The generated mesh has the fast preset's 2 cells
   through the wall, which its mesh companion keeps (it halves to no fewer): the line says the wall's part is not
   in the estimate and the attribute error_covers_wall is 0 (planted: the wall always counted as covered, or the
   attribute always 1 -> FAILED). The end of loading's estimate (error_loaded_load, error_loaded_c_over_t) is the
   largest of the history's row-by-row error_load and error_c_over_t over the loading's last trial increment
   (stroke / -increments), to round-off; here the last row alone reads the load's 7.9 % against 13 % a row before
   it (planted: the end's stroke alone -> FAILED).
"""
import math
import os
import re
import subprocess

import h5py
import numpy as np

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
k = Checks("answer")
FAST = ["-options_file", f"{src}/options/preset-fast.opts", "-progress", 0]
RO, R_APEX, P2 = 17.5, 3.0, 4.0  # (options/squaring.opts, options/dies/v90_r3.profile, oval_then_square.opts)


def history(path):
    with h5py.File(path, "r") as h:
        H = {c: h["/history"][c][:] for c in h["/history"]}
        A = {a: h["/history"].attrs[a] for a in h["/history"].attrs}
    return H, A


def die_reach(path, tool, lam):
    """How far from the tube's centre the V-die's apex is along the turned press (the tube's x: the quarter model
    draws the turned die by the reflection about y = x, pressing along -x; the apex is the V's deepest point, the
    outline's largest x) at the output step nearest load parameter lam."""
    with h5py.File(path, "r") as h:
        t = h["/time"][:, 0]
        step = int(np.argmin(np.abs(t - lam)))
        v, d = h[f"/tools/{tool}/vertices"][:], h[f"/tools/{tool}/displacement"][step]
    a = int(np.argmax(v[:, 0]))
    return v[a, 0] + d[a, 0], t[step]


def printed(text, label):
    """The numbers of the printed line starting with `label` (after 'tubeform: ')."""
    line = next((l for l in text.splitlines() if l.startswith("tubeform: " + label)), "")
    # (numbers alone: not the digits of the names C1, C2)
    return [float(v) for v in re.findall(r"(?<![A-Za-z0-9.])[-+]?\d+\.?\d*(?:[eE][-+]?\d+)?",
                                         line[len("tubeform: " + label):])]


# A. Two passes.
apex = RO * math.sqrt(2) - R_APEX * (math.sqrt(2) - 1)  # the V-die's nearest point at stroke 0
for mu in (0.05, 0.2):
    f = out(f"answer_oval_mu{mu}.h5")
    p = run(tf, mpirun, 1, ["-options_file", f"{src}/options/oval_then_square.opts"] + FAST +
            ["-friction_mu", mu, "-output", f, "-output_stroke", 0.5])
    H, A = history(f)
    reach, lam = die_reach(f, "pass2-die", 3.0)
    end2 = H["stroke"][H["stage"] == 2][-1]
    k.check(abs(lam - 3.0) < 1e-12 and abs(reach - (apex - P2)) < 1e-9 and abs(end2 - P2) < 1e-12 and
            A["pass2_start_stroke"] < 0,
            f"mu {mu}: the second pass's die starts at U = {A['pass2_start_stroke']:.5f} mm (where it touches the "
            f"oval) and its apex ends {reach:.9f} mm from the centre, {reach - (apex - P2):+.1e} from U = {P2:g} "
            f"(1e-9); the history's last stroke of the pass {end2:g}")
    if mu != 0.05:
        continue
    text = p.stdout
    for stage, label in ((0, ""), (2, "second pass: ")):
        rows = np.flatnonzero(H["stage"] == stage)
        end, last = rows[-1], np.flatnonzero(H["stage"] <= stage + 1)[-1]
        load = printed(text, label + "load at the end of loading")
        shown = printed(text, label + "loaded:"), printed(text, label + "after springback")
        want = [[H[c][r] for c in ("c_over_t", "x_max", "y_max")] for r in (end, last)]
        ok = len(load) >= 2 and abs(load[1] - H["load"][end]) <= 5e-5 * abs(H["load"][end])
        # (loaded: C/t, C1/C2, C1, C2; after springback: C/t, C1/C2, C1, its change, C2, its change)
        for got, (ct, c1, c2), at in zip(shown, want, ((2, 3), (2, 4))):
            ok = ok and len(got) > max(at) and abs(got[0] - ct) <= 5e-5 and abs(got[1] - c1 / c2) <= 5e-5
            ok = ok and abs(got[at[0]] - c1) <= 5e-5 and abs(got[at[1]] - c2) <= 5e-5
        k.check(ok, f"pass {stage // 2 + 1}: the printed load {load[1:2]} and shapes {shown} are the history's "
                f"(load {H['load'][end]:.5g}; C/t, C1, C2 {want})")
    first = printed(text, "loaded:")
    ratio = np.abs(H["deviation_ratio"] - H["x_max"] / H["y_max"]).max()
    k.check(len(first) >= 4 and first[1] > 1 and abs(first[1] - first[2] / first[3]) < 1e-4 and ratio < 1e-12,
            f"the plates flatten the tube along their motion: C1/C2 {first[1:2]} above 1, C1 {first[2:3]} mm across "
            f"the press over C2 {first[3:4]} mm along it; the history's deviation_ratio x_max / y_max within "
            f"{ratio:.0e}")
    est = next((l for l in text.splitlines() if "estimated error" in l), "")
    k.check("second pass: load" in est and "pass2_error_loaded_load" in A and "pass2_error_unloaded_c_over_t" in A,
            f"the estimate covers both passes: '{est[10:]}'")

# B. A mesh file.
msh = out("answer_q24.msh")
subprocess.run(["gmsh", "-2", "-setnumber", "nt", "2", "-setnumber", "ntheta", "24", f"{src}/meshes/quarter_tube.geo",
                "-o", msh], check=True, capture_output=True)
for name, extra in (("file", ["-mesh_file", msh]), ("generated", [])):
    f = out(f"answer_{name}.h5")
    p = run(tf, mpirun, 1, ["-options_file", f"{src}/options/squaring.opts"] + FAST +
            ["-unload", "none", "-output", f] + extra)
    H, A = history(f)
    est = next((l for l in p.stdout.splitlines() if "estimated error" in l), "")
    if name == "file":
        k.check("increments alone" in est and "upper bound" not in est and "warning" not in p.stdout and
                A.get("error_covers_mesh") == 0,
                f"a mesh file: the estimate covers the increments alone and says so ('{est[10:90]}...'), no "
                f"warning, error_covers_mesh {A.get('error_covers_mesh')}")
    else:
        k.check(A.get("error_covers_mesh") == 1, f"a generated mesh: error_covers_mesh {A.get('error_covers_mesh')}")
        k.check("not the wall's: its 2 cells through are the companions' too" in est and
                A.get("error_covers_wall") == 0,
                f"2 cells through the wall, kept by the mesh companion: the line says its part is not estimated "
                f"('{est[10:140]}...'), error_covers_wall {A.get('error_covers_wall')}")
        # The end of loading read over its last trial increment (the preset's -increments).
        trials = float(re.search(r"^-increments (\S+)", open(f"{src}/options/preset-fast.opts").read(), re.M).group(1))
        loading = H["stage"] == 0
        u = H["stroke"][loading]
        last = u >= u[-1] * (1 - 1 / trials) - 1e-12
        window = [(H[f"error_{c}"][loading][last].max(), A[f"error_loaded_{c}"]) for c in ("load", "c_over_t")]
        k.check(all(abs(w - a) <= 1e-12 * max(a, 1e-3) for w, a in window),
                f"the end of loading's estimate is the largest over its last trial increment ({last.sum()} rows): "
                f"load, C/t {[(float(w), float(a)) for w, a in window]} (the window's, the file's)")
        # Where the largest estimated error is, and the largest elsewhere, from the file's per-stroke attributes.
        for name, pattern, unit in (("load", r"load (\S+) % at U = (\S+) \(mesh [^;]*; (\S+) % at most elsewhere\)",
                                     100), ("c_over_t", r"C/t (\S+) at U = (\S+) \(mesh [^;]*; (\S+) at most "
                                                        r"elsewhere\)", 1)):
            at = {u: unit * A[f"error_{name}_at_{u:g}"] for u in (1, 2, 3)}
            at[4.2] = unit * A[f"error_loaded_{name}"]
            worst = max(at, key=at.get)
            rest = max(v for u, v in at.items() if u != worst)
            m = re.search(pattern, est)
            got = (float(m.group(1)), float(m.group(2)), float(m.group(3))) if m else None
            want = (float(f"{at[worst]:.2g}"), worst, float(f"{rest:.2g}"))
            k.check(got == want, f"the estimate's {name}: printed largest, where, largest elsewhere {got}; the "
                    f"file's {want}")
k.done()
