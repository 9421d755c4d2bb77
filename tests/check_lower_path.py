"""The lower die on a path of its own (-lower_die_motion path, -lower_die_path U,y,...: tool/motion_schedule.cpp).

The lower die rises through the given heights y at the given strokes U, linear in U between them, and stays after
the last; the upper die comes down by U. The paper's tube (options/squaring.opts, fast preset, the half model),
pressed to U = 2 mm.

A. A path straight up by U (-lower_die_path 2,2) is the mirror's motion (-lower_die_motion mirror, -model half),
   drawn by another motion (a straight stroke, motion_stroke.cpp): the two histories agree in every column
   within 1e-12 of each column's largest value (the two motions place the die by the same operations: the
   path's slope 2 / 2 is 1 exactly; 1e-12 only leaves room for round-off, measured 0).
B. A die that waits, then rises (-lower_die_path 1,0,2,1): at every field step its displacement in the results is
   the path's at the row's stroke (0 up to U = 1, U - 1 after; x 0) within 1e-12 mm (the path's own arithmetic:
   a few additions of numbers ~2 mm); the history has a row at U = 1, the path's kink, to 1e-12 (an increment
   ends there); the energy balance recomputed from the history, the upper die's half of the load over U and the
   lower die's reported force over the path's rise, holds within tests/check_squaring.py's 5e-3 at every
   increment (measured 1.0e-3).
   On 2 ranks, within tests/check_squaring.py's 1.3e-8 of the largest load, x_max, y_max, C/t; continued from a
   checkpoint taken past the kink (the die's stroke is saved, its piece taken again from it at the next
   increment), the history of the run never stopped within tests/check_restart.py's 1e-12.
C. Refusals, one line each naming the option: strokes that do not rise, a path without -lower_die_motion path (or
   the motion without a path), with -stroke_path.
"""
import numpy as np

from tfcheck import Checks, args, lower_die_steps, out, ran_to_end, run, run_all, self_checks

tf, mpirun, src = args()
k = Checks("lower_path")
BASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-stroke", 2, "-progress", 0, "-error_estimate", 0]


def press(name, opts, n=1, p=None):
    """The run's history and tools (its results up to a stop too); a check that it ran to its end (`p`: the run,
    made already)."""
    return ran_to_end(k, tf, mpirun, n, BASE + opts, out(name), " ".join(map(str, opts)), p)


# A's and B's single-rank presses side by side (the machine's two cores), before B's 2-rank one; press() checks each.
ONE = {"lower_straight.h5": ["-lower_die_motion", "path", "-lower_die_path", "2,2"],
       "lower_wait.h5": ["-lower_die_motion", "path", "-lower_die_path", "1,0,2,1"],
       "lower_mirror.h5": ["-model", "half"]}
made = dict(zip(ONE, run_all(tf, mpirun, [BASE + o + ["-output", out(n)] for n, o in ONE.items()], check=False,
                             timeout=600)))

# A. Straight up by U: the mirror's motion.
mirror = press("lower_mirror.h5", ONE["lower_mirror.h5"], p=made["lower_mirror.h5"])
path = press("lower_straight.h5", ONE["lower_straight.h5"], p=made["lower_straight.h5"])
cols = [c for c in mirror if c != "tools"]
same = all(path[c].shape == mirror[c].shape for c in cols)
worst = max(np.abs(path[c] - mirror[c]).max() / max(np.abs(mirror[c]).max(), 1e-300) for c in cols) if same else 1
k.check(same and worst <= 1e-12, f"a lower die's path straight up by U gives the mirror's history: {len(cols)} columns "
        f"within {worst:.1e} of their largest values (1e-12)")

# B. It waits, then rises.
h = press("lower_wait.h5", ONE["lower_wait.h5"], p=made["lower_wait.h5"])
U = h["stroke"]
lam, disp = lower_die_steps(out("lower_wait.h5"), h)
press_steps = np.flatnonzero(lam <= 1)
want = np.clip(2 * lam[press_steps] - 1, 0, None)
miss = max(np.abs(disp[press_steps, :, 0]).max(), np.abs(disp[press_steps, :, 1] - want[:, None]).max()) \
    if len(disp) == len(lam) and len(press_steps) > 5 else np.inf
k.check(miss <= 1e-12, f"the lower die's displacement at {len(press_steps)} field steps of the press is the path's at "
        f"their strokes within {miss:.1e} mm (1e-12)")
k.check(np.abs(U - 1).min() <= 1e-12, f"a row at the path's kink U = 1 (nearest {np.abs(U - 1).min():.1e} off)")
loading = h["stage"] == 0
a = self_checks(h, lower_rise=np.clip(U - 1, 0, None))[0]  # (the path's rise at each row's stroke)
e = np.abs(a[1:][loading[1:]]).max()
k.check(e < 5e-3, f"the energy balance from the history and the path's rise within {e:.1e} at every increment "
        f"of the press (5e-3)")

# B, on 2 ranks (tests/check_squaring.py's bound up to U = 2.6 mm), and continued from a checkpoint taken past
# the kink (tests/check_restart.py's bound: the die's stroke is saved, its piece taken again from it).
WAIT = ["-lower_die_motion", "path", "-lower_die_path", "1,0,2,1"]
two = press("lower_wait_np2.h5", WAIT, 2)
same = two["load"].shape == h["load"].shape
rel = max(np.abs(two[c] - h[c]).max() / np.abs(h[c]).max() for c in ("load", "x_max", "y_max", "c_over_t")) \
    if same else 1
k.check(same and rel <= 1.3e-8, f"2 ranks: load, x_max, y_max, C/t within {rel:.1e} of 1 rank's (1.3e-8)")
past = int(np.flatnonzero(U > 1)[0]) + 2 if (U > 1).any() else 1
press("lower_part.h5", WAIT + ["-checkpoint", out("lower_ck.h5"), "-checkpoint_every", past])
part = press("lower_part.h5", WAIT + ["-restart", out("lower_ck.h5")])
same = all(part[c].shape == h[c].shape for c in h if c != "tools")
worst = max(np.abs(part[c] - h[c]).max() / max(np.abs(h[c]).max(), 1e-300) for c in h if c != "tools") \
    if same else 1
k.check(same and worst <= 1e-12, f"continued from a checkpoint taken every {past} increments (the first past the "
        f"kink): the history "
        f"within {worst:.1e} of the run never stopped (1e-12)")

# C. Refusals.
for opts, word in ((["-lower_die_motion", "path", "-lower_die_path", "1,0,0.5,1"], "-lower_die_path"),
                   (["-lower_die_path", "1,1"], "-lower_die_path"),
                   (["-lower_die_motion", "path"], "-lower_die_path"),
                   (["-lower_die_motion", "path", "-lower_die_path", "2,2", "-stroke_path", "1,2"], "-stroke_path")):
    p = run(tf, mpirun, 1, BASE + opts + ["-output", out("lower_bad.h5")], check=False)
    lines = [x for x in p.stderr.splitlines() + p.stdout.splitlines() if "error" in x.lower() and word in x]
    k.check(p.returncode != 0 and len(lines) >= 1, f"{' '.join(opts)}: refused (exit {p.returncode}) naming {word}: "
            f"{lines[0].strip() if lines else 'no such line'}")
k.done()
