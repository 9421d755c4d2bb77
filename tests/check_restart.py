"""Checkpoint and restart: a run continued from a checkpoint gives
the history and fields of the run that was never stopped, and computes only
what came after the checkpoint.

The case is the default squaring scene on the fast preset (inertia on, V-die
contact with friction, the paper's springback; about 3 s on 2 ranks), so the
checkpoint carries every part of the state: point states and coordinates,
the motion, contact nodes, slips, frames, pending forces, the reversed loads
of the springback stage, the energy accounts and the history.
  - The pressure scene with qm6 and -equilibrium_tol 0.005, whose energy input
    and out-of-balance force read the internal force of qm6's condensed
    modes (a restart without the condensation moved w_ext by 5e-7).
  - A resume, not a run again from increment 0 (which writes the same
    history): PETSc's own count of numeric factorizations (-log_view, which a
    restart may add) in the run that wrote the checkpoint and in the restart
    add up exactly to the uninterrupted run's (the same arithmetic takes the
    same solves; both sides hold the companion run of the error estimate
    once): a restart from zero counts the whole run again. After a rank was
    killed (its log lost), the restart's count is at most the uninterrupted
    run's less one per increment before the checkpoint.
  - Fields: the run that writes the checkpoint stops there
    (-rmin_max_increments, which a restart may drop) or is stopped by a
    signal, so its results hold only the field steps up to there: the
    restarted process must write the rest. The checkpoint's steps stay byte
    for byte (a restart that went on one step too early fails), and
    every step of every field (nodes, cells, /time, the die's displacement)
    is within the history's 1e-12 of the uninterrupted run's.
  - Same ranks: a restart repeats the same arithmetic on the same state, so
    the tolerance is 1e-12 relative to each column's largest value (round-off
    of a single changed operation would already show as 1e-16..1e-13, and a
    missing piece of state as 1e-10 or more: a node frame left out moved the
    next increment's load by 1e-15 relative and the end by 1e-7).
    Checkpoints in the loading stage and in the springback stage (lambda > 1),
    on 2 ranks; one written by SIGTERM (wherever it lands), on 1 rank; and
    the last one before a rank was killed (SIGKILL), on 2 ranks, continuing
    the .partial results the killed run left.
  - 1 -> 2 ranks: the checkpoint of a 1-rank run continued on 2 ranks agrees
    with the 1-rank run within 3e-6 relative for load, stroke and shape: 100
    times the largest measured with MUMPS (3.5e-9 on OpenBLAS Haswell, 3.0e-8
    on SkylakeX; 4.7e-8 with PETSc's LU, the bound then 5e-6); fields start
    anew in a new -output (same -output: refused).
  - Same ranks, 1e-12: measured 0 (bit for bit) in every case on both
    kernels; the bound is not round-off's but the smallest state defect's
    (above), so it stays.
  - A failed checkpoint write (its scratch file cannot be created) stops the
    run with one line naming -checkpoint, and leaves the previous checkpoint
    byte for byte as it was.
  - Bad restarts: a missing file, a checkpoint of another mesh or another
    stroke, and a checkpoint whose results file is gone give one line each,
    non-zero exit. Run-control options may change (a restart above adds
    -history_csv; the 1 -> 2 ranks one a new -output).
The 1-rank runs (the run never stopped, SIGTERM's restart, the 1-rank checkpoint and the bad restarts) are the
`np1` part, the rest the `np2` part, which reads the first's run and checkpoint (tests/CMakeLists.txt: its fixture;
the first on one core beside another test, the second with both cores).
"""
import filecmp
import os
import shutil
import signal
import subprocess
import sys
import time

import h5py
import numpy as np

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
part = sys.argv[4] if len(sys.argv) > 4 else "both"
k = Checks("restart" + (f" ({part})" if part != "both" else ""))
# The two parts' files in a folder of their own: the np2 part reads the np1 part's, which a test run between them
# must not overwrite (tests/check_full_disk.py writes a full_np1.h5 of its own).
os.makedirs("restart", exist_ok=True)
os.chdir("restart")
CASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-progress", "0"]


def fresh(*names):
    for n in names:
        for p in (out(n), out(n) + ".partial", out(n) + ".tmp"):
            if os.path.isdir(p):
                shutil.rmtree(p)
            elif os.path.exists(p):
                os.remove(p)


def history(name):
    with h5py.File(out(name), "r") as h:
        return {c: h["/history"][c][:] for c in h["/history"]}


def fields(name):
    """Every dataset of a result file with a row per field step: /time, the node and cell fields, the tools'
    displacements."""
    with h5py.File(out(name), "r") as h:
        got = {"/time": h["/time"][:]}
        for g in ("/vertex_fields", "/cell_fields"):
            got.update({f"{g}/{n}": h[g][n][:] for n in h[g]})
        got.update({f"/tools/{t}/displacement": h["/tools"][t]["displacement"][:] for t in h.get("/tools", {})})
    return got


def logged(name):
    """PETSc's event log of a run into name.log (-log_view: a restart may add or drop it)."""
    return ["-log_view", ":" + out(name + ".log")]


def factorizations(name):
    """PETSc's own count of numeric LU factorizations in a run's log (each stage's line summed; the most of any
    rank): what the process computed, whatever tubeform says."""
    with open(out(name + ".log")) as f:
        return sum(int(l.split()[1]) for l in f if l.startswith("MatLUFactorNum "))


def check_resumed(what, first, rest, full):
    """The restarted process factorized exactly what the uninterrupted run did after the checkpoint: the run
    that wrote the checkpoint and the restart together as often as the uninterrupted run (whose companion run
    for the error estimate the restart makes too; the interrupted run made none)."""
    f1, f2, f = factorizations(first), factorizations(rest), factorizations(full)
    k.check(f1 > 0 and f1 + f2 == f, f"{what}: the restart factorized {f2} times, the run that wrote the "
            f"checkpoint {f1}: together {f1 + f2}, the uninterrupted run {f} (PETSc's counts)")


def check_fields(what, result, before, ck, full):
    """The field steps the checkpoint counts on kept byte for byte; the others, which the interrupted results did
    not hold, written by the restarted process: all of them within 1e-12 of the uninterrupted run's."""
    with h5py.File(out(ck), "r") as h:
        n_ck = len(h["/run/times"])
    after, ref = fields(result), fields(full)
    n_before, n_full = len(before["/time"]), len(ref["/time"])
    kept = all(d in after and after[d][:n_ck].tobytes() == before[d][:n_ck].tobytes() for d in before)
    w, which = 0.0, ""
    for d, r in ref.items():
        a = after.get(d)
        if a is None or a.shape != r.shape:
            w, which = np.inf, f"{d} has {None if a is None else a.shape[0]} steps"
            break
        e = np.abs(a - r).max(initial=0) / max(np.abs(r).max(initial=0), 1e-300)
        if e > w:
            w, which = e, d
    k.check(n_ck <= n_before < n_full and kept and w <= 1e-12,
            f"{what}: the interrupted results held {n_before} of the {n_full} field steps, the checkpoint's "
            f"{n_ck} kept byte for byte: {'yes' if kept else 'NO'}; every step within {w:.1e} ({which}) of the "
            f"uninterrupted run's (1e-12)")


def worst(a, b, cols=None):
    """Largest difference of the history columns relative to each column's largest value."""
    w, which = 0.0, ""
    for c in cols or a:
        if a[c].shape != b[c].shape:
            return np.inf, f"{c} has {len(a[c])} vs {len(b[c])} rows"
        diff = np.where(a[c] == b[c], 0.0, np.abs(a[c] - b[c]))  # equal Infs (a flat side's radius) agree
        diff[np.isnan(diff)] = np.inf  # an Inf against a number, or a NaN, does not
        d = diff.max(initial=0) / max(np.abs(a[c][np.isfinite(a[c])]).max(initial=0), 1e-300)
        if d > w:
            w, which = d, c
    return w, which


def checkpoint_lambda(name):
    with h5py.File(out(name), "r") as h:
        return h["/run/lambda"][0], int(h["/run/increments"][0])


def error_lines(p):
    return [l for l in (p.stdout + p.stderr).splitlines() if "error" in l.lower() and "tubeform" in l]


# SIGTERM on 1 rank once a third of the history is written: a checkpoint, flagged results, restart.
def sigterm(full1, rows):
    fresh("sig.h5", "sig.csv", "ck_sig.h5")
    cmd = [tf] + CASE + ["-output", out("sig.h5"), "-history_csv", out("sig.csv"), "-checkpoint", out("ck_sig.h5")] + \
        logged("sig_first")
    proc = subprocess.Popen(cmd, cwd=src, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    t0 = time.time()
    while time.time() - t0 < 60 and proc.poll() is None:
        if os.path.exists(out("sig.csv") + ".partial"):
            with open(out("sig.csv") + ".partial") as f:
                if sum(1 for _ in f) > rows // 3:
                    break
        time.sleep(0.02)
    proc.send_signal(signal.SIGTERM)
    text, _ = proc.communicate(timeout=60)
    ok = proc.returncode != 0 and "interrupted by SIGTERM" in text and os.path.exists(out("ck_sig.h5"))
    k.check(ok, f"SIGTERM: non-zero exit {proc.returncode}, the stop named, a checkpoint written")
    if ok:
        with h5py.File(out("sig.h5"), "r") as h:
            k.check(h["/history"].attrs["interrupted"] == signal.SIGTERM,
                    "SIGTERM: the results are flagged interrupted")
        lam, inc = checkpoint_lambda("ck_sig.h5")
        before = fields("sig.h5")
        run(tf, mpirun, 1, CASE + ["-output", out("sig.h5"), "-history_csv", out("sig.csv"), "-restart",
                                   out("ck_sig.h5")] + logged("sig_rest"))
        h = history("sig.h5")
        w, col = worst(full1, h)
        with h5py.File(out("sig.h5"), "r") as f:
            opts = f.attrs["options"]
            opts = opts.decode() if isinstance(opts, bytes) else str(opts)
        k.check("-restart" in opts and "-unload reverse" in opts,  # (sorted: the last option is cut first)
                "the continued file's options attribute is the restarted run's, whole (a rewrite kept the old length)")
        csv_rows = sum(1 for _ in open(out("sig.csv"))) - 1
        k.check(w <= 1e-12 and csv_rows == len(full1["stroke"]),
                f"np=1 restart after SIGTERM at increment {inc}: history within {w:.1e} ({col}) (1e-12), "
                f"CSV whole ({csv_rows} rows)")
        check_resumed(f"np=1 restart after SIGTERM at increment {inc}", "sig_first", "sig_rest", "full_np1")
        check_fields(f"np=1 restart after SIGTERM at increment {inc}", "sig.h5", before, "ck_sig.h5", "full_np1.h5")


# 1 -> 2 ranks, the 1-rank run that writes the checkpoint (the np2 part continues it) and the bad restarts.
def one_rank_checkpoint(loading):
    fresh("ck1.h5", "part1.h5", "part12.h5", "gone.h5", "x.h5")
    run(tf, mpirun, 1, CASE + ["-output", out("part1.h5"), "-checkpoint", out("ck1.h5"), "-checkpoint_every",
                               loading * 2 // 3, "-rmin_max_increments", loading * 2 // 3], check=False)
    for opts, expect, what in (
        (["-restart", out("no_such.h5"), "-output", out("x.h5")], "no such checkpoint", "a missing checkpoint"),
        (["-restart", out("ck1.h5"), "-output", out("x.h5"), "-mesh_ntheta", 24], "mesh", "another mesh"),
        (["-restart", out("ck1.h5"), "-output", out("gone.h5")], "not in -output", "results gone"),
        (["-restart", out("ck1.h5"), "-output", out("x.h5"), "-stroke", 3], "-stroke is '3' here, '4.2'",
         "another stroke"),
    ):
        p = run(tf, mpirun, 1, CASE + opts, check=False)
        lines = error_lines(p)
        k.check(p.returncode != 0 and len(lines) == 1 and expect in lines[0], f"{what}: one line ({lines})")


# Same ranks: a checkpoint in the loading stage and one in the springback
# stage. The run that writes it stops there (-rmin_max_increments, which a
# restart may drop), so its results hold the field steps up to there only.
def same_ranks(full2, rows, loading):
    for every, stage in ((loading * 2 // 3, "loading"), (loading + (rows - loading) // 2, "springback")):
        fresh("part.h5", "ck.h5")
        p = run(tf, mpirun, 2, CASE + ["-output", out("part.h5"), "-checkpoint", out("ck.h5"), "-checkpoint_every",
                                       every, "-rmin_max_increments", every] + logged("part_first"), check=False)
        lam, inc = checkpoint_lambda("ck.h5")
        k.check(p.returncode != 0 and (lam < 1) == (stage == "loading") and inc == every,
                f"np=2 run stopped (exit {p.returncode}) with its checkpoint after increment {inc} (lambda {lam:.4f}), "
                f"in the {stage} stage")
        before = fields("part.h5")
        p = run(tf, mpirun, 2, CASE + ["-output", out("part.h5"), "-restart", out("ck.h5")] + logged("part_rest"))
        h = history("part.h5")
        w, col = worst(full2, h)
        k.check(w <= 1e-12, f"np=2 restart in the {stage} stage: history within {w:.1e} ({col}) (1e-12)")
        check_resumed(f"np=2 restart in the {stage} stage", "part_first", "part_rest", "full_np2")
        check_fields(f"np=2 restart in the {stage} stage", "part.h5", before, "ck.h5", "full_np2.h5")
        k.check("restarting from" in p.stdout, "the restart says where it continues from")


# The pressure scene with qm6 and -equilibrium_tol 0.005: the energy input from
# the supports and the out-of-balance force both read the internal force,
# which for qm6 depends on the condensation of each cell's last tangent.
def qm6_restart():
    QM6 = ["-options_file", f"{src}/options/pressure_plastic.opts", "-element", "qm6", "-equilibrium_tol", "0.005",
           "-progress", "0"]
    fresh("qm6_full.h5", "qm6.h5", "ck_qm6.h5")
    run(tf, mpirun, 2, QM6 + ["-output", out("qm6_full.h5")] + logged("qm6_full"))
    qfull = history("qm6_full.h5")
    qrows = len(qfull["stroke"])
    run(tf, mpirun, 2, QM6 + ["-output", out("qm6.h5"), "-checkpoint", out("ck_qm6.h5"), "-checkpoint_every",
                              qrows // 2, "-rmin_max_increments", qrows // 2] + logged("qm6_first"), check=False)
    run(tf, mpirun, 2, QM6 + ["-output", out("qm6.h5"), "-restart", out("ck_qm6.h5")] + logged("qm6_rest"))
    h = history("qm6.h5")
    w, col = worst(qfull, h)
    k.check(w <= 1e-12, f"np=2 restart of pressure, qm6, -equilibrium_tol 0.005 at increment {qrows // 2}: history "
            f"within {w:.1e} ({col}) (1e-12)")
    check_resumed("np=2 restart of pressure, qm6", "qm6_first", "qm6_rest", "qm6_full")


# A rank killed (SIGKILL) on 2 ranks: mpirun ends the job (no hang), the
# .partial results and the last checkpoint remain, and the restart continues
# the .partial file to the same history. The kill must land after a
# checkpoint and before the run ends: the run is watched until both are on
# disk (a checkpoint every 40 increments, half the history written) and a rank
# is killed then; if the run had already finished (a fast machine), it is
# tried again, up to KILL_ATTEMPTS times; the comparison is never skipped.
def rank_killed(full2, rows):
    # (a run of ~150 increments outlives the watch loop's 20 ms polling by far; 3 tries make a miss moot)
    KILL_ATTEMPTS = 3
    cmd = [mpirun, "-n", "2", tf] + CASE + ["-output", out("kill.h5"), "-history_csv", out("kill.csv"), "-checkpoint",
                                            out("ck_kill.h5"), "-checkpoint_every", "40", "-output_stroke", "4.2"]
    for attempt in range(1, KILL_ATTEMPTS + 1):
        fresh("kill.h5", "kill.csv", "ck_kill.h5")
        proc = subprocess.Popen(cmd, cwd=src, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        t0 = time.time()
        while time.time() - t0 < 300 and proc.poll() is None:
            if os.path.exists(out("ck_kill.h5")) and os.path.exists(out("kill.csv") + ".partial"):
                with open(out("kill.csv") + ".partial") as f:
                    if sum(1 for _ in f) > rows // 2:
                        break
            time.sleep(0.02)
        ranks = subprocess.run(["pgrep", "-P", str(proc.pid)], capture_output=True, text=True).stdout.split()
        killed = False
        if proc.poll() is None and len(ranks) == 2:
            try:
                os.kill(int(ranks[-1]), signal.SIGKILL)
                killed = True
            except ProcessLookupError:  # the rank ended between pgrep and the kill
                pass
        try:
            proc.communicate(timeout=60)
            ended = True
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.communicate()
            ended = False
        if killed or not ended:
            break
        print(f"       attempt {attempt}: the run ended before a rank could be killed (exit {proc.returncode}); again")
    k.check(killed and ended and proc.returncode != 0 and os.path.exists(out("kill.h5") + ".partial"),
            f"a rank killed (attempt {attempt} of {KILL_ATTEMPTS}): the job ends (exit {proc.returncode}) within 60 s, "
            f"the .partial results stay")
    have = ended and os.path.exists(out("ck_kill.h5"))
    k.check(have, "a rank killed: its last checkpoint is on disk")
    if have:
        lam, inc = checkpoint_lambda("ck_kill.h5")
        run(tf, mpirun, 2, CASE + ["-output", out("kill.h5"), "-history_csv", out("kill.csv"), "-restart",
                                   out("ck_kill.h5"), "-output_stroke", 4.2] + logged("kill_rest"))
        h = history("kill.h5")
        w, col = worst(full2, h)
        k.check(w <= 1e-12, f"np=2 restart after a rank was killed (checkpoint at increment {inc}): history within "
                f"{w:.1e} ({col}) (1e-12)")
        # (the killed run wrote no log: every increment before the checkpoint factorized at least once)
        f2, f = factorizations("kill_rest"), factorizations("full_np2")
        k.check(f2 <= f - inc, f"np=2 restart after a rank was killed: the restart factorized {f2} times, at most the "
                f"uninterrupted run's {f} less one for each of the checkpoint's {inc} increments")


# 1 -> 2 ranks: the np1 part's checkpoint continued on 2 ranks.
def one_to_two(full1):
    fresh("part12.h5")
    p = run(tf, mpirun, 2, CASE + ["-output", out("part1.h5"), "-restart", out("ck1.h5")], check=False)
    lines = error_lines(p)
    k.check(p.returncode != 0 and len(lines) >= 1 and "new -output" in lines[0],
            f"1 -> 2 ranks into the same -output: refused ({lines[:1]})")
    run(tf, mpirun, 2, CASE + ["-output", out("part12.h5"), "-restart", out("ck1.h5")])
    h = history("part12.h5")
    w, col = worst(full1, h, ["stroke", "load", "c_over_t", "deviation_ratio", "x_max", "y_max"])
    k.check(w <= 3e-6, f"1 -> 2 ranks: load, stroke and shape within {w:.1e} ({col}) of the 1-rank run (3e-6)")


# A checkpoint write that fails leaves the previous one intact.
def failed_write():
    fresh("ck_keep.h5", "restart_keep.h5")
    run(tf, mpirun, 2,
        CASE + ["-output", out("restart_keep.h5"), "-checkpoint", out("ck_keep.h5"), "-checkpoint_every", 100])
    shutil.copy(out("ck_keep.h5"), out("ck_keep_before.h5"))
    os.mkdir(out("ck_keep.h5") + ".tmp")  # the scratch file cannot be created
    fresh("keep2.h5")
    p = run(tf, mpirun, 2, CASE + ["-output", out("keep2.h5"), "-checkpoint", out("ck_keep.h5"), "-checkpoint_every",
                                   100], check=False)
    lines = error_lines(p)
    k.check(p.returncode != 0 and len(lines) >= 1 and "-checkpoint" in lines[0],
            f"failed checkpoint write: non-zero exit, named ({lines[:1]})")
    k.check(filecmp.cmp(out("ck_keep.h5"), out("ck_keep_before.h5"), shallow=False),
            "failed checkpoint write: the previous checkpoint is unchanged")
    fresh("ck_keep.h5")


# The run never stopped, on 2 and on 1 rank. On 2 ranks with -checkpoint as the runs it is compared with (a run
# that may write a checkpoint takes every rank; without one its error estimate's companions would take the second).
# The 1-rank ones are the np1 part's (the run never stopped, SIGTERM, the checkpoint continued on 2 ranks, the bad
# restarts); the np2 part reads its run and its checkpoint.
def np1_part():
    fresh("full_np1.h5")
    run(tf, mpirun, 1, CASE + ["-output", out("full_np1.h5")] + logged("full_np1"))
    full1 = history("full_np1.h5")
    sigterm(full1, len(full1["stroke"]))
    one_rank_checkpoint(int(np.sum(full1["stage"] == 0)))


def np2_part():
    fresh("full_np2.h5")
    run(tf, mpirun, 2, CASE + ["-output", out("full_np2.h5"), "-checkpoint", out("ck_full.h5")] + logged("full_np2"))
    full2 = history("full_np2.h5")
    rows, loading = len(full2["stroke"]), int(np.sum(full2["stage"] == 0))
    same_ranks(full2, rows, loading)
    qm6_restart()
    rank_killed(full2, rows)
    one_to_two(history("full_np1.h5"))
    failed_write()


if part in ("np1", "both"):
    np1_part()
if part in ("np2", "both"):
    np2_part()
k.done()
