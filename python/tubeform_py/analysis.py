"""Reference solutions and result readers shared by the scripts and tests
(run with /usr/bin/python3)."""
import math

import h5py
import numpy as np


def read(path):
    """History (dict of arrays), mesh and cell fields (all steps) of a result file."""
    with h5py.File(path, "r") as h:
        out = {"history": {c: h["/history"][c][:] for c in h["/history"]},
               "X": h["/geometry/vertices"][:], "cells": h["/viz/topology/cells"][:]}
        for name in h["/cell_fields"]:
            out[name[:-2] if name.endswith("_c") else name] = h["/cell_fields"][name][:]
    return out


def cell_areas(X, C):
    P = X[C]
    return 0.5 * sum(P[:, q, 0] * P[:, (q + 1) % 4, 1] - P[:, (q + 1) % 4, 0] * P[:, q, 1] for q in range(4))


def hill_errors(path, sy=165.3, a=10.0, b=20.0):
    """Relative errors of a plastic thick-cylinder run against Hill's plane-strain
    solution (incompressible von Mises, k = sy/sqrt 3): first yield pressure,
    worst pressure vs plastic radius for c in [0.55 b, 0.85 b] (current radii),
    and the limit pressure 2 k ln(b/a) on the current radii at the maximum."""
    d = read(path)
    H, k = d["history"], sy / math.sqrt(3)
    p = H["load"]
    first = int(np.argmax(H["limiter"] == 2))
    py = k * (1 - a * a / (b * b))
    area = cell_areas(d["X"], d["cells"])
    worst, count = 0.0, 0
    if d["plastic"].shape[0] == len(p):
        for j in range(len(p)):
            ap = float((d["plastic"][j] * area).sum())
            c = math.sqrt(a * a + 4 * ap / math.pi)
            if 0.55 * b <= c <= 0.85 * b:
                ac, bc = a + H["stroke"][j], H["x_max"][j]
                cc = math.sqrt(c * c + ac * ac - a * a)
                pc = k * (1 - cc * cc / (bc * bc) + 2 * math.log(cc / ac))
                worst = max(worst, abs(p[j] / pc - 1))
                count += 1
    im = int(np.argmax(p))
    pl = 2 * k * math.log(H["x_max"][im] / (a + H["stroke"][im]))
    return {"first_yield": p[first] / py - 1, "p_first": p[first], "p_y": py, "radius": worst, "radius_points": count,
            "limit": p[im] / pl - 1, "p_max": p[im], "p_limit": pl, "p_limit_small_strain": 2 * k * math.log(b / a),
            "energy": float(np.abs((H["w_ext"][1:] - H["w_int"][1:]) / H["w_ext"][1:]).max()), "increments": len(p) - 1}
