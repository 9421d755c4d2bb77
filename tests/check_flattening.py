"""Ring crush between plates (options/flattening.opts): Rm/t = 20, qm6 2 x 96,
elastic-perfectly plastic aluminum, frictionless.
References (thin ring theory, plane strain):
  elastic  P/delta = E' I / (0.1488 Rm^3), delta = 2 U, E' = E/(1-nu^2), I = t^3/12
  plastic  P0 = 4 Mp / Rm, Mp = (2/sqrt 3) sy t^2 / 4 (rigid-plastic collapse)
Checks: the stiffness of the first (elastic) increment within 3 %; the
load where the plateau begins within 10 % of P0, taken as the intersection
of the initial elastic line with the tangent of the last quarter of the
curve (the two-tangent construction: the elastic-plastic curve bends over
gradually, so some construction is needed; measured 0.95 P0 on refined
meshes too). Energy balance within 1 % of the external work.
"""
import math

import h5py
import numpy as np

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
k = Checks("flattening")
E, nu, t, Rm, sy = 75000.0, 0.34, 1.0, 20.0, 165.3
f = out("flattening.h5")
run(tf, mpirun, 2, ["-options_file", f"{src}/options/flattening.opts", "-stroke", 3, "-output", f, "-output_every", 100000])
with h5py.File(f, "r") as h:
    H = {c: h["/history"][c][:] for c in h["/history"]}
U, P = H["stroke"], H["load"]
stiff = E / (1 - nu * nu) * t**3 / 12 / (0.1488 * Rm**3)
ratio = P[1] / (2 * U[1]) / stiff  # first increment: the ring's geometry still circular
k.check(H["n_plastic"][1] == 0 and abs(ratio - 1) < 0.03, f"elastic P/delta = {P[1] / (2 * U[1]):.4f}, thin ring {stiff:.4f} ({ratio - 1:+.2%})")
P0 = 4 * (2 / math.sqrt(3)) * sy * t * t / 4 / Rm
late = U >= 0.75 * U[-1]
slope, icpt = np.polyfit(U[late], P[late], 1)
k_el = P[1] / U[1]
u_x = icpt / (k_el - slope)
p_onset = k_el * u_x
k.check(abs(p_onset / P0 - 1) < 0.10, f"plateau onset {p_onset:.3f} N/mm vs 4 Mp/Rm = {P0:.3f} ({p_onset / P0 - 1:+.1%}); load at the end {P[-1]:.3f}")
e = np.abs(H["energy_error"][1:]).max()
k.check(e < 0.01, f"energy balance error {e:.2e} < 1 %")
k.done()
