"""Homogeneous plane-strain tension/compression (options/tension.opts): the
von Mises stress against the flow curve sigma_y(ep) evaluated here from the
law's formula (independent of the code), for each hardening law: Ludwik
(aluminum n = 0.927, linear n = 1, n = 0.1), Swift, a table, perfect
plasticity, and compression. With the paper's tangent update the stress drifts
off the curve where the path turns (elastic-plastic transition), by an amount
that falls with the increment (measured: 1.5 %, 0.2 %, 0.03 % at 50, 200,
800 increments for aluminum); at 400 increments it must stay below 0.5 %.
With -drift_correction it is on the curve to round-off (1e-10).
"""
import math

import h5py
import numpy as np

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
k = Checks("tension")
table = [(0.0, 165.0), (0.01, 200.0), (0.05, 240.0)]


def table_sy(ep):
    return float(np.interp(ep, [e for e, _ in table], [s for _, s in table]))


cases = [
    ("ludwik aluminum", [], lambda ep: 165.3 + 673.5 * ep**0.927),
    ("ludwik n=1", ["-material_n", 1], lambda ep: 165.3 + 673.5 * ep),
    ("ludwik n=0.1", ["-material_n", 0.1], lambda ep: 165.3 + 673.5 * ep**0.1),
    ("perfectly plastic", ["-material_k", 0], lambda ep: 165.3),
    ("swift", ["-material_law", "swift", "-material_k", 500, "-material_n", 0.2], lambda ep: 500 * ((165.3 / 500) ** 5 + ep) ** 0.2),
    ("table", ["-material_law", "table", "-material_table", ",".join(f"{e},{s}" for e, s in table)], table_sy),
    ("compression", ["-tension_strain", -0.1], lambda ep: 165.3 + 673.5 * ep**0.927),
]
for name, extra, law in cases:
    for drift in (False, True):
        f = out("tension.h5")
        run(tf, mpirun, 1, ["-options_file", f"{src}/options/tension.opts", "-increments", 400, "-rmin_deps", 0.5, "-output", f]
            + extra + (["-drift_correction"] if drift else []))
        with h5py.File(f, "r") as h:
            vm = h["/cell_fields/von_mises_c"][:].mean(axis=1)
            ep = h["/cell_fields/eps_p_c"][:].mean(axis=1)
        m = ep > 0
        err = max(abs(v / law(e) - 1) for v, e in zip(vm[m], ep[m]))
        tol = 1e-10 if drift else 5e-3
        k.check(m.sum() > 100 and err < tol, f"{name}{' (drift correction)' if drift else ''}: max |sbar / sigma_y(ep) - 1| = {err:.1e} < {tol:g}, ep(end) = {ep[-1]:.4f}")
k.done()
