"""The rate problem of a plane-strain block in uniaxial stress (sigma_yy = 0) pulled along x to nominal strains:
the stress path integrated in substeps, each solved for sigma_yy = 0 by a secant on its d_yy. Shared by
tests/check_tension.py and tests/check_kinematic.py, which give the material's update; no part of it comes from the
solver.

Plain floats, not numpy: a substep is three stress components, which numpy's per-call cost would make these tests'
longest part. The secant starts from the last substep's d_yy / d_xx, which changes little between substeps (it
takes 2-3 updates a substep, against 5-6 from a fixed start)."""
import math

import numpy as np

SIGMA_YY_TOL = 1e-11  # MPa: the secant's stop, 1e-13 of the stresses here (round-off of the update's sums)
FIRST_RATIO = -0.5  # d_yy / d_xx of an incompressible flow, the first substep's start
RATIO_STEP = 1e-3  # the secant's second point, this far in d_yy / d_xx from its first


def stress_path(strokes, sub, update, state, sxx, syy):
    """sigma_xx at the nominal strains `strokes` (the first the state's), `sub` substeps between each two.
    update(state, dxx, dyy) returns the state at the end of a substep of logarithmic strain increments dxx, dyy
    (dzz = 0) without changing `state`; sxx(state) and syy(state) read its stresses."""
    out, ratio = [sxx(state)], FIRST_RATIO
    for a, b in zip(strokes[:-1], strokes[1:]):
        for j in range(sub):
            dxx = math.log1p(a + (b - a) * (j + 1) / sub) - math.log1p(a + (b - a) * j / sub)
            y0, y1 = ratio * dxx, (ratio + RATIO_STEP) * dxx
            f0, new = syy(update(state, dxx, y0)), update(state, dxx, y1)
            f1 = syy(new)
            for _ in range(60):
                if f1 == f0 or abs(f1) < SIGMA_YY_TOL:
                    break
                y0, f0, y1 = y1, f1, y1 - f1 * (y1 - y0) / (f1 - f0)
                new = update(state, dxx, y1)
                f1 = syy(new)
            state = new
            if dxx != 0:
                ratio = y1 / dxx
        out.append(sxx(state))
    return np.array(out)
