"""A die that strokes in pulses (-lower_die_motion pulse, -lower_die_pulse_amplitude A, -lower_die_pulse_period P:
tool/motion_pulse.cpp): the lower die rises by y(U) = U - A tri(U / P), tri the triangle wave rising from 0 to 1
over the first half of each period and back over the second, while the upper die comes down by U. The paper's tube
(options/squaring.opts, fast preset, the half model), pressed to U = 2 mm: A = 0.3, P = 0.5, four pulses in which
the lower die backs off by 0.1 mm (slope 1 - 2 A / P = -0.2) and catches up (slope 2.2).

A. Amplitude 0 is the plain motion: its history is that of the lower die's path straight up by U
   (-lower_die_motion path -lower_die_path 2,2, motion_schedule.cpp), bit for bit: both place the die at
   0 + U x 1 (no kinks before the end). Tolerance 0: the same operations on the same numbers.
B. With A = 0.3: at every field step of the press the lower die's displacement in the results is y(U) of the
   closed form above at the step's stroke U = 2 lambda, x 0, within 1e-12 mm (a few operations on numbers ~2 mm);
   the history has a row at each half period k P / 2 below the end (the kinks, where an increment ends) within
   1e-12; the lower die moves down on the first half of a pulse (its displacement falls at each field step from
   U = 0.5 to 0.75, with fields every 0.05 mm of stroke);
   the energy balance recomputed from the history (the upper die's half of the load over U, the lower die's reported
   force over y(U): the same sum as tests/check_lower_path.py) holds within tests/check_squaring.py's 5e-3 at
   every increment of the press; half a pulse on (U = 0.75, 1.25, 1.75, rows at kinks) the load is below the plain
   motion's by more than 1 % (the dies are 0.3 mm less closed there: the plain motion's load rises about 2 % over
   the 0.15 mm of stroke that closes them as far; a die that did not move behind would give 0).
   On 2 ranks: load, x_max, y_max, C/t within tests/check_squaring.py's 1.3e-8 of their largest value.
C. Refusals, one line each naming the option: a negative or non-number amplitude, a period of 0, an amplitude
   without -lower_die_motion pulse, the motion with -stroke_path.
"""
import numpy as np

from tfcheck import Checks, args, lower_die_steps, out, ran_to_end, run, run_all, self_checks

tf, mpirun, src = args()
k = Checks("pulse")
BASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-stroke", 2, "-progress", 0, "-error_estimate", 0]
A, P = 0.3, 0.5
PULSE = ["-lower_die_motion", "pulse", "-lower_die_pulse_amplitude", A, "-lower_die_pulse_period", P]
FIELDS = ["-output_stroke", 0.05]  # (fields every 0.05 mm of stroke: five on each half pulse)


def press(name, opts, n=1, p=None):
    """The run's history and tools; a check that it ran to its end (`p`: the run, made already)."""
    return ran_to_end(k, tf, mpirun, n, BASE + opts, out(name), " ".join(map(str, opts)), p)


def rise(U):
    """The closed form: y(U) = U - A tri(U / P)."""
    f = U / P - np.floor(U / P)
    return U - A * np.where(f < 0.5, 2 * f, 2 * (1 - f))


# A's and B's single-rank presses side by side (the machine's two cores), before B's 2-rank one; press() checks each.
ONE = {"pulse.h5": PULSE + FIELDS, "pulse_plain.h5": ["-lower_die_motion", "path", "-lower_die_path", "2,2"],
       "pulse_zero.h5": ["-lower_die_motion", "pulse", "-lower_die_pulse_amplitude", 0, "-lower_die_pulse_period", P]}
made = dict(zip(ONE, run_all(tf, mpirun, [BASE + o + ["-output", out(n)] for n, o in ONE.items()], check=False,
                             timeout=600)))

# A. Amplitude 0: the plain motion, bit for bit.
plain = press("pulse_plain.h5", ONE["pulse_plain.h5"], p=made["pulse_plain.h5"])
zero = press("pulse_zero.h5", ONE["pulse_zero.h5"], p=made["pulse_zero.h5"])
cols = [c for c in plain if c != "tools"]
same = all(zero[c].shape == plain[c].shape and zero[c].tobytes() == plain[c].tobytes() for c in cols)
k.check(same, f"amplitude 0 gives the plain motion's history bit for bit ({len(cols)} columns, "
        f"{len(plain['stroke'])} rows)")

# B. Four pulses.
h = press("pulse.h5", ONE["pulse.h5"], p=made["pulse.h5"])
U = h["stroke"]
lam, disp = lower_die_steps(out("pulse.h5"), h)
steps = np.flatnonzero(lam <= 1)
want = rise(2 * lam[steps])
miss = max(np.abs(disp[steps, :, 0]).max(), np.abs(disp[steps, :, 1] - want[:, None]).max()) \
    if len(disp) == len(lam) and len(steps) > 5 else np.inf
k.check(miss <= 1e-12, f"the lower die's displacement at {len(steps)} field steps is y(U) of the closed form within "
        f"{miss:.1e} mm (1e-12)")
kinks = np.arange(1, 8) * P / 2
off = max(np.abs(U - s).min() for s in kinks)
k.check(off <= 1e-12, f"a row at each of the {len(kinks)} kinks k P / 2 (the farthest {off:.1e} off; 1e-12)")
back = steps[(2 * lam[steps] > 0.5 - 1e-9) & (2 * lam[steps] < 0.75 + 1e-9)]
dy = np.diff(disp[back, 0, 1]) if len(back) > 1 else np.zeros(1)
k.check(len(back) > 2 and (dy < 0).all(), f"the die backs off on the first half of a pulse: its y falls at each of "
        f"{len(back)} field steps from U = 0.5 to 0.75 (by {-dy.sum() if len(dy) else 0:.4f} mm; the closed form 0.05)")
loading = h["stage"] == 0
a = self_checks(h, lower_rise=rise(U))[0]
e = np.abs(a[1:][loading[1:]]).max()
k.check(e < 5e-3, f"the energy balance from the history and y(U) within {e:.1e} at every increment of the press "
        f"(5e-3)")
mid = np.arange(1, 4) * P + P / 2  # (half a pulse on: the dies 0.3 mm less closed than the plain motion's)
on, ref = [np.interp(mid, r["stroke"][r["stage"] == 0], r["load"][r["stage"] == 0]) for r in (h, plain)]
drop = (1 - on / ref).min()
k.check(drop > 0.01, f"the pulses change the run: half a pulse on (U = {', '.join(map(str, mid))}) the load is below "
        f"the plain motion's by {drop:.1%} at least (1 %)")
two = press("pulse_np2.h5", PULSE + FIELDS, 2)
same = two["load"].shape == h["load"].shape
rel = max(np.abs(two[c] - h[c]).max() / np.abs(h[c]).max() for c in ("load", "x_max", "y_max", "c_over_t")) \
    if same else 1
k.check(same and rel <= 1.3e-8, f"2 ranks: load, x_max, y_max, C/t within {rel:.1e} of 1 rank's (1.3e-8)")

# C. Refusals.
for opts, word in ((["-lower_die_motion", "pulse", "-lower_die_pulse_amplitude", -0.1], "-lower_die_pulse_amplitude"),
                   (["-lower_die_motion", "pulse", "-lower_die_pulse_amplitude", "nan"], "-lower_die_pulse_amplitude"),
                   (["-lower_die_motion", "pulse", "-lower_die_pulse_period", 0], "-lower_die_pulse_period"),
                   (["-lower_die_pulse_amplitude", 0.1], "-lower_die_pulse_amplitude"),
                   (PULSE + ["-stroke_path", "1,2"], "-stroke_path")):
    p = run(tf, mpirun, 1, BASE + opts + ["-output", out("pulse_bad.h5")], check=False)
    lines = [x for x in p.stderr.splitlines() + p.stdout.splitlines() if "error" in x.lower() and word in x]
    k.check(p.returncode != 0 and len(lines) == 1, f"{' '.join(map(str, opts))}: refused (exit {p.returncode}) in one "
            f"line naming {word}: {lines[0].strip() if lines else 'no such line'}")
k.done()
