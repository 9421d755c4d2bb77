"""The tube's wall never crosses a symmetry plane (docs/theory.md, "Symmetry planes"): a 25.4 x 1.65 mm tube
(mu 0.12) pressed 8 mm on the quarter model folds its wall onto both planes, where the real tube meets its other
half (from U = 6.8-7.0 mm on, four nodes on each plane at 8 mm; the last millimetre to 9 mm, which this check
pressed before, took three fifths of the run's increments and added no plane the wall meets).
Reference: the geometry of the symmetric tube. The quarter model's material lies in x >= 0, y >= 0; its mirror
images in the other quadrants. So at every written step every node has x >= -TOL and y >= -TOL, with
TOL = 1e-6 mm: a free node counts as touching a wall within 1e-7 mm (the contact set's gap tolerance) and the first touch along
a step is exact for a straight wall; a node on the wall follows it, its gap closed by the next increment: nodes stay
on the wall to round-off of the coordinates (1e-15 x 13 mm). TOL is ten times the touching distance, a thousandth of
the depth at which the run stops for a crossing (1e-4 of the tube's size, 1.3e-3 mm), and a millionth of the
1.4 and 2.2 mm the wall crossed x = 0 and y = 0 by (pressed 9 mm) when the planes were not walls. The walls did
hold it: after the paper's springback (dies gone) nodes still touch them, which only the walls can be
(n_contact > 0), and the run finishes (exit 0).
The half model of the same tube has no wall at y = 0 (the lower die is its own): its upper and lower walls meet
there, which the solver does not model; on 2 ranks the run stops with one line naming where the wall meets itself
and the stroke, a non-zero exit, no hang, and the history up to the stop written and flagged `stopped`: its last
stroke is the one the line names (to the line's 6 digits).
Two tests run it (tests/CMakeLists.txt), by the part given after the source directory: `quarter` (one rank) and
`half` (2 ranks: both of the machine's cores); with neither, both.
"""
import re
import sys

import h5py
import numpy as np

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
part = sys.argv[4] if len(sys.argv) > 4 else "both"
k = Checks(f"symmetry_walls ({part})")
TOL = 1e-6  # mm (see above)
tube = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-tube_ro", 12.7, "-tube_t", 1.65, "-friction_mu", 0.12, "-error_estimate", 0]
QUARTER_STROKE, HALF_STROKE = 8, 9  # mm (the half model stops where its wall meets itself, at about 6.7)

if part in ("quarter", "both"):
    f = out("walls_quarter.h5")
    p = run(tf, mpirun, 1, tube + ["-stroke", QUARTER_STROKE, "-output", f], check=False)
    last = (p.stdout + p.stderr).strip().splitlines()[-1:] or [""]
    k.check(p.returncode == 0, f"quarter model: the run finishes (exit {p.returncode}: {last[0]})")
    if p.returncode == 0:
        with h5py.File(f, "r") as h:
            X = h["/geometry/vertices"][:, :2]
            lowest = np.array([(X + u[:, :2]).min(axis=0) for u in h["/vertex_fields/displacement_u"][:]])
            H = {c: h["/history"][c][:] for c in ("n_contact", "stage")}
        k.check(lowest[:, 0].min() >= -TOL, f"quarter model: every node at x >= -{TOL:g} mm at every written step "
                f"(lowest {lowest[:, 0].min():.3g})")
        k.check(lowest[:, 1].min() >= -TOL, f"quarter model: every node at y >= -{TOL:g} mm at every written step "
                f"(lowest {lowest[:, 1].min():.3g})")
        k.check(H["stage"][-1] == 1 and H["n_contact"][-1] > 0, f"quarter model: after the springback, the dies gone, "
                f"{int(H['n_contact'][-1])} nodes rest on the walls")

if part in ("half", "both"):
    f = out("walls_half.h5")
    p = run(tf, mpirun, 2, tube + ["-stroke", HALF_STROKE, "-model", "half", "-output", f], check=False,
            report_hang=True)
    lines = [l for l in (p.stdout + p.stderr).splitlines() if "meets itself" in l]
    k.check(not getattr(p, "timed_out", False) and p.returncode != 0 and len(lines) == 1,
            f"half model, 2 ranks: exit {p.returncode}, {len(lines)} line saying where the wall meets itself")
    m = re.search(r"meets itself at \(([-\d.e]+), ([-\d.e]+)\).*\(stroke ([\d.e+-]+),", lines[0]) if lines else None
    k.check(m is not None and abs(float(m.group(2))) < 0.1,
            f"half model: it meets itself at the plane y = 0, where the upper and lower walls meet ({lines[:1]})")
    if m:
        with h5py.File(f, "r") as h:
            U, stopped = h["/history"]["stroke"][:], h["/history"].attrs["stopped"]
        k.check(abs(U[-1] - float(m.group(3))) <= 1e-5 * U[-1] and stopped == 1,
                f"half model: the history is written to the stop (last stroke {U[-1]:.6g}, the line's {m.group(3)}), "
                f"flagged stopped ({stopped:g})")
k.done()
