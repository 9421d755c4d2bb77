#!/usr/bin/python3
"""How -rmin_deps trades increments and time for accuracy, on the plastic
thick cylinder (options/pressure_plastic.opts, 80 x 8 mesh) against Hill.

    /usr/bin/python3 studies/study_rmin.py

Five trial increments only, and the paper's increments (-equilibrium_tol 0:
with equilibrium iterations points yield inside a step, and r1 ends none), so
that r2 (the strain limit) and r1 (yield onset) decide the increment sizes. Errors are relative to Hill's solution
(python/tubeform_py/analysis.py: first yield, pressure vs plastic radius, limit).
"""
import os
import subprocess
import sys
import time

# The helper package python/tubeform_py (python/README.md).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from tubeform_py.analysis import hill_errors  # noqa: E402
from tubeform_py.tfruns import runs_env  # noqa: E402

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
env = runs_env(os.environ)  # (scripts/runs.env: the environment of tubeform's runs)
print(f"{'rmin_deps':>10} {'group_tol':>9} {'increments':>10} {'wall (s)':>9} {'first yield':>12} {'p vs c':>8} {'limit':>8} {'energy':>9}")
for deps, group in ((4e-3, 1e-6), (1e-3, 1e-6), (2.5e-4, 1e-6), (1e-3, 0.01), (1e-3, 0.1), (1e-3, 0.5)):
    out = f"/tmp/tubeform_study_{deps}_{group}.h5"
    cmd = [f"{root}/build/tubeform", "-options_file", "options/pressure_plastic.opts", "-mesh_nt", "80", "-increments", "5",
           "-rmin_deps", str(deps), "-rmin_group_tol", str(group), "-equilibrium_tol", "0", "-output_every", "1",
           "-output", out]
    t0 = time.time()
    subprocess.run(cmd, cwd=root, env=env, check=True, capture_output=True)
    wall = time.time() - t0
    e = hill_errors(out)
    print(f"{deps:>10g} {group:>9g} {e['increments']:>10d} {wall:>9.2f} {e['first_yield']:>+12.2%} {e['radius']:>8.2%} {e['limit']:>+8.2%} {e['energy']:>9.1e}")
