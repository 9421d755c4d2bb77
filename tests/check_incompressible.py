"""Nearly incompressible walls converge like compressible ones (docs/theory.md, 5a; docs/reliability.md).

The default case on the default preset (qm6, 4 cells through the wall, midpoint kinematics with equilibrium
iterations) pressed to U = 2 mm without springback, at nu 0.47, 0.48, 0.49 and 0.499, 1 rank, no error estimate:
A. Factorizations an increment at nu 0.499 (the run's last line: its increments and factorizations): at most 6, and
   at most 1.25 times nu 0.49's (the iterations' count moves by a few % with the increments a run takes: 3.07 to
   3.19 an increment from nu 0.47 to 0.499 here). Measured 3.19 against 3.12. With the start's tangent in the
   corrections (the midpoint strain's linearization at the iterate left out) nu 0.499 takes 10.5 against 3.5.
B. The load at U = 0.5, 1, 1.5, 2 mm at nu 0.499 against its extrapolation from nu 0.47, 0.48, 0.49, quadratic in
   nu (an element that does not lock has a load smooth in nu through 0.5): within the extrapolation's own
   estimate, |its quadratic term|, plus what the equilibrium criterion leaves open, the out-of-balance force
   allowed at a node (-equilibrium_tol 0.005 of the mean nodal force q_avg), in the load's units (the punch load
   is twice the quarter model's die force): 2 x 0.005 q_avg (0.10 to 0.14 N/mm, 1e-3 of the load). Measured: off
   by 3.9e-3 N/mm at most (3.7e-5 of the load). A locking element (-element q4) misses it by 15 to 23 % of the
   load from U = 1 mm on.
"""
import re

import h5py
import numpy as np

from tfcheck import Checks, args, out, run_all

tf, mpirun, src = args()
k = Checks("incompressible")
NUS = ("0.47", "0.48", "0.49", "0.499")
STROKES = (0.5, 1.0, 1.5, 2.0)
BASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-default.opts",
        "-error_estimate", "0", "-stroke", "2", "-unload", "none"]
EQUILIBRIUM_TOL = 0.005  # the default -equilibrium_tol
LOAD_PER_DIE_FORCE = 2  # the punch load is twice the quarter model's die force

procs = dict(zip(NUS, run_all(tf, mpirun, [BASE + ["-material_nu", nu, "-output", out(f"nu{nu}.h5")] for nu in NUS])))


def per_increment(nu):
    m = re.search(r"done, (\d+) increments, (\d+) factorizations", procs[nu].stdout)
    return int(m.group(2)) / int(m.group(1))


def at_strokes(nu, column):
    with h5py.File(out(f"nu{nu}.h5"), "r") as h:
        return np.interp(STROKES, h["/history/stroke"][:], h[f"/history/{column}"][:])


f49, f499 = per_increment("0.49"), per_increment("0.499")
print(f"factorizations an increment: " + ", ".join(f"nu {nu} {per_increment(nu):.2f}" for nu in NUS))
k.check(f499 <= 6, f"nu 0.499: {f499:.2f} factorizations an increment <= 6")
k.check(f499 <= 1.25 * f49, f"nu 0.499: {f499:.2f} factorizations an increment <= 1.25 x nu 0.49's {f49:.2f}")

# Newton's backward differences from nu 0.49 in steps of 0.01: s = 0.9 steps to nu 0.499.
load = {nu: at_strokes(nu, "load") for nu in NUS}
s = (0.499 - 0.49) / 0.01
d1, d2 = load["0.49"] - load["0.48"], load["0.49"] - 2 * load["0.48"] + load["0.47"]
quadratic = s * (s + 1) / 2 * d2
extrapolated = load["0.49"] + s * d1 + quadratic
open_ = LOAD_PER_DIE_FORCE * EQUILIBRIUM_TOL * at_strokes("0.499", "q_avg")
for i, u in enumerate(STROKES):
    miss, tol = abs(load["0.499"][i] - extrapolated[i]), abs(quadratic[i]) + open_[i]
    k.check(miss <= tol, f"U = {u} mm: load at nu 0.499 {load['0.499'][i]:.4f} N/mm, extrapolated {extrapolated[i]:.4f} "
            f"(quadratic term {quadratic[i]:+.4f}): off by {miss:.4f} <= {tol:.4f} ({miss / load['0.499'][i]:.1e} of it)")
k.done()
