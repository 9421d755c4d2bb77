#!/usr/bin/python3
"""Punch speed study for -dynamics implicit: one squaring case pressed at
several punch speeds (and quasi-statically), loading only. Prints, per run,
the punch load at U = 1, 2, 3 and 4.2 mm, C/t and C1/C2 = x_max / y_max at
the end, the smallest of the paper's deviation ratio min(C1, C2)/max(C1, C2)
and where, the largest kinetic energy and the inertia work (kinetic
energy + what backward Euler damped) relative to the external work, the
largest energy balance error, increments, solves and wall time. A result
that does not move as the speed goes down is the quasi-static one.

    /usr/bin/python3 studies/study_speed.py [OPTIONS_FILE] [SPEED ...]

Defaults: options/squaring_al_37_mu0.35.opts at 10, 1 and 0.1 mm/s, plus the
quasi-static run (which may stall: docs/theory.md, "Stalls"). Runs two at a
time; results in results/speed_<speed>.h5.
"""
import os
import re
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

import h5py
import numpy as np

# The helper package python/tubeform_py (python/README.md).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from tubeform_py.tfruns import deviation  # noqa: E402
from tubeform_py.tfruns import runs_env  # noqa: E402

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
env = runs_env(os.environ)  # (scripts/runs.env: the environment of tubeform's runs)
args = sys.argv[1:]
opts = args.pop(0) if args and not args[0].replace(".", "", 1).isdigit() else "options/squaring_al_37_mu0.35.opts"
speeds = [float(a) for a in args] or [10.0, 1.0, 0.1]
os.makedirs(os.path.join(root, "results"), exist_ok=True)


def run(speed):
    """speed in mm/s; 0 = quasi-static."""
    name = f"{speed:g}" if speed else "quasistatic"
    out = os.path.join(root, "results", f"speed_{name}.h5")
    cmd = [f"{root}/build/tubeform", "-options_file", opts, "-unload", "none", "-output", out, "-output_every", "100000", "-rmin_stall_increments", "300"]
    if speed:
        cmd += ["-dynamics", "implicit", "-punch_speed", repr(speed)]
    else:
        cmd += ["-dynamics", "quasistatic"]
    t0 = time.time()
    p = subprocess.run(cmd, cwd=root, env=env, capture_output=True, text=True)
    wall = time.time() - t0
    m = re.search(r"(\d+) factorizations", p.stdout)
    status = "done" if p.returncode == 0 else "stalled" if "stalled" in p.stderr else "failed"
    return name, out, status, int(m.group(1)) if m else -1, wall


def row(name, out, status, solves, wall):
    if status == "failed" or not os.path.exists(out):
        return f"| {name} | {status} |"
    with h5py.File(out, "r") as h:
        H = {c: h["/history"][c][:] for c in h["/history"]}
    U, P, D = H["stroke"], H["load"], deviation(H["x_max"], H["y_max"])  # the paper's min/max
    at = " | ".join(f"{np.interp(u, U, P):.2f}" if u <= U[-1] + 1e-9 else "-" for u in (1, 2, 3, 4.2))
    w = H["w_ext"][-1]
    c1_c2 = H["x_max"][-1] / H["y_max"][-1]
    end = f"{H['c_over_t'][-1]:.3f} | {c1_c2:.4f}" if status == "done" else f"stalled at U = {U[-1]:.3f} |"
    i = np.argmin(D)
    return (f"| {name} | {at} | {end} | {D[i]:.3f} at {U[i]:.2f} | {H['w_kinetic'].max() / w:.1e} | {H['w_inertia'][-1] / w:.1e}"
            f" | {np.abs(H['energy_error'][10:]).max():.1e} | {len(U) - 1} | {solves if solves >= 0 else '-'} | {wall:.0f} |")


with ThreadPoolExecutor(max_workers=2) as pool:
    rows = [row(*r) for r in pool.map(run, speeds + [0.0])]
print(f"{opts}, loading only (-unload none)")
print("| punch speed (mm/s) | P(U=1) | P(2) | P(3) | P(4.2) N/mm | C/t at end | C1/C2 at end "
      "| smallest min(C1,C2)/max(C1,C2) at U (mm) "
      "| max kinetic / w_ext | inertia work / w_ext | max energy error | increments | solves | wall (s) |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
print("\n".join(rows))
