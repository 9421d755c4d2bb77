"""Thick cylinder, elastic-perfectly plastic J2, plane strain (Hill 1950).

a = 10, b = 20, sy = 165.3, nu = 0.499 (von Mises with incompressibility:
Hill's solution is exact), k = sy / sqrt(3), inner radius driven outwards
(options/pressure_plastic.opts, 80 x 8 B-bar mesh). References:
  first yield   p_y = k (1 - a^2/b^2)
  plastic zone  p(c) = k (1 - c^2/b^2 + 2 ln(c/a))
  limit         p_L = 2 k ln(b/a), with the current radii at the maximum
                (the cylinder has grown; the small-strain value is reported).
The paper's forward increments (-equilibrium_tol 0), where r1 ends an
increment on the first yield, and the default equilibrium increments (no r1:
points yield inside a step), each checked. Checks (1 %, the required
tolerance): the pressure of the increment that r1 ended on the first yield
(paper's increments only); p(c) for the plastic radius c measured from the
plastic Gauss-point area, c in [0.55 b, 0.85 b] (where dp/dc is not small);
the limit pressure. Energy balance |w_ext - w_int| < 0.5 % of w_ext at every
increment, and w_int = w_plastic + w_elastic within 2e-4 (measured 1.6e-6 on
every kernel: 100 times that). The same run on 2 ranks: each history column
within 100 times the largest 1 vs 2 rank difference measured on OpenBLAS
Haswell, SkylakeX and Prescott (RANKS below; round-off of the summation
order; a partition-boundary error would be O(1)); n_plastic, a count, equal.
"""
import os
import sys

import h5py
import numpy as np

from tfcheck import Checks, args, out, run, run_all

sys.path.insert(0, os.path.join(sys.argv[3], "python"))  # the helper package (python/README.md)
from tubeform_py.analysis import hill_errors  # noqa: E402

tf, mpirun, src = args()
k_ = Checks("hill")
# 1 vs 2 ranks, per column: 100 x the largest of the values measured (Haswell, SkylakeX, Prescott):
# load 1.1e-11, 1.2e-11, 5.5e-12; stroke 3.5e-12, 6.8e-12, 6.3e-12; w_ext 4.0e-12, 7.1e-12, 7.1e-12;
# rmin 2.2e-10, 4.4e-10, 6.7e-10 (a ratio of small step quantities); n_plastic 0 (a count).
RANKS = {"load": 1.2e-9, "stroke": 7e-10, "w_ext": 7e-10, "n_plastic": 0.0, "rmin": 7e-8}
hist = {}
base = ["-options_file", f"{src}/options/pressure_plastic.opts", "-mesh_nt", 80, "-output_every", 1]
# (the two single-rank runs side by side, then the 2-rank one)
run_all(tf, mpirun, [base + ["-equilibrium_tol", 0, "-output", out("hill_np1.h5")],
                     base + ["-output", out("hill_equilibrium.h5")]])
run(tf, mpirun, 2, base + ["-equilibrium_tol", 0, "-output", out("hill_np2.h5")])
for n in (1, 2):
    with h5py.File(out(f"hill_np{n}.h5"), "r") as h:
        hist[n] = {c: h["/history"][c][:] for c in h["/history"]}
for name, path in (("paper's increments", "hill_np1.h5"), ("equilibrium", "hill_equilibrium.h5")):
    e = hill_errors(out(path))
    if name != "equilibrium":
        k_.check(abs(e["first_yield"]) < 0.01, f"{name}: first yield at p = {e['p_first']:.3f}, Hill {e['p_y']:.3f} ({e['first_yield']:+.2%})")
    k_.check(e["radius_points"] >= 10 and e["radius"] < 0.01, f"{name}: pressure vs plastic radius over {e['radius_points']} increments: worst {e['radius']:.2%} off Hill")
    k_.check(abs(e["limit"]) < 0.01, f"{name}: limit pressure {e['p_max']:.3f}, Hill with current radii {e['p_limit']:.3f} ({e['limit']:+.2%}); small-strain {e['p_limit_small_strain']:.3f}")
    k_.check(e["energy"] < 5e-3, f"{name}: energy balance: max |w_ext - w_int| / w_ext = {e['energy']:.2e}")
H = hist[1]
wp = H["w_plastic"][-1] + H["w_elastic"][-1]
k_.check(abs(wp / H["w_int"][-1] - 1) < 2e-4, f"w_int = w_plastic + w_elastic within 2e-4 ({wp / H['w_int'][-1] - 1:+.2e})")

for col, tol in RANKS.items():
    x1, x2 = hist[1][col], hist[2][col]
    rel = np.abs(x1 - x2).max() / max(np.abs(x1).max(), 1e-300) if len(x1) == len(x2) else 1.0
    k_.check(rel <= tol, f"1 vs 2 ranks, history {col}: {rel:.1e} relative ({tol:g})")
k_.done()
