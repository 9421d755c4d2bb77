"""The side dies on a motion of their own (-side_motion stroke, fixed, path, pulse or force, each a kind of the motion
registry, tool/motion_*.cpp, read under the prefix side_ as the lower and upper dies' are under theirs; docs/dies.md,
"Side dies").

The ring of options/flattening.opts between the top plate and a side plate (`-side_die flat`, the quarter model: four
plates around the ring), fast preset, pressed to U = 2 mm, every increment a field step.
A. -side_motion path -side_path 2,2 (in by the stroke, drawn by the schedule kind) is the stroke's motion: every
   history column within 1e-12 of its largest value (the same press; the two kinds place the plate by different
   operations, so round-off may part them: measured 0).
B. -side_force 20, the option as it was before -side_motion, is -side_motion force -side_force 20: the same history
   bit for bit.
C. A side plate that waits, then moves in (-side_path 1.037,0,2,0.6: a kink no increment would end on by chance):
   at every field step its displacement is the path's at the row's U (x -d, y 0) within 1e-12 mm (the path's own
   arithmetic on numbers ~2 mm), a row lies on the kink within 1e-12 mm (the kink ends an increment), the history's
   side_stroke is the path's travel at every row within 1e-12 mm, and the run's energy balance (each plate's work
   from its reported force over its reported travel against the internal work) within 5e-3 at every increment from
   U = 0.5 mm (tests/check_side_dies.py C's bound; a travel counted by the stroke instead of the path's leaves the
   side plate's work wrong by its whole share).
D. -side_motion fixed: the side plate's displacement 0 at every field step (exactly: a fixed tool's offset is 0 x
   its stroke), side_stroke 0, the energy balance as C's, and the load at the end more than 2 % off the stroke's
   (a wall that stays is another press: measured 7.7 %; the option ignored would give the stroke's).
E. A second pass's own, on the paper's tube (options/squaring.opts, fast preset, U = 2 mm, then -pass2_stroke 2.5
   -pass2_side_die flat -pass2_side_motion path -pass2_side_path 0.5,0,2.5,0.3): the tube the first pass widened
   reaches past the plates' drawing, so they start moved back along their axis to where they touch it (not with
   the pass's dies that travel together: the upper die still starts at U = 0); at every field step of the pass the
   plate's displacement by its motion (the results', from where it starts) is the path's travel at the upper die's
   travel there (read from the upper die's own displacement) within 1e-12 mm, y 0; the plates carry load at the
   end of the press (side_load > 0: they touch; drawn where they are, not moved back, they would start inside the
   tube and stop the run); the energy balance within C's 5e-3 at every increment of the pass.
Bad input (a motion of the side dies without side dies, another motion's option): tests/check_bad_input.py.
"""
import numpy as np

from tfcheck import Checks, args, history_and_tools, out, ran_to_end, run_all

tf, mpirun, src = args()
k = Checks("side_motion")
BASE = ["-options_file", f"{src}/options/flattening.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-error_estimate", 0, "-progress", 0, "-stroke", 2, "-side_die", "flat", "-output_stroke", 0,
        "-output_every", 1]
KINK = 1.037
PASS2 = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
         "-error_estimate", 0, "-progress", 0, "-stroke", 2, "-output_stroke", 0, "-output_every", 1]
RUNS = {"side_stroke.h5": BASE, "side_straight.h5": BASE + ["-side_motion", "path", "-side_path", "2,2"],
        "side_force_old.h5": BASE + ["-side_force", 20],
        "side_force.h5": BASE + ["-side_motion", "force", "-side_force", 20],
        "side_wait.h5": BASE + ["-side_motion", "path", "-side_path", f"{KINK},0,2,0.6"],
        "side_fixed.h5": BASE + ["-side_motion", "fixed"],
        "side_pass2.h5": PASS2 + ["-pass2_stroke", 2.5, "-pass2_side_die", "flat", "-pass2_side_motion", "path",
                                  "-pass2_side_path", "0.5,0,2.5,0.3"]}
made = dict(zip(RUNS, run_all(tf, mpirun, [o + ["-output", out(n)] for n, o in RUNS.items()], check=False,
                              timeout=600)))
H = {n: ran_to_end(k, tf, mpirun, 1, o, out(n), n[:-3], made[n]) for n, o in RUNS.items()}


def same(a, b):
    """The largest difference of two histories' columns relative to each column's largest value (1: other shapes)."""
    cols = [c for c in a if c != "tools"]
    if not all(a[c].shape == b[c].shape for c in cols):
        return 1.0
    return max(np.abs(a[c] - b[c]).max() / max(np.abs(a[c]).max(), 1e-300) for c in cols)


def balance(h):
    """The run's energy balance at every increment from U = 0.5 mm of the press."""
    rows = (h["stroke"] >= 0.5) & (h["stage"] == 0)
    return np.abs(h["energy_error"][rows]).max() if rows.any() else np.inf


# A. In by the stroke, drawn by the schedule kind.
worst = same(H["side_straight.h5"], H["side_stroke.h5"])
k.check(worst <= 1e-12, f"A. -side_path 2,2 gives the stroke's history: within {worst:.1e} of the largest (1e-12)")

# B. The old spelling of force control.
worst = same(H["side_force_old.h5"], H["side_force.h5"])
k.check(worst == 0, f"B. -side_force 20 alone is -side_motion force -side_force 20: {worst:.1e} apart (0)")

# C. It waits, then moves in.
h = H["side_wait.h5"]
U, d = h["stroke"], h["tools"]["side-plate"][:, 0, :]
travel = np.interp(U, [0, KINK, 2], [0, 0, 0.6])
loading = h["stage"] == 0
off = max(np.abs(d[loading, 0] + travel[loading]).max(), np.abs(d[loading, 1]).max()) \
    if len(d) == len(U) else np.inf
on_kink = np.abs(U - KINK).min()
side = np.abs(h["side_stroke"] - travel).max()
e = balance(h)
k.check(off <= 1e-12 and on_kink <= 1e-12 and side <= 1e-12 and e <= 5e-3,
        f"C. waiting, then in: the plate's displacement at {loading.sum()} field steps the path's within {off:.1e} mm, "
        f"a row on the kink within {on_kink:.1e} mm, side_stroke the path's within {side:.1e} mm (1e-12 each); "
        f"the energy balance within {e:.1e} from U = 0.5 mm (5e-3)")

# D. Walls that stay.
h = H["side_fixed.h5"]
moved = np.abs(h["tools"]["side-plate"]).max()
e = balance(h)
gap = abs(h["load"][h["stage"] == 0][-1] / H["side_stroke.h5"]["load"][H["side_stroke.h5"]["stage"] == 0][-1] - 1)
k.check(moved == 0 and np.abs(h["side_stroke"]).max() == 0 and e <= 5e-3 and gap > 0.02,
        f"D. fixed: the plate moved {moved:.1e} mm, side_stroke {np.abs(h['side_stroke']).max():.1e} (0 each); the "
        f"energy balance within {e:.1e} (5e-3); the end load {100 * gap:.1f} % off the stroke's (> 2 %)")

# E. A second pass's own.
h = H["side_pass2.h5"]
steps = h["stage"] == 2 if len(h["tools"]["pass2-side-plate"]) == len(h["stage"]) else np.zeros(0, bool)
plate, upper = h["tools"]["pass2-side-plate"][steps, 0, :], h["tools"]["pass2-V-die"][steps, 0, 1]
travel = np.interp(-upper, [0, 0.5, 2.5], [0, 0, 0.3])  # (the upper die's own displacement: down by its stroke)
off = max(np.abs(plate[:, 0] + travel).max(), np.abs(plate[:, 1]).max()) if steps.any() else np.inf
load = h["side_load"][steps][-1] if steps.any() else 0
e = np.abs(h["energy_error"][steps]).max() if steps.any() else np.inf
k.check(steps.sum() > 10 and off <= 1e-12 and load > 0 and e <= 5e-3,
        f"E. the second pass's plates along their path from where they start at {steps.sum()} field steps within "
        f"{off:.1e} mm (1e-12), side_load {load:.4g} N/mm at the end (> 0), the energy balance within {e:.1e} "
        f"(5e-3)")
k.done()
