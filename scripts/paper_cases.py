#!/usr/bin/python3
"""The paper's squaring cases (options/squaring_*_mu*.opts): three tubes,
three friction coefficients. Prints, per case, the punch load at U = 1, 2, 3
and 4.2 mm, C/t and C1/C2 at 4.2 mm and after springback, increments,
solves (factorizations, friction and loading/unloading iterations included),
unsettled trial steps (taken after the step halvings ran out) and wall time; writes the table to results/paper_cases.md.

    /usr/bin/python3 scripts/paper_cases.py [JOBS]     (JOBS runs at a time, default 2)
"""
import glob
import os
import re
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from analysis import read  # noqa: E402

import numpy as np  # noqa: E402

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
jobs = int(sys.argv[1]) if len(sys.argv) > 1 else 2
timeout = 1800  # seconds per case
cases = sorted(glob.glob(os.path.join(root, "options", "squaring_*_mu*.opts")))
os.makedirs(os.path.join(root, "results"), exist_ok=True)


def run(path):
    name = os.path.basename(path)[len("squaring_"):-len(".opts")]
    out = os.path.join(root, "results", f"squaring_{name}.h5")
    t0 = time.time()
    try:
        p = subprocess.run([f"{root}/build/tubeform", "-options_file", os.path.relpath(path, root), "-output", out, "-output_every", "50"],
                           cwd=root, env=env, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return name, None, time.time() - t0, f"not finished within {timeout} s"
    wall = time.time() - t0
    if p.returncode != 0:
        # A stalled run (-rmin_stall_increments) still writes its results up to the stall.
        if "stalled" in p.stderr and os.path.exists(out):
            return name, read(out)["history"], wall, "stalled"
        return name, None, wall, p.stderr.strip().splitlines()[-1] if p.stderr.strip() else "failed"
    m = re.search(r"done, \d+ increments, (\d+) factorizations", p.stdout)
    solves = int(m.group(1)) if m else -1
    return name, read(out)["history"], wall, solves


rows = []
with ThreadPoolExecutor(max_workers=jobs) as pool:
    for name, H, wall, info in pool.map(run, cases):
        if H is None:
            rows.append(f"| {name} | failed: {info} |")
            continue
        load = H["stage"] == 0
        U, P = H["stroke"][load], H["load"][load]
        at = [f"{np.interp(u, U, P):.1f}" if u <= U[-1] + 1e-9 else "-" for u in (1, 2, 3, 4.2)]
        last = np.nonzero(load)[0][-1]
        if info == "stalled":
            # Loading stopped short: no 4.2 mm state, no springback.
            shape = f"stalled at U = {U[-1]:.3f} | | | "
            info = "-"
        else:
            shape = f"{H['c_over_t'][last]:.3f} | {H['deviation_ratio'][last]:.4f} | {H['c_over_t'][-1]:.3f} | {H['deviation_ratio'][-1]:.4f}"
        rows.append(f"| {name} | " + " | ".join(at) + f" | {shape}"
                    f" | {np.abs(H['energy_error'][1:][load[1:]]).max():.1e} | {H['penetration'].max():.1e}"
                    f" | {len(H['stroke']) - 1} | {info} | {int(H['unsettled'][-1])} | {wall:.0f} |")
        print(rows[-1], flush=True)
head = ("| case | P(U=1) | P(2) | P(3) | P(4.2) N/mm | C/t at 4.2 | C1/C2 at 4.2 | C/t after springback | C1/C2 after | max energy error | max penetration (mm) | increments | solves | unsettled | wall (s) |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
table = head + "\n" + "\n".join(rows)
open(os.path.join(root, "results", "paper_cases.md"), "w").write(table + "\n")
print(table)
