#!/usr/bin/python3
"""The paper's squaring cases (options/squaring_*_mu*.opts): three tubes,
three friction coefficients. Prints, per case, the punch load at U = 1, 2, 3
and 4.2 mm, C/t and the paper's deviation ratio min(C1, C2)/max(C1, C2) at
4.2 mm and after springback, the smallest deviation ratio over the loading
and where, the largest energy balance error and penetration,
increments, solves (factorizations, friction and loading/unloading
iterations included), unsettled trial steps (taken after the step halvings
ran out) and wall time; writes the table to results/paper_cases.md. The
deviation ratio is the smaller of x_max (C1, across the press) and y_max
(C2, along it) over the larger, as the paper's stays at most 1; the
history's deviation_ratio is C1/C2 itself (docs/theory.md, "Metrics").
springback is the paper's, elastic (`-- -springback material` for the
material's own law).

    /usr/bin/python3 scripts/paper_cases.py [JOBS]    run the cases (JOBS at a time, default 2)
    /usr/bin/python3 scripts/paper_cases.py --table   tabulate the last runs again (no runs)
    ... --tag NAME -- OPTIONS                          a variant: OPTIONS added to every run,
                                                      results named squaring_<case>_NAME.h5
                                                      and paper_cases_NAME.md

Each run leaves results/squaring_<case>[_NAME].h5 and a small .json beside it
(status, solves, wall time) that --table reads.
"""
import glob
import json
import os
import re
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

# The helper package python/tubeform_py (python/README.md).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from tubeform_py.analysis import read  # noqa: E402
from tubeform_py.tfruns import runs_env  # noqa: E402
from tubeform_py.tfruns import deviation  # noqa: E402

import numpy as np  # noqa: E402

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
env = runs_env(os.environ)  # (scripts/runs.env: the environment of tubeform's runs)
timeout = 3600  # seconds per case (a stalled run spends up to ~30 min before the stall watch ends it)
cases = sorted(glob.glob(os.path.join(root, "options", "squaring_*_mu*.opts")))
results = os.path.join(root, "results")
os.makedirs(results, exist_ok=True)
args = sys.argv[1:]
extra = args[args.index("--") + 1:] if "--" in args else []
args = args[:args.index("--")] if "--" in args else args
tag = ""
if "--tag" in args:
    i = args.index("--tag")
    tag = "_" + args[i + 1]
    del args[i:i + 2]
tabulate_only = "--table" in args
args = [a for a in args if a != "--table"]


def case_name(path):
    return os.path.basename(path)[len("squaring_"):-len(".opts")]


def run(path):
    """Runs one case; records status, solves and wall time beside its result."""
    name = case_name(path)
    out = os.path.join(results, f"squaring_{name}{tag}.h5")
    t0 = time.time()
    try:
        p = subprocess.run([f"{root}/build/tubeform", "-options_file", os.path.relpath(path, root), "-output", out, "-output_every", "50",
                            "-springback", "elastic"] + extra,
                           cwd=root, env=env, capture_output=True, text=True, timeout=timeout)
        m = re.search(r"done, \d+ increments, (\d+) factorizations", p.stdout)
        if p.returncode == 0:
            info = {"status": "done", "solves": int(m.group(1)) if m else -1}
        elif "stalled" in p.stderr and os.path.exists(out):
            # A stalled run (-rmin_stall_increments) still writes its results up to the stall.
            info = {"status": "stalled", "solves": -1}
        else:
            info = {"status": "failed: " + (p.stderr.strip().splitlines()[-1] if p.stderr.strip() else "no message"), "solves": -1}
    except subprocess.TimeoutExpired:
        info = {"status": f"failed: not finished within {timeout} s", "solves": -1}
    info["wall"] = time.time() - t0
    json.dump(info, open(out[:-3] + ".json", "w"))
    return name


def row(name):
    """One table row from a case's result file and its .json."""
    out = os.path.join(results, f"squaring_{name}{tag}.h5")
    try:
        info = json.load(open(out[:-3] + ".json"))
    except OSError:
        return f"| {name} | not run |"
    if info["status"].startswith("failed") or not os.path.exists(out):
        return f"| {name} | {info['status']} |"
    H = read(out)["history"]
    load = H["stage"] == 0
    dev = deviation(H["x_max"], H["y_max"])  # the paper's min(C1, C2)/max(C1, C2)
    U, P, D = H["stroke"][load], H["load"][load], dev[load]
    at = [f"{np.interp(u, U, P):.1f}" if u <= U[-1] + 1e-9 else "-" for u in (1, 2, 3, 4.2)]
    last = np.nonzero(load)[0][-1]
    if info["status"] == "stalled":
        # Loading stopped short: no 4.2 mm state, no springback.
        shape = f"stalled at U = {U[-1]:.3f} | | |"
    else:
        shape = f"{H['c_over_t'][last]:.3f} | {D[-1]:.4f} | {H['c_over_t'][-1]:.3f} | {dev[-1]:.4f}"
    i = np.argmin(D)
    solves = info["solves"] if info["solves"] >= 0 else "-"
    return (f"| {name} | " + " | ".join(at) + f" | {shape} | {D[i]:.3f} at {U[i]:.2f}"
            f" | {np.abs(H['energy_error'][1:][load[1:]]).max():.1e} | {H['penetration'].max():.1e}"
            f" | {len(H['stroke']) - 1} | {solves} | {int(H['unsettled'][-1])} | {info['wall']:.0f} |")


if not tabulate_only:
    jobs = int(args[0]) if args else 2
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        for name in pool.map(run, cases):
            print(row(name), flush=True)
head = ("| case | P(U=1) | P(2) | P(3) | P(4.2) N/mm | C/t at 4.2 | min(C1,C2)/max(C1,C2) at 4.2 "
        "| C/t after springback | min(C1,C2)/max(C1,C2) after | its smallest at U (mm) "
        "| max energy error | max penetration (mm) | increments | solves | unsettled | wall (s) |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
table = head + "\n" + "\n".join(row(case_name(c)) for c in cases)
open(os.path.join(results, f"paper_cases{tag}.md"), "w").write(table + "\n")
print(table)
