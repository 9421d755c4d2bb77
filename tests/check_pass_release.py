"""Each pass's release (-unload, -pass<N>_unload): a pass lets the tube go by reversing its contact forces, by
withdrawing its dies, or (the last pass) not at all.

The paper's tube (options/squaring.opts, the fast preset, the quarter model):
  ELASTIC:  pressed 0.02 mm (elastic), its dies withdrawn (-unload withdraw), then a second pass to U = 1.5 mm
            released by the paper's springback (-pass2_unload reverse);
  ONE:      the same tube pressed once to U = 1.5 mm and released by the paper's springback;
  WITHDRAW: pressed 1.5 mm, its dies withdrawn, turned a quarter turn (-pass2_turn 90), pressed again to 1.5 mm and
            its dies withdrawn (the second pass takes the first pass's -unload);
  LOADED:   WITHDRAW with -pass2_unload none: the run ends with the second pass loaded.

A. An elastic press whose dies are withdrawn gives the tube back: the second pass of ELASTIC presses as ONE. Its dies
   start where ONE's did (pass2_start_stroke within 1e-4 mm of 0: the tube is round again; a die drawn on a tube
   still pressed starts 0.02 mm back), and the end of its press and of its springback (load, C1, C2, C/t) is ONE's
   within 1e-3 of each column's largest (tests/check_hold.py I's bound for a pass after an elastic one; measured
   7.5e-5: the friction's micro-slips and the passes' other increments).
B. A withdrawal takes the dies back to where their pass started: the history's stroke at the end of each release of
   WITHDRAW is the pass's start (0, pass2_start_stroke) within 1e-12 mm and the dies carry no load there (every node
   has left them by the separation event: 0 within 1e-9 of the largest load). Withdrawn from U = 1.5 to 0, a die
   that stayed at the end of its press, or stepped back by a stage's length, misses by 1.5 mm.
C. Energy in every stage of WITHDRAW, from the history's columns: the model's share of the punch load (half, in the
   quarter model) integrated over the stroke, in each press and each withdrawal (where the tube pushes the die back:
   negative), equals the growth of the internal and friction work over the stage within 5e-3 of the pass's press
   work (tests/check_passes.py B's bound; measured 2e-4). A withdrawal whose load is read as the paper's release
   reads it (from reversed forces, none here) leaves the springback's work unmatched: the run stops at its own
   energy check (26 % after two increments).
D. The last pass unreleased (LOADED): the history ends with the second press (stages 0-2) and is WITHDRAW's up to
   there, every column equal (the limiter of the last row aside: it says the run ended); its second pass's
   `unloaded_` attributes are its loaded ones (as a single pass's under -unload none), and the summary prints no
   springback line for it. Each pass's springback line names its own
   release: "the dies withdrawn" for both of WITHDRAW's, the paper's for ELASTIC's second.
E. WITHDRAW on 2 ranks: load, C1, C2, C/t at each stage's end within 3e-5 of each column's largest value
   (tests/check_passes.py C's bound).
F. A checkpoint half way through the second pass's withdrawal, continued with -restart: the history of WITHDRAW
   within 1e-12 of each column's largest value (tests/check_restart.py's bound): the restart rebuilds the pass's
   dies and release from the options, its dies' start and strokes from the checkpoint.
Bad input (a pass after an unreleased one, withdrawal with the half model or with side dies): tests/check_bad_input.py.
"""
import h5py
import numpy as np

from tfcheck import Checks, args, checkpoint_at, out, run, run_all

tf, mpirun, src = args()
k = Checks("pass_release")
U = 1.5
BASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-error_estimate", 0, "-progress", 0, "-output_stroke", 0]
WITHDRAW = BASE + ["-stroke", U, "-unload", "withdraw", "-pass2_stroke", U, "-pass2_turn", 90]
RUNS = {"release_elastic.h5": BASE + ["-stroke", 0.02, "-unload", "withdraw", "-pass2_stroke", U,
                                      "-pass2_unload", "reverse"],
        "release_one.h5": BASE + ["-stroke", U],
        "release_withdraw.h5": WITHDRAW,
        "release_loaded.h5": WITHDRAW + ["-pass2_unload", "none"]}
done = dict(zip(RUNS, run_all(tf, mpirun, [opts + ["-output", out(name)] for name, opts in RUNS.items()],
                              timeout=600)))


def read(name):
    with h5py.File(out(name), "r") as f:
        return {c: f["/history"][c][:] for c in f["/history"]}, dict(f["/history"].attrs)


def end_of(h, stage, col):
    return h[col][h["stage"] == stage][-1]


# A. After an elastic press withdrawn, the second pass presses as one pass.
el, el_attrs = read("release_elastic.h5")
one, _ = read("release_one.h5")
start = el_attrs["pass2_start_stroke"]
k.check(abs(start) <= 1e-4, f"A. the second pass's dies start at U = {start:.2e} mm, the round tube's zero within "
        f"1e-4 mm")
worst, where = 0.0, ""
for col in ("load", "x_max", "y_max", "c_over_t"):
    for mine, theirs in ((2, 0), (3, 1)):
        gap = abs(end_of(el, mine, col) - end_of(one, theirs, col)) / np.abs(one[col]).max()
        if gap >= worst:
            worst, where = gap, f"{col} at the end of stage {mine}"
k.check(worst <= 1e-3, f"A. ELASTIC's second pass ends its press and its springback as ONE: within {worst:.1e} of "
        f"the largest ({where}; 1e-3)")

# B. Each withdrawal ends where its pass started, the dies free.
wd, wd_attrs = read("release_withdraw.h5")
for stage, want in ((1, 0.0), (3, wd_attrs["pass2_start_stroke"])):
    back, load = end_of(wd, stage, "stroke"), end_of(wd, stage, "load")
    k.check(abs(back - want) <= 1e-12 and abs(load) <= 1e-9 * wd["load"].max(),
            f"B. stage {stage}: the dies withdrawn to U = {back:.3g} mm (the pass's start {want:.3g}), load {load:.2e} "
            f"N/mm")

# C. Energy in every stage.
for stage in range(4):
    rows = np.where(wd["stage"] == stage)[0]
    before = rows[0] - 1 if rows[0] > 0 else None
    # (a press from where its dies start, touching the tube: the first's 0, a later one's pass<N>_start_stroke; a
    # withdrawal from where the press before it ended)
    start = 0.0 if stage == 0 else wd["stroke"][before] if stage % 2 else wd_attrs[f"pass{stage // 2 + 1}_start_stroke"]
    stroke = np.concatenate(([start], wd["stroke"][rows]))
    load = np.concatenate(([0.0] if stage % 2 == 0 else [wd["load"][before]], wd["load"][rows]))
    work = 0.5 * np.sum(0.5 * (load[1:] + load[:-1]) * np.diff(stroke))  # (the quarter's half of the load)
    grown = sum(wd[c][rows[-1]] - (0.0 if before is None else wd[c][before]) for c in ("w_int", "w_friction"))
    press = stage - stage % 2
    rows_p = np.where(wd["stage"] == press)[0]
    scale = wd["w_int"][rows_p[-1]] + wd["w_friction"][rows_p[-1]] - (
        0.0 if press == 0 else wd["w_int"][rows_p[0] - 1] + wd["w_friction"][rows_p[0] - 1])
    k.check(abs(grown - work) <= 5e-3 * scale,
            f"C. stage {stage} ({'withdrawal' if stage % 2 else 'press'}): internal and friction work grow by "
            f"{grown:.6g}, the punch load's work is {work:.6g}: within {abs(grown - work) / scale:.1e} of the "
            f"pass's press work (5e-3)")

# D. The last pass unreleased.
ld, ld_attrs = read("release_loaded.h5")
same = len(ld["stage"]) == int(np.sum(wd["stage"] <= 2))
gap = max(np.abs(ld[c][:-1] - wd[c][:len(ld[c]) - 1]).max() for c in ld) if same else 1.0
last = max(np.abs(ld[c][-1] - wd[c][len(ld[c]) - 1]) for c in ld if c != "limiter") if same else 1.0
k.check(sorted(set(ld["stage"].astype(int))) == [0, 1, 2] and same and gap == 0 and last == 0,
        f"D. LOADED ends with the second press: stages {sorted(set(ld['stage'].astype(int)))}, WITHDRAW's history to "
        f"there (largest difference {max(gap, last):.1e})")
shapes = ("c_over_t", "x_max", "y_max")
k.check(all(ld_attrs[f"pass2_unloaded_{c}"] == ld_attrs[f"pass2_loaded_{c}"] for c in shapes) and
        all(wd_attrs[f"pass2_unloaded_{c}"] != wd_attrs[f"pass2_loaded_{c}"] for c in shapes),
        "D. LOADED's second pass: its unloaded C/t, C1, C2 are its loaded ones (no springback), WITHDRAW's differ")
lines = {name: [l for l in done[name].stdout.splitlines() if "after springback" in l] for name in RUNS}
k.check(len(lines["release_loaded.h5"]) == 1 and len(lines["release_withdraw.h5"]) == 2 and
        all("(the dies withdrawn)" in l for l in lines["release_withdraw.h5"]) and
        "second pass: after springback (the contact forces reversed" in lines["release_elastic.h5"][-1] and
        "(the dies withdrawn)" in lines["release_elastic.h5"][0],
        "D. each pass's springback line names its release: " + " | ".join(
            l.split(":")[1].strip() for l in lines["release_elastic.h5"]))

# E. 1 vs 2 ranks.
run(tf, mpirun, 2, WITHDRAW + ["-output", out("release_withdraw_np2.h5")], timeout=600)
two, _ = read("release_withdraw_np2.h5")
worst = max(abs(end_of(wd, s, c) - end_of(two, s, c)) / np.abs(wd[c]).max()
            for c in ("load", "x_max", "y_max", "c_over_t") for s in range(4))
k.check(worst <= 3e-5, f"E. WITHDRAW on 2 ranks: load, C1, C2, C/t at each stage's end within {worst:.1e} of the "
        f"largest value (3e-5)")

# F. A checkpoint inside the second withdrawal, continued.
ck = out("release_ck.h5")
every = int(np.sum(wd["stage"] <= 2)) + int(np.sum(wd["stage"] == 3)) // 2
part_opts = WITHDRAW + ["-output", out("release_part.h5")]
checkpoint_at(tf, mpirun, 1, part_opts, ck, every, timeout=600)
cont = run(tf, mpirun, 1, part_opts + ["-restart", ck], check=False, timeout=600)
with h5py.File(ck, "r") as c:
    lam = c["/run/lambda"][0]
part, _ = read("release_part.h5")
cols = list(wd)
same_shape = all(part[c].shape == wd[c].shape for c in cols)
worst = max(np.abs(part[c] - wd[c]).max() / max(np.abs(wd[c]).max(), 1e-300) for c in cols) if same_shape else 1.0
k.check(cont.returncode == 0 and same_shape and worst <= 1e-12 and 3 < lam < 4,
        f"F. continued from a checkpoint inside the second withdrawal (lambda {lam:.3f}, exit {cont.returncode}): "
        f"the history within {worst:.1e} (1e-12)")
k.done()
