"""Interrupted runs: SIGINT, SIGTERM and a scheduler's warning SIGUSR1 end a
run with its results written and flagged, one line naming the signal, and a
non-zero exit on every rank, whenever the signal comes.

How a job is stopped decides how long it has (Open MPI 4.1, measured here):
mpirun that receives SIGTERM sends its ranks SIGTERM one second later and
SIGKILL one second after that; a batch system's time limit signals mpirun and
every rank at once (mpirun adds its own SIGTERM a second later); `timeout`
signals mpirun twice (itself, then its process group), and mpirun then
leaves at once after a SIGTERM to each rank; mpirun killed outright tells its
ranks nothing. SIGUSR1 is forwarded without a kill. The run drops the
increment in progress at its next solve (the ranks agree on the signal before
every solve) and writes what it has; a second SIGTERM is caught as the first
(METIS gave rank 0's handler back good for one signal only: the second ended
it silently); a rank whose mpirun has gone gets a SIGTERM of its own
(parent-death signal), stops the same way, and its line, which cannot reach
anyone then, is in the file's stop_reason.

The case is the paper's tube on the fast preset, pressed to 1.5 mm (119
loading rows, 10 of springback, the companion run of the error estimate
after them), with a field step at every increment (-output_every 1), so that
a signal often falls into a write. Each try signals at a chosen moment,
found by watching the run's history CSV and result file: in the loading (at
a random row), at the first springback row, at the last row (the final
write), during the companion (once the results are in place), and at a
random time. 1 rank is signalled as a process group; 2 ranks as a batch
system does (mpirun and every rank), as `timeout --foreground` does (mpirun
alone), as `timeout` does (mpirun twice, 20 ms apart), and by SIGKILL to
mpirun. Every try must end within 5 s of its signal (`timeout -k 5`), every
process of the job gone, with:
  - the results in place (no .partial of any kind left) and readable (every
    history column and the last field step read back, finite);
  - flagged stopped, interrupted = the signal's number, stop_reason naming
    it, and one line "interrupted by SIG..." with a non-zero exit (no line
    when mpirun left before its ranks could print); or, when the signal came
    after the run's end, complete (stopped = 0, the full stroke) with either
    no error line and exit 0 (after the estimate too), one line saying the
    companion run was interrupted and the results are complete, or, after the
    run's last line, no error line whatever the exit (PetscFinalize gives the
    signal its default action back; mpirun signalled exits 1).
Before the storm, SIGINT to 1 rank and SIGUSR1 to mpirun (2 ranks).
The seed is fixed (a failure repeats); the moments land where the run is.
The 1-rank tries are the `np1` part, the 2-rank ones the `np2` part (tests/CMakeLists.txt: the first beside another
test on the other core, the second with both cores); each must reach both a stopped run and one past its end.
"""
import os
import random
import signal
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np

from tfcheck import Checks, args, out

tf, mpirun, src = args()
part = sys.argv[4] if len(sys.argv) > 4 else "both"
NPS = {"np1": (1,), "np2": (2,)}.get(part, (1, 2))
k = Checks("signals" + (f" ({part})" if part != "both" else ""))
CASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-stroke", "1.5", "-output_every", "1", "-progress", "0"]
LOADING_ROWS, ROWS = 119, 129  # this case's history: rows of the loading (with row 0), of the whole run
GRACE = 5  # s from the signal to SIGKILL, as `timeout -k 5` gives
rng = random.Random(44 + sum(NPS))  # (each part its own sequence)


def job_processes(leader):
    """The pids of a job started as a session leader: mpirun and its ranks (a batch system's job)."""
    pids = []
    for d in os.listdir("/proc"):
        if d.isdigit():
            try:
                stat = open(f"/proc/{d}/stat").read()
            except OSError:
                continue
            if int(stat.rsplit(")", 1)[1].split()[3]) == leader:  # field 6: the session id
                pids.append(int(d))
    return pids


def send(pids, sig):
    for pid in pids:
        try:
            os.kill(pid, sig)
        except ProcessLookupError:
            pass


def stages(path):
    """The stage column of the history CSV being written (its .partial); [] before it exists."""
    try:
        with open(path + ".partial") as f:
            lines = f.read().splitlines()
    except OSError:
        return []
    at = lines[0].split(",").index("stage") if lines else 0
    return [float(l.split(",")[at]) for l in lines[1:] if l.count(",") == lines[0].count(",")]


def wait_for(proc, ready, limit=120):
    """Polls ready() every 2 ms until it holds; False if the run ended first (or after `limit` s)."""
    t0 = time.time()
    while proc.poll() is None and time.time() - t0 < limit:
        if ready():
            return True
        time.sleep(0.002)
    return False


def attempt(np_, sig, moment, mode, name):
    f, csv = out(f"{name}.h5"), out(f"{name}.csv")
    for p in (f, csv, f[:-3] + ".xmf"):
        for q in (p, p + ".partial", p + ".estimate.partial"):
            if os.path.exists(q):
                os.remove(q)
    env = dict(os.environ)
    if env.get("OMPI_MCA_orte_tmpdir_base"):  # each run its own Open MPI session directory (tfcheck.run)
        os.makedirs(env["OMPI_MCA_orte_tmpdir_base"], exist_ok=True)
        env["OMPI_MCA_orte_tmpdir_base"] = tempfile.mkdtemp(dir=env["OMPI_MCA_orte_tmpdir_base"])
    cmd = ([mpirun, "-n", str(np_)] if np_ > 1 else []) + [tf] + CASE + ["-output", f, "-history_csv", csv]
    proc = subprocess.Popen(cmd, cwd=src, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            start_new_session=True, env=env)
    if moment.startswith("loading"):
        at = rng.randrange(5, LOADING_ROWS - 5)
        moment = f"loading (row {at})"
        reached = wait_for(proc, lambda: len(stages(csv)) >= at)
    elif moment == "springback":
        reached = wait_for(proc, lambda: max(stages(csv) or [0]) >= 1)
    elif moment == "last row":
        reached = wait_for(proc, lambda: len(stages(csv)) >= ROWS)
    elif moment == "companion":
        reached = wait_for(proc, lambda: os.path.exists(f))
        time.sleep(rng.uniform(0, 0.2))
    else:  # a random time after the results were opened
        reached = wait_for(proc, lambda: os.path.exists(f + ".partial"))
        time.sleep(rng.uniform(0, 1.5 if np_ == 1 else 6))
    ts = time.time()
    if mode == "kill mpirun":  # mpirun killed outright: its ranks learn it from the kernel (a SIGTERM of their own)
        send([proc.pid], signal.SIGKILL)
    elif mode in ("mpirun", "timeout"):
        send([proc.pid], sig)
        if mode == "timeout":  # `timeout` signals mpirun, then its own process group, mpirun in it
            time.sleep(0.02)
            send([proc.pid], sig)
    elif np_ > 1:
        send(job_processes(proc.pid), sig)
    else:
        os.killpg(proc.pid, sig)
    late = False
    try:
        text, _ = proc.communicate(timeout=GRACE)
    except subprocess.TimeoutExpired:
        send(job_processes(proc.pid), signal.SIGKILL)
        text, _ = proc.communicate()
        late = True
    launcher_left = time.time() - ts
    # The job has ended when its last process has: ranks that mpirun left behind finish on their own.
    while job_processes(proc.pid) and time.time() - ts < GRACE:
        time.sleep(0.01)
    if job_processes(proc.pid):
        send(job_processes(proc.pid), signal.SIGKILL)
        late = True
    took = time.time() - ts
    # mpirun that left before it would signal its ranks (a second SIGTERM) takes their output with it: the
    # reason is then in the file alone.
    orphaned = np_ > 1 and launcher_left < 0.9
    lines = [l for l in text.splitlines() if l.startswith("tubeform: error")]
    label = f"np={np_} {signal.Signals(sig).name} to {mode if mode != 'job' else 'the job'} at {moment}"
    if not reached:
        label += " (the run ended before that moment)"
    left = [q for p in (f, csv, f[:-3] + ".xmf") for q in (p + ".partial", p + ".estimate.partial")
            if os.path.exists(q)]
    readable, flags, whole, what, reason = False, None, False, "no result file", ""
    if os.path.exists(f):
        try:
            with h5py.File(f, "r") as h:
                hist = {c: h["/history"][c][:] for c in h["/history"]}
                last = h["/vertex_fields/displacement_u"][-1]
                a = h["/history"].attrs
                flags = (int(a["stopped"]), int(a["interrupted"]))
                reason = a["stop_reason"].decode() if "stop_reason" in a else ""
                # (Inf is a flat side's corner radius, the only column where it is a value)
                readable = all(np.isfinite(v).all() or (c.startswith("r_corner") and not np.isnan(v).any())
                               for c, v in hist.items()) and np.isfinite(last).all()
                whole = hist["stroke"].max() >= 1.5 - 1e-9 and hist["stage"][-1] >= 1 and len(hist["stroke"]) == ROWS
                what = f"{len(hist['stroke'])} rows, stage {hist['stage'][-1]:g}, stopped {flags[0]}, " \
                       f"interrupted {flags[1]}"
        except (OSError, KeyError) as e:
            what = f"unreadable: {e}"
    expect = int(signal.SIGTERM if np_ > 1 and sig == signal.SIGINT else sig)
    name_ok = lambda l: f"interrupted by {signal.Signals(expect).name}" in l
    if flags == (1, expect):
        said = orphaned and not lines or proc.returncode != 0 and len(lines) == 1 and name_ok(lines[0])
        ended = said and name_ok(reason)
        kind = "flagged"
    elif flags == (0, 0) and whole:
        # (after its last line, PetscFinalize gives the signals their default action back: a signal then ends
        # the process, which had nothing left to do; mpirun signalled then exits 1 whatever its ranks did)
        finished = "tubeform: self-checks" in text and not lines
        ended = orphaned and not lines or (proc.returncode == 0 and not lines) or (
            proc.returncode != 0 and len(lines) == 1 and name_ok(lines[0]) and "companion" in lines[0]
            and "complete" in lines[0]) or finished
        kind = "complete"
    else:
        ended, kind = False, "neither flagged nor complete"
    ok = not late and readable and ended and not left
    k.check(ok, f"{label}: {kind}, {what}; exit {proc.returncode}, the job out {took:.2f} s after the signal"
            + (f" (mpirun left after {launcher_left:.2f} s)" if orphaned else "")
            + (" (SIGKILL: not out within 5 s)" if late else "") + (f", left {left}" if left else "")
            + f"; {lines[:1] if lines else 'no error line'}" + (f"; stop_reason '{reason}'" if reason else ""))
    return kind


t_start = time.time()
if 1 in NPS:
    attempt(1, signal.SIGINT, "loading", "job", "sigint_np1")
if 2 in NPS:
    attempt(2, signal.SIGUSR1, "loading", "mpirun", "sigusr1_np2")
# 1 rank: its process group; 2 ranks: mpirun and every rank at once (a batch system), mpirun alone
# (`timeout --foreground`, a kill), mpirun twice (`timeout`), mpirun killed (SIGKILL).
TRIES = {1: [("loading", "job"), ("springback", "job"), ("last row", "job"), ("companion", "job"), ("random", "job")],
         2: [("loading", "job"), ("springback", "job"), ("last row", "job"), ("companion", "timeout"),
             ("loading", "timeout"), ("random", "mpirun"), ("loading", "kill mpirun")]}
for np_ in NPS:
    kinds = [attempt(np_, signal.SIGTERM, moment, mode, f"storm_np{np_}_{i}") for i, (moment, mode) in
             enumerate(TRIES[np_])]
    k.check(kinds.count("flagged") >= 2 and kinds.count("complete") >= 1,
            f"np={np_}: the moments reached both a stopped run and one past its end: {kinds} "
            f"({time.time() - t_start:.0f} s)")
k.done()
