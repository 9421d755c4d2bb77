#!/usr/bin/python3
"""What -kinematics, -equilibrium_tol and the increment count buy, on the
plastic thick cylinder (options/pressure_plastic.opts) and the column
(options/column.opts).

    /usr/bin/python3 studies/study_switches.py

Prints, per run: final out-of-balance force (N/mm), largest energy balance
error over the increments, and the result (cylinder: maximum pressure vs
Hill's limit on the current radii; column: final load vs the Euler load).
"""
import math
import os
import subprocess
import sys

# The helper package python/tubeform_py (python/README.md).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from tubeform_py.analysis import hill_errors, read  # noqa: E402
from tubeform_py.tfruns import runs_env  # noqa: E402

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
env = runs_env(os.environ)  # (scripts/runs.env: the environment of tubeform's runs)


def run(opts, extra):
    out = "/tmp/tubeform_switches.h5"
    subprocess.run([f"{root}/build/tubeform", "-options_file", opts, "-output", out] + extra, cwd=root, env=env, check=True, capture_output=True)
    return out


print(f"{'run':<62} {'residual':>9} {'energy':>8}  result")
for extra in ([], ["-equilibrium_tol", "0.005"], ["-kinematics", "midpoint"], ["-kinematics", "midpoint", "-equilibrium_tol", "0.005"]):
    f = run("options/pressure_plastic.opts", extra)
    e, H = hill_errors(f), read(f)["history"]
    print(f"{'cylinder ' + ' '.join(extra):<62} {H['residual'][-1]:>9.2e} {e['energy']:>8.1e}  p_max {e['p_max']:.2f} vs Hill {e['p_limit']:.2f} ({e['limit']:+.2%})")
pcr = math.pi**2 * 75000 / (1 - 0.34**2) / 12 / 25**2
for extra in (["-increments", "100"], ["-increments", "400"], ["-increments", "800"], ["-increments", "100", "-equilibrium_tol", "0.005"], ["-increments", "100", "-kinematics", "midpoint"]):
    H = read(run("options/column.opts", extra))["history"]
    print(f"{'column ' + ' '.join(extra):<62} {H['residual'][-1]:>9.2e} {abs(H['energy_error'][1:]).max():>8.1e}  load {H['load'][-1]:.2f} vs Euler {pcr:.2f} ({H['load'][-1] / pcr - 1:+.2%})")
