"""The error estimate's candidates that studies/estimate_levels.py judges (`eval`): each an estimate, in the values'
units, from a record of a preset level's runs (estimate_levels.record: the run, its step and mesh companions, its
directional levels), None where the levels it reads are missing.

Levels: run; S its steps' companion (s 1/2); M the mesh companion (half the cells through the wall, at least 2, and
around); MS both; MM half M's; the directional ones at s 1: T- half the cells through the wall (none under 2), T+ and
T++ two and four times them, A- half the cells around, A+ twice them; Q and QS (plan quarter) three quarters of
the cells through the wall (at least 2) and around, at s 1 and 1/2.
"""
import os

import numpy as np

A = np.abs
# The contact ripple is taken out of a curve by a local quadratic fit over +- this many of its periods.
FIT_PERIODS = float(os.environ.get("FIT_PERIODS", "2"))
# An observed order is believed between these (a first-order element's 1 and a smooth second order's 2, a factor
# beyond): outside, and where the three levels do not converge monotonically, the direction's part takes p 1.
ORDER_RANGE = (0.5, 3.0)


def at(U, F, u, w=0.0):
    """F at stroke u: interpolated (w 0), or read off a local quadratic fit over u +- w (one-sided at the end)."""
    if w <= 0:
        return float(np.interp(u, U, F))
    m = (U >= u - w) & (U <= u + w) if u + w <= U[-1] + 1e-9 else U >= U[-1] - 2 * w
    return float(np.polyfit(U[m] - u, F[m], 2)[-1])



def at_cells(r, key, w=0.0):
    """Level `key`'s loads and C/t at the reported strokes (fitted over +- w mm), C/t after springback."""
    spring, (U, P, C) = r["curves"][key]
    return np.array([at(U, P, u, w) for u in r["strokes"]] + [at(U, C, u, w) for u in r["strokes"]] + [spring])


def parts(r, periods=0.0):
    """The steps' part MS - M, the mesh's part M - run (signed), and the run's own contact ripple |run - its fit|:
    the curves fitted over +- `periods` contact periods (0: as they are, no ripple)."""
    run, m, ms = (at_cells(r, k, periods * r["period"]) for k in ("run", "M", "MS"))
    return ms - m, m - run, np.abs(at_cells(r, "run") - run)


# Richardson's 1 / (2^p - 1) for the mesh's part at refinement 2: p = 1 for qm6 (stiff by about 1/n through the
# wall), p = 2 for qm6bar (docs/accuracy.md, "The element through the wall").
mesh_factor = lambda r: 1 / 3 if r["element"] == "qm6bar" else 1.0  # noqa: E731


def ripple_free(r, worst=False, mesh=1.0, spring=False, w=None):
    """|MS - M| + mesh |M - run| with the contact ripple out: the curves fitted over +- FIT_PERIODS periods plus the
    run's own ripple, or (worst) the largest over u +- one period. `spring`: C/t after springback as the loaded end's
    estimate plus that of the springback's change (a sum's error is within the sum of its terms')."""
    s, m, q = parts(r, 0 if worst else (w or FIT_PERIODS))
    est, U = A(s) + mesh * A(m) + q, r["curves"]["run"][1][0]
    for k, (col, u) in enumerate([(c, u) for c in (1, 2) for u in r["strokes"]] if worst else []):
        us = np.linspace(max(U[0], u - r["period"]), min(U[-1], u + r["period"]), 41)
        y = {k: np.interp(us, r["curves"][k][1][0], r["curves"][k][1][col]) for k in ("run", "M", "MS")}
        est[k] = np.max(A(y["MS"] - y["M"]) + mesh * A(y["M"] - y["run"]))
    if spring:
        run, m, ms = (at_cells(r, k)[-1] - at_cells(r, k)[-2] for k in ("run", "M", "MS"))
        est[-1] = est[-2] + A(ms - m) + mesh * A(m - run)
    return est


def gci(r):
    """Roache's grid convergence index from the meshes run, M, MM (Celik et al. 2008), plus |MS - M|: where the mesh
    converges monotonically (0 < (run - M) / (M - MM) < 1) at an observed order p in [0.5, 2] (qm6's 1 within a
    factor 2), 1.25 |M - run| / (2^p - 1); elsewhere 3 |M - run| (p 1, the two-grid factor). qm6 runs with MM only."""
    if r["curves"]["MM"] is None or r["element"] != "qm6":
        return None
    run, m, mm = (at_cells(r, k) for k in ("run", "M", "MM"))
    R = (run - m) / np.where(m == mm, 1e-300, m - mm)
    p = np.log(1 / np.clip(R, 1e-12, None)) / np.log(2)
    sure = (R > 0) & (R < 1) & (p >= 0.5) & (p <= 2)
    return A(parts(r)[0]) + np.where(sure, 1.25 / (2 ** np.clip(p, 0.5, 2) - 1), 3) * A(m - run)


def order(coarse, mid, fine):
    """The order observed per value on three levels at refinement 2 where it is believed (monotone convergence, within
    ORDER_RANGE), else 1; and where it is believed."""
    R = (mid - fine) / np.where(coarse == mid, 1e-300, coarse - mid)
    p = np.log2(1 / np.clip(R, 1e-12, None))
    sure = (R > 0) & (p >= ORDER_RANGE[0]) & (p <= ORDER_RANGE[1])
    return np.where(sure, p, 1.0), sure


def directional(r, observed=False, element=False):
    """The run's error through the wall and around, each at order 1 or (observed) at the order its direction's three
    levels show (`order`): from the coarser companion |c - run| / (2^p - 1); through the wall from the finer T+ where
    T- cannot be (2 cells) |T+ - run| 2^p / (2^p - 1). A dict of the parts (and signed: the run's error), orders and
    where the orders are believed; None where a direction's companion is missing. `element`: through the wall at the
    element's order (mesh_factor's: qm6 1, qm6bar 2)."""
    c, run = r["curves"], at_cells(r, "run")
    v = {k: None if c[k] is None else at_cells(r, k) for k in ("T-", "T+", "T++", "A-", "A+")}
    coarse = v["T-"] is not None
    if v["A-"] is None or (v["T-"] if coarse else v["T+"]) is None:
        return None
    out = {}
    for d, ladder in (("t", (v["T-"], run, v["T+"]) if coarse else (run, v["T+"], v["T++"])),
                      ("a", (v["A-"], run, v["A+"]))):
        full = observed and all(x is not None for x in ladder)
        p, sure = order(*ladder) if full else (np.ones_like(run), np.zeros(run.shape, bool))
        p = np.full_like(run, 2.0) if element and d == "t" and r["element"] == "qm6bar" else p
        signed = (ladder[0] - run) / (2 ** p - 1) if d == "a" or coarse else (run - v["T+"]) * 2 ** p / (2 ** p - 1)
        out[d], out["signed_" + d] = A(signed), signed
        out["p_" + d], out["sure_" + d] = p, sure
    return out


def steps_and_directions(r, observed=False, signed=False, element=False):
    """|MS - M| + the run's error through the wall + around (`directional`), or (signed) + |their signed sum|."""
    d = directional(r, observed, element)
    return None if d is None else A(parts(r)[0]) + (A(d["signed_t"] + d["signed_a"]) if signed else d["t"] + d["a"])


def quarter(r, p=1.0, periods=0.0, steps=1.0):
    """|QS - Q| + |Q - run| / (r^p - 1) from the companions at three quarters of the cells (Q, r = 4/3 around, and
    through the wall where the run has more than 2 cells) and Q at twice its increment limits (QS); the curves fitted
    over +- `periods` contact periods plus the run's ripple (0: as they are)."""
    c = r["curves"]
    if c.get("Q") is None or c.get("QS") is None:
        return None
    w = periods * r["period"]
    run, q, qs = (at_cells(r, k, w) for k in ("run", "Q", "QS"))
    ripple = A(at_cells(r, "run") - run) if periods else 0.0
    return steps * A(qs - q) + A(q - run) / (r["ratio_a"] ** p - 1) + ripple


# Candidates: an estimate (the values' units) from a record, None where its levels are missing. "old" and the
# second-order mesh are what docs/accuracy.md compares with; (a)-(d) the families the study of the estimate tried.
CANDIDATES = {
    "old: 3 |MS - run|": lambda r: 3 * A(sum(parts(r)[:2])),
    "shipped: |MS - M| + |M - run|": lambda r: A(parts(r)[0]) + A(parts(r)[1]),
    "|MS - M| + |M - run| / 3": lambda r: A(parts(r)[0]) + A(parts(r)[1]) / 3,
    "a signed: |MS - run| (p 1)": lambda r: A(sum(parts(r)[:2])),
    "a max(signed, parts / 2)": lambda r: np.maximum(A(sum(parts(r)[:2])), (A(parts(r)[0]) + A(parts(r)[1])) / 2),
    "a max(signed, larger part)": lambda r: np.maximum(A(sum(parts(r)[:2])), np.maximum(*map(A, parts(r)[:2]))),
    "b |MS - M| + |M - run| / (2^p - 1)": lambda r: A(parts(r)[0]) + mesh_factor(r) * A(parts(r)[1]),
    "c fitted + ripple, b": lambda r: ripple_free(r, mesh=mesh_factor(r)),
    "c fitted + ripple, b, sprung from the end": lambda r: ripple_free(r, mesh=mesh_factor(r), spring=True),
    "c fitted + ripple, sprung from the end": lambda r: ripple_free(r, spring=True),
    "c fitted + ripple, sprung from the end, 1 period": lambda r: ripple_free(r, spring=True, w=1),
    "c fitted + ripple, sprung from the end, 3 periods": lambda r: ripple_free(r, spring=True, w=3),
    "c max over +- 1 period, b": lambda r: ripple_free(r, worst=True, mesh=mesh_factor(r)),
    "c max over +- 1 period, b, sprung from the end": lambda r: ripple_free(r, True, mesh_factor(r), True),
    "q 3/4 companions, p 1": lambda r: quarter(r, 1.0),
    "q 3/4 companions, p 2": lambda r: quarter(r, 2.0),
    "q 3/4 companions, p 1.5": lambda r: quarter(r, 1.5),
    "q 3/4 companions, p 2, ripple fitted": lambda r: quarter(r, 2.0, FIT_PERIODS),
    "d GCI run, M, MM": gci,
    "d shipped where GCI applies": lambda r: None if gci(r) is None else A(parts(r)[0]) + A(parts(r)[1]),
    "d |S - run| + |M - run|": lambda r: A(at_cells(r, "S") - at_cells(r, "run")) + A(parts(r)[1]),
    "e |MS - M| + through + around (p 1)": steps_and_directions,
    "e |MS - M| + through + around (p observed)": lambda r: steps_and_directions(r, True),
    "e |MS - M| + through (qm6bar p 2) + around (p 1)": lambda r: steps_and_directions(r, element=True),
    "e |MS - M| + |through + around| signed (p 1)": lambda r: steps_and_directions(r, signed=True),
    "e shipped where directions apply": lambda r: None if directional(r) is None else A(parts(r)[0]) + A(parts(r)[1]),
}
# Bases for a fitted factor c (the least that bounds 95 % of the cells): how sharp each could be, and, leaving one
# tube out, how far c fitted to four tubes carries to the fifth.
FITTED = ("shipped: |MS - M| + |M - run|", "a signed: |MS - run| (p 1)", "c fitted + ripple, b, sprung from the end",
          "e |MS - M| + through + around (p 1)", "e |MS - M| + through + around (p observed)")

