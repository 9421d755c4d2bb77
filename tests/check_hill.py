"""Thick cylinder, elastic-perfectly plastic J2, plane strain (Hill 1950).

a = 10, b = 20, sy = 165.3, nu = 0.499 (von Mises with incompressibility:
Hill's solution is exact), k = sy / sqrt(3), inner radius driven outwards
(options/pressure_plastic.opts, 80 x 8 B-bar mesh). References:
  first yield   p_y = k (1 - a^2/b^2)
  plastic zone  p(c) = k (1 - c^2/b^2 + 2 ln(c/a))
  limit         p_L = 2 k ln(b/a), with the current radii at the maximum
                (the cylinder has grown; the small-strain value is reported).
Checks (1 %, the issue's tolerance): the pressure of the increment that r1
ended on the first yield; p(c) for the plastic radius c measured from the
plastic Gauss-point area, c in [0.55 b, 0.85 b] (where dp/dc is not small);
the limit pressure. Energy balance |w_ext - w_int| < 0.5 % of w_ext at every
increment. The same run on 2 ranks: history within 1e-8 relative (MUMPS
round-off is ~1e-12 here; a partition-boundary error would be O(1)).
"""
import math

import h5py
import numpy as np

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
k_ = Checks("hill")
sy, a, b = 165.3, 10.0, 20.0
k = sy / math.sqrt(3)
hist = {}
for n in (1, 2):
    run(tf, mpirun, n, ["-options_file", f"{src}/options/pressure_plastic.opts", "-mesh_nt", 80, "-output_every", 1,
                        "-output", out(f"hill_np{n}.h5")])
    with h5py.File(out(f"hill_np{n}.h5"), "r") as h:
        hist[n] = {c: h["/history"][c][:] for c in h["/history"]}
        if n == 1:
            X, C = h["/geometry/vertices"][:], h["/viz/topology/cells"][:]
            frac = h["/cell_fields/plastic_c"][:]
H = hist[1]
p = H["load"]

first = int(np.argmax(H["limiter"] == 2))
py = k * (1 - a * a / (b * b))
k_.check(abs(p[first] / py - 1) < 0.01, f"first yield at p = {p[first]:.3f}, Hill {py:.3f} ({p[first] / py - 1:+.2%})")

P = X[C]
area = 0.5 * sum(P[:, q, 0] * P[:, (q + 1) % 4, 1] - P[:, (q + 1) % 4, 0] * P[:, q, 1] for q in range(4))
worst, count = 0.0, 0
for j in range(len(p)):
    ap = float((frac[j] * area).sum())
    c = math.sqrt(a * a + 4 * ap / math.pi)
    if 0.55 * b <= c <= 0.85 * b:
        # Hill's formula on the current radii: the wall has grown by the inner
        # displacement (incompressible, so r^2 - R^2 is the same for all r).
        ac, bc = a + H["stroke"][j], H["x_max"][j]
        cc = math.sqrt(c * c + ac * ac - a * a)
        pc = k * (1 - cc * cc / (bc * bc) + 2 * math.log(cc / ac))
        worst = max(worst, abs(p[j] / pc - 1))
        count += 1
k_.check(count >= 10 and worst < 0.01, f"pressure vs plastic radius over {count} increments: worst {worst:.2%} off Hill")

im = int(np.argmax(p))
acur, bcur = a + H["stroke"][im], H["x_max"][im]
pl = 2 * k * math.log(bcur / acur)
k_.check(abs(p[im] / pl - 1) < 0.01, f"limit pressure {p[im]:.3f}, Hill with current radii {pl:.3f} ({p[im] / pl - 1:+.2%}); small-strain {2 * k * math.log(b / a):.3f}")

e = np.abs(H["w_ext"][1:] - H["w_int"][1:]) / np.abs(H["w_ext"][1:])
k_.check(e.max() < 5e-3, f"energy balance: max |w_ext - w_int| / w_ext = {e.max():.2e}")
wp = H["w_plastic"][-1] + H["w_elastic"][-1]
k_.check(abs(wp / H["w_int"][-1] - 1) < 5e-3, f"w_int = w_plastic + w_elastic within 0.5% ({wp / H['w_int'][-1] - 1:+.2e})")

for col in ("load", "stroke", "w_ext", "n_plastic", "rmin"):
    x1, x2 = hist[1][col], hist[2][col]
    rel = np.abs(x1 - x2).max() / max(np.abs(x1).max(), 1e-300) if len(x1) == len(x2) else 1.0
    k_.check(rel < 1e-8, f"1 vs 2 ranks, history {col}: {rel:.1e} relative")
k_.done()
