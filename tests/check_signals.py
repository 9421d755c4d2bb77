"""Interrupted runs: SIGINT, SIGTERM and a scheduler's warning
SIGUSR1 end a run at the end of the current increment with its results
written and flagged, one line naming the signal, and a non-zero exit on
every rank. One rank without mpirun gets SIGINT itself (Ctrl-C); on 2 ranks
mpirun gets SIGUSR1 (it forwards it) and SIGTERM (it sends the ranks
SIGTERM, then SIGKILL a few seconds later: the run must be out by then).
The run is the paper's default case on its forward increments
(-equilibrium_tol 0: about half a minute; the default equilibrium increments
take 4 s), signalled once its result file has been created and it has had
2 s to get going. A signal during the error estimate's companion run (after
the run's end): the results complete, flagged interrupted, one line.
"""
import os
import signal
import subprocess
import time

import h5py
import numpy as np

from tfcheck import Checks, args, out

tf, mpirun, src = args()
k = Checks("signals")


def interrupted_run(np_, sig, name, extra=("-equilibrium_tol", "0"), companion=False):
    f = out(f"{name}.h5")
    for p in (f, f + ".partial"):
        if os.path.exists(p):
            os.remove(p)
    cmd = ([mpirun, "-n", str(np_)] if np_ > 1 else []) + [tf, "-options_file", f"{src}/options/squaring.opts",
                                                           "-output", f, "-progress", "0"] + list(extra)
    p = subprocess.Popen(cmd, cwd=src, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    t0 = time.time()
    started = f + (".companion.h5.partial" if companion else ".partial")
    while not os.path.exists(started) and time.time() - t0 < 60:
        time.sleep(0.01)
    time.sleep(0 if companion else 2)
    p.send_signal(sig)
    try:
        text, _ = p.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        p.kill()
        text, _ = p.communicate()
    lines = [l for l in text.splitlines() if l.startswith("tubeform: error")]
    label = f"np={np_} {signal.Signals(sig).name}" + (" in the companion run" if companion else "")
    expect = signal.SIGTERM if np_ > 1 and sig == signal.SIGINT else sig
    k.check(p.returncode != 0 and len(lines) == 1 and f"interrupted by {signal.Signals(expect).name}" in lines[0],
            f"{label}: exit {p.returncode}, one line naming the signal: {lines}")
    ok = os.path.exists(f) and not os.path.exists(f + ".partial")
    if ok:
        with h5py.File(f, "r") as h:
            a = h["/history"].attrs
            rows = h["/history/stroke"].shape[0]
            ok = (a["stopped"] == 1 and a["interrupted"] == int(expect) and rows > 2
                  and all(np.isfinite(h["/history"][c][:]).all() for c in h["/history"])
                  and h["/vertex_fields/displacement_u"].shape[0] >= 2)
            stroke = h["/history/stroke"][-1]
            # the companion runs after the run's end: the history is whole (loading to 4.2 mm, springback)
            ok = ok and (not companion or (h["/history/stroke"][:].max() >= 4.2 - 1e-9 and
                                           "companion" in lines[0]))
    k.check(ok, f"{label}: results written up to the stop, flagged stopped and interrupted, finite"
            + (f" (stroke {stroke:.3f} mm, {rows} rows)" if ok else ""))


interrupted_run(1, signal.SIGINT, "sigint_np1")
interrupted_run(2, signal.SIGUSR1, "sigusr1_np2")
interrupted_run(2, signal.SIGTERM, "sigterm_np2")
interrupted_run(1, signal.SIGINT, "sigint_companion", extra=(), companion=True)
k.done()
