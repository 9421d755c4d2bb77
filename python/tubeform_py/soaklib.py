"""The soak of tools/soak: random tubes through whole squaring runs, one at a time, each sorted into what a user
would meet: finished (clean or with a warning), stopped with one line, crashed, hung, NaN in its history, or
unflagged (its energy balance or its error estimate off what its preset expects, and no warning said so).
tools/soak is the command; tests/check_soak.py runs three short cases through the same functions."""
import glob
import math
import os
import random
import re
import resource
import signal
import subprocess
import time

import h5py
import numpy as np

from . import tfruns, tubes

# The soak's ranges (the extremes a user may bring): R/t, E / sigma_y, the hardening exponent n (Ludwik and Swift),
# mu, the stroke from 1 mm to 0.35 Ro.
RT, ESY, N_EXP, MU, STROKE = (4, 100), (100, 2000), (0.05, 1), (0, 0.6), (1, 0.35)
# Each tube's preset, drawn with these weights: the accurate preset costs about 4 times the default's and 9 times
# the fast one's (docs/accuracy.md, "Presets"), so it gets one case in ten.
PRESET_SHARE = {"fast": 0.45, "default": 0.45, "accurate": 0.10}
# Swift's K (ep0 + ep)^n: ep0 log-uniform in this range (fitted steels and aluminum: dc04 0.0043, aa6061_t6 0.0075)
# and K = sigma_y ep0^-n, unless the flow stress at ep = 0.2 would pass SWIFT_MAX_HARDENING sigma_y (a small ep0 at
# a large n: 200 sigma_y at ep0 1e-3, n 1; no metal hardens so): then ep0 is the one that reaches it there.
SWIFT_EP0 = (1e-3, 5e-2)
SWIFT_MAX_HARDENING = 4.0
# The run's own -time_limit (s of its incremental loop) by preset: 100 times the preset's whole run on the paper's
# tube on a quiet machine (2.6, 6.7, 23.7 s; docs/accuracy.md, "Presets"), rounded up. The slowest draw, the
# thinnest wall pressed furthest, took 18 times the paper's tube on the fast preset on a loaded machine (R/t 100,
# 7 mm: 47 s): 100 leaves it a factor of 5 for the load and the deeper folds. A run that reaches it stops with its
# one line (a stop, not a hang).
TIME_LIMIT = {"fast": 300, "default": 700, "accurate": 2400}
# Seconds mpirun gets to end its ranks after SIGTERM before the job is killed (it sends them SIGTERM, then SIGKILL).
KILL_GRACE = 20
# What a crashed rank leaves in the output (as tests/tfcheck.py's CRASH_MARKS; "error on rank" is a stop here:
# one rank's error said in one line, docs/reliability.md).
CRASH_MARKS = ("Caught signal", "exited on signal", "MPI_ABORT", "core dumped", "Segmentation fault")
STOP_LINE = re.compile(r"tubeform: error( on rank \d+)?: ")


def wall_limit(time_limit):
    """The wall time a run gets before it is killed as a hang: its loop and the error estimate's two companion
    runs (each held to the same -time_limit, on a coarser mesh or with longer steps), and 60 s to start and write."""
    return 3 * time_limit + 60


def swift_k(sy, n, ep0):
    """Swift's K for sigma_y(0) = sy at ep0, ep0 raised where the law would harden past SWIFT_MAX_HARDENING."""
    if (1 + 0.2 / ep0) ** n > SWIFT_MAX_HARDENING:
        ep0 = 0.2 / (SWIFT_MAX_HARDENING ** (1 / n) - 1)
    return sy * ep0 ** -n


def draw(seed, count, presets=None, stroke=STROKE):
    """The soak's tubes s01, s02, ...: per case tubes.draw_tube in the soak's ranges, then the ranks (1 or
    2), the law (Ludwik or Swift), Swift's ep0 and the preset (weights `presets`, default PRESET_SHARE), in that
    order from one generator (a case's draw does not change with the options that act after it)."""
    presets = presets or PRESET_SHARE
    rng = random.Random(seed)
    cases = {}
    for i in range(count):
        c = tubes.draw_tube(rng, RT, MU, stroke, ESY, N_EXP)
        c["np"] = rng.choice((1, 2))
        c["law"] = rng.choice(("ludwik", "swift"))
        ep0 = math.exp(rng.uniform(*(math.log(x) for x in SWIFT_EP0)))
        c["preset"] = rng.choices(list(presets), weights=list(presets.values()))[0]
        if c["law"] == "swift":
            c["K"] = swift_k(c["sy"], c["n"], ep0)
        cases[f"s{i + 1:02d}"] = c
    return cases


def expectation(preset, src=tfruns.root):
    """(-expect_load, -expect_c_over_t) as the preset's file sets them (0 where it sets none)."""
    text = open(os.path.join(src, "options", f"preset-{preset}.opts")).read()
    return tuple(float(m.group(1)) if (m := re.search(rf"^-{o}\s+(\S+)", text, re.M)) else 0.0
                 for o in ("expect_load", "expect_c_over_t"))


def command(c, out, exe, mpirun, time_limit):
    """The run's command: 2 ranks under mpirun, 1 rank as an MPI singleton (no mpirun)."""
    ranks = [mpirun, "-q", "-n", "2"] if c["np"] == 2 else []
    return ranks + [exe] + tubes.options(c, c["preset"], out, time_limit)


def describe(c):
    """The case as a command to repeat it by hand (without -time_limit and -output)."""
    o = tubes.options(c, c["preset"], "x.h5", 0)
    drop = ("-time_limit", "-output")
    o = [x for i, x in enumerate(o) if x not in drop and o[i - 1] not in drop]
    return " ".join((["mpirun", "-n", "2"] if c["np"] == 2 else []) + ["build/tubeform"] + o)


def _allow_cores():
    """(in the child) core files up to the hard limit: a crash leaves its core beside the log."""
    hard = resource.getrlimit(resource.RLIMIT_CORE)[1]
    resource.setrlimit(resource.RLIMIT_CORE, (hard, hard))


def execute(cmd, cwd, limit):
    """Runs cmd in its own process group; returns (exit code, output, timed out). Past `limit` seconds it is sent
    SIGTERM (mpirun passes it to the ranks; a rank stops at its next solve), after KILL_GRACE more its group is
    killed."""
    env = dict(os.environ, **{k: v for k, v in tfruns.env.items() if k.startswith("OMPI_")})
    p = subprocess.Popen(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                         start_new_session=True, preexec_fn=_allow_cores)
    timed_out = False
    try:
        text, _ = p.communicate(timeout=limit)
    except subprocess.TimeoutExpired:
        timed_out = True
        p.send_signal(signal.SIGTERM)
        try:
            text, _ = p.communicate(timeout=KILL_GRACE)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            text, _ = p.communicate()
    try:  # (whatever of the group outlived its leader)
        os.killpg(p.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass
    return p.returncode, text, timed_out


def run_case(name, c, outdir, exe=tfruns.EXE, mpirun="mpirun", src=tfruns.root, time_limit=None):
    """One case's log (results/soak/<seed>/<name>.log), run unless cached with the same command. The log: the
    command, the run's output, and a last line 'soak: exit E wall W limit L timed_out T cores K'. A core file the
    run leaves in `src` (its working directory) is moved beside the log."""
    time_limit = time_limit or TIME_LIMIT[c["preset"]]
    out, log_path = os.path.join(outdir, name + ".h5"), os.path.join(outdir, name + ".log")
    cmd = command(c, out, exe, mpirun, time_limit)
    if os.path.exists(log_path) and open(log_path).readline().rstrip("\n") == " ".join(cmd):
        return open(log_path).read()
    for f in (out, out + ".partial", log_path):
        if os.path.exists(f):
            os.remove(f)

    def core_files():  # (by name and time: a new core file may have the name of an old one)
        return {f: os.path.getmtime(f) for f in glob.glob(os.path.join(src, "core*")) if os.path.isfile(f)}

    before, t0, limit = core_files(), time.time(), wall_limit(time_limit)
    rc, text, timed_out = execute(cmd, src, limit)
    wall = time.time() - t0
    cores = [f for f, t in core_files().items() if before.get(f) != t]
    for i, f in enumerate(cores):
        os.replace(f, os.path.join(outdir, f"{name}.core{i}"))
    log = (" ".join(cmd) + "\n" + text + f"\nsoak: exit {rc} wall {wall:.1f} limit {limit} timed_out "
           f"{int(timed_out)} cores {len(cores)}\n")
    with open(log_path, "w") as f:
        f.write(log)
    return log


def history_nonfinite(path):
    """The /history columns (and numeric attributes) of a result file holding NaN, or Inf outside r_corner_x,
    r_corner_y (an Inf there is a flat side's corner radius: docs/reliability.md); None without a readable file."""
    try:
        with h5py.File(path, "r") as h:
            g = h["/history"]
            bad = [c for c in g if not (np.isfinite(g[c][:]) | (c.startswith("r_corner") & np.isinf(g[c][:]))).all()]
            bad += [f"@{a}" for a, v in g.attrs.items() if isinstance(v, (float, np.floating)) and math.isnan(v)]
            estimate = {a: float(g.attrs[a]) for a in ("error_load", "error_c_over_t") if a in g.attrs}
    except (OSError, KeyError):
        return None, {}
    return bad, estimate


def off_target(v, estimate, expect, log):
    """The checks of a finished run that are off its preset's expectation (load, C/t: `expect`): its energy
    balance (self-check (a), the printed line: the press's work from the reported load against where it went, so a
    balance off by x says the load's work is off by about x) above the load's expectation; its estimate (the printed
    line and the file's error_load, error_c_over_t: the larger) above either; no estimate where no line says why."""
    load_x, ct_x = expect
    off = []
    if not v["energy"]:
        off.append("no self-check line")
    elif not float(v["energy"]) / 100 <= load_x:
        off.append(f"energy balance {v['energy']} % > {100 * load_x:g} %")
    if not v["est_load"] and "tubeform: no error estimate" not in log:
        return off + ["no error estimate, and no line says why"]
    e_load = max(float(v["est_load"] or 0) / 100, estimate.get("error_load", 0))
    e_ct = max(float(v["est_ct"] or 0), estimate.get("error_c_over_t", 0))
    if not e_load <= load_x:
        off.append(f"estimate: load {100 * e_load:.2g} % > {100 * load_x:g} %")
    if not e_ct <= ct_x:
        off.append(f"estimate: C/t {e_ct:.2g} > {ct_x:g}")
    return off


def crash_why(rc, cores, marks):
    """Why a run counts as crashed: a signal (Python's negative exit code; mpirun's 128 + N), core files, a mark."""
    if rc is not None and rc < 0:
        return f"killed by signal {-rc}"
    if rc is not None and rc >= 128:
        return f"exit {rc}: signal {rc - 128}"
    return f"{cores} core file(s)" if cores else f"'{marks[0]}' in its output"


def classify(log, h5, expect):
    """What a run's log (run_case's) and result file say: the numbers of tubes.parse and kind ('finished',
    'stop', 'crash' or 'hang') with why, the stop lines, the warnings, the /history columns not finite ('nonfinite'),
    the checks off the expectation ('off') and of those the ones no warning flagged ('unflagged')."""
    v = tubes.parse(log)
    tail = re.search(r"^soak: exit (\S+) wall (\S+) limit (\S+) timed_out (\d) cores (\d+)$", log, re.M)
    rc = None if tail[1] == "None" else int(tail[1])
    lines = log.replace(tfruns.root + os.sep, "").splitlines()[1:]  # (paths as from the source tree)
    stops = [line for line in lines if STOP_LINE.match(line)]
    v.update(rc=rc, wall=float(tail[2]), stops=stops, warnings=[l for l in lines if l.startswith("tubeform: warning:")],
             kind="finished", why="", off=[], unflagged=[])
    marks = [m for m in CRASH_MARKS if m in log]
    bad, estimate = history_nonfinite(h5 if os.path.exists(h5) else h5 + ".partial")
    v["nonfinite"] = bad or []
    if tail[4] == "1":
        v.update(kind="hang", why=f"no exit within {tail[3]} s: killed")
    elif rc is None or rc < 0 or rc >= 128 or tail[5] != "0" or marks:
        v.update(kind="crash", why=crash_why(rc, int(tail[5]), marks))
    elif rc != 0 and len(stops) == 1:
        v.update(kind="stop", why=stops[0])
    elif rc != 0:
        v.update(kind="crash", why=f"exit {rc} with {len(stops)} error lines (one expected)")
    elif stops or not v["increments"] or bad is None:
        v.update(kind="crash", why="exit 0 with an error line" if stops else "exit 0 without its 'done' line"
                 if not v["increments"] else "exit 0 without a readable result file")
    if v["kind"] == "finished":
        v["off"] = off_target(v, estimate, expect, log)
        v["unflagged"] = [] if v["warnings"] else v["off"]
    return v


def verdict(v):
    """A row's last cell: what the soak counts the run as."""
    if v["kind"] in ("crash", "hang"):
        text = f"**{v['kind'].upper()}**: {v['why']}"
    elif v["kind"] == "stop":
        text = "stop: " + v["why"]
    elif v["unflagged"]:
        text = "**UNFLAGGED**: " + "; ".join(v["unflagged"])
    else:
        text = "finished" + (f", warned ({'; '.join(v['off'])})" if v["warnings"] and v["off"] else
                             ", warned" if v["warnings"] else "")
    if v["nonfinite"]:
        text += f"; **NaN/Inf in /history**: {', '.join(v['nonfinite'])}"
    return text.replace("|", "/")


HEAD = ("| case | preset | ranks | law | R/t | E/sy | n | mu | stroke mm | exit | wall s | increments | load N/mm | "
        "C/t loaded, after springback | estimate: load %, C/t | preset expects | energy % | internal work % | "
        "verdict |")


def row(name, c, v, expect):
    """The case's table row."""
    cells = [name, c["preset"], c["np"], c["law"], f"{c['ro'] / c['t']:.1f}", f"{c['E'] / c['sy']:.0f}",
             f"{c['n']:.2f}", f"{c['mu']:.2f}", f"{c['stroke']:.2f}", v["rc"], f"{v['wall']:.0f}", v["increments"],
             v["load"], f"{v['ct']}, {v['ct_back']}" if v["ct"] else "", f"{v['est_load']}, {v['est_ct']}"
             if v["est_load"] else "", f"{100 * expect[0]:g}, {expect[1]:g}", v["energy"], v["internal"], verdict(v)]
    return "| " + " | ".join(str(x) for x in cells) + " |"


def summary(results):
    """The summary line of [(name, case, classify's dict)]: the runs by preset and ranks, then by what they gave."""
    def count(f):
        return sum(1 for _, c, v in results if f(c, v))
    def n(k, one, many):
        x = count(lambda c, v: v["kind"] == k)
        return f"{x} {one if x == 1 else many}"
    presets = ", ".join(f"{count(lambda c, v, p=p: c['preset'] == p)} {p}" for p in PRESET_SHARE)
    return (f"{len(results)} runs ({presets}; {count(lambda c, v: c['np'] == 2)} on 2 ranks): "
            f"{n('crash', 'crash', 'crashes')}, {n('hang', 'hang', 'hangs')}, {count(lambda c, v: v['nonfinite'])} "
            f"with NaN in /history, {n('stop', 'stop', 'stops')}, {count(lambda c, v: v['unflagged'])} unflagged; "
            f"{count(lambda c, v: v['kind'] == 'finished')} finished, "
            f"{count(lambda c, v: v['kind'] == 'finished' and v['warnings'])} of them with a warning")


def failed(v):
    """Whether the soak fails on this run: a crash, a hang, NaN in its history, or unflagged."""
    return v["kind"] in ("crash", "hang") or bool(v["nonfinite"]) or bool(v["unflagged"])


def report(results):
    """The lines under the table: the summary, each stop with its line, each failure with its verdict, and the
    command of each."""
    lines = ["", "Summary: " + summary(results)]
    stops = [(n, c, v["why"]) for n, c, v in results if v["kind"] == "stop"]
    fails = [(n, c, verdict(v)) for n, c, v in results if failed(v)]
    for title, items in (("Stops", stops), ("Crashes, hangs, NaN, unflagged", fails)):
        if items:
            lines += ["", f"{title}:"] + [f"- {n}: {why} (`{describe(c)}`)" for n, c, why in items]
    return lines
