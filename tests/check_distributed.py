"""The distributed factorization: 2 ranks above 20,000 dofs against 1 rank.

Above 20,000 dofs on several ranks MUMPS factors the matrix distributed
(src/assembly/linear_solver.cpp); below, or on one rank, every rank factors
the whole matrix. Two cases above the threshold, each run on 1 rank (the
reference) and on 2 ranks:
  - pressure: the plastic thick cylinder (options/pressure_plastic.opts) on
    40 x 250 cells (20,582 dofs), the inner radius driven to 0.07 mm in 7
    increments: the plastic zone has crossed most of the wall (36,500 of its
    40,000 Gauss points), short of the limit load. (Past it the cylinder
    softens as it thins, and which points unload first is decided by
    round-off: runs differing in the last digit part by 8 to 13 % in the
    displacement, on 1 rank as on 2.)
  - squaring: the default scene on 32 x 350 cells (23,166 dofs), pressed to
    U = 0.1 mm (6 nodes in contact with friction, 1,590 plastic Gauss
    points), loading only.
Checks, each case:
  - the 2-rank run says it factors distributed ("MUMPS LU distributed over 2
    ranks (N dofs", N > 20,000), so the comparison below is of that path;
  - the same discrete path: as many increments, and in each the same limiter
    and the same numbers of plastic points and contact nodes;
  - history columns (stroke, load, w_ext, w_int, w_plastic, x_max, y_max)
    and the last displacement field (nodes matched by their coordinates):
    the largest difference relative to the largest value, 2 ranks against
    each 1-rank run, within TOL = K x S.
The tolerance comes from the run's own round-off sensitivity S, measured
here: the 1-rank case run three times, each a change that leaves the
mathematics alone and moves only round-off: MUMPS's AMD ordering without
scaling (the default), the AMF ordering (-redundant_mat_mumps_icntl_7 2: the
factorization's operations in another order) and MUMPS's scaling
(-redundant_mat_mumps_icntl_8 77: the same operations on rescaled numbers);
S is the largest relative difference of the quantities above between any
two of them. The 2-rank run differs from the 1-rank ones by perturbations
of these kinds (MUMPS's own ordering, its scaling, its dynamic scheduling,
the partition boundary's sums in another order), amplified by the same
problem: measured 0.1-2.0 S (pressure) and 0.4-1.3 S (squaring) over 7 runs
of this test and its cases, OpenBLAS Haswell, Prescott and the machine's own
kernel (docs/performance.md, "Solver"). K = 10. S must be
above zero (the variants changed something: else TOL would be meaningless)
and TOL below 1e-6 (round-off, not a run whose last digits decide its path;
a defect at the partition boundary would be O(1e-2), and a modulus or wall
thickness 1e-8 off is caught).
"""
import itertools

import numpy as np

from tfcheck import Checks, args, load, out, run, run_all

tf, mpirun, src = args()
k = Checks("distributed")
K = 10  # TOL = K x S (above)
CEILING = 1e-6  # the largest TOL that still tells round-off from a defect (above)
VARIANTS = {"AMD": [],  # (linear_solver.cpp's default: AMD, no scaling)
            "AMF": ["-redundant_mat_mumps_icntl_7", 2],
            "scaled": ["-redundant_mat_mumps_icntl_8", 77]}
CASES = {
    "pressure": ["-options_file", f"{src}/options/pressure_plastic.opts", "-mesh_nt", 40, "-mesh_ntheta", 250,
                 "-pressure_u", 0.07, "-increments", 7],
    "squaring": ["-options_file", f"{src}/options/squaring.opts", "-mesh_nt", 32, "-mesh_ntheta", 350, "-stroke", 0.1,
                 "-increments", 20, "-error_estimate", 0, "-unload", "none"],
}
COLUMNS = ("stroke", "load", "w_ext", "w_int", "w_plastic", "x_max", "y_max")
DISCRETE = ("limiter", "n_plastic", "n_contact")


def opts(case, tag, extra=()):
    return CASES[case] + list(extra) + ["-output_every", 100000, "-output", out(f"distributed_{case}_{tag}.h5")]


def result(case, tag):
    """Node coordinates, the last displacement (nodes ordered by their initial coordinates), the history."""
    d = load(out(f"distributed_{case}_{tag}.h5"))
    order = np.lexsort((d["X"][:, 1].round(10), d["X"][:, 0].round(10)))
    return d["X"][order], d["U"][order], d["history"]


def differences(a, b):
    """The largest difference of each compared quantity relative to its largest value in a."""
    rel = lambda x, y: float(np.abs(x - y).max() / max(np.abs(x).max(), 1e-300))
    d = {c: rel(a[2][c], b[2][c]) if len(a[2][c]) == len(b[2][c]) else np.inf for c in COLUMNS}
    # (nodes matched by coordinates, to within 1e-6 of the body's size: else the fields cannot be compared)
    matched = a[0].shape == b[0].shape and np.abs(a[0] - b[0]).max() <= 1e-6 * np.abs(a[0]).max()
    d["displacement"] = rel(a[1], b[1]) if matched else np.inf
    return d


def same_path(a, b):
    """'' if a and b took the same increments (count, limiter, plastic points, contact nodes), else what differs."""
    if len(a[2]["stroke"]) != len(b[2]["stroke"]):
        return f": {len(a[2]['stroke']) - 1} and {len(b[2]['stroke']) - 1} increments"
    differ = [c for c in DISCRETE if not np.array_equal(a[2][c], b[2][c])]
    return ": " + ", ".join(differ) + " differ" if differ else ""


# (the squaring cases first: the longest, 6 times a pressure case's; the pool's cores end together)
run_all(tf, mpirun, [opts(c, v, e) for c in reversed(CASES) for v, e in VARIANTS.items()])
two = {c: run(tf, mpirun, 2, opts(c, "np2")) for c in CASES}
for case in CASES:
    line = next((l for l in (two[case].stdout + two[case].stderr).splitlines() if "linear solver:" in l), "")
    words = line.split("(")[-1].split()
    dofs = int(words[0]) if words and words[0].isdigit() else 0
    k.check("MUMPS LU distributed over 2 ranks" in line and dofs > 20000,
            f"{case}: 2 ranks factor distributed above 20,000 dofs: '{line.removeprefix('tubeform: ')}'")
    one = {v: result(case, v) for v in VARIANTS}
    np2 = result(case, "np2")
    spread = {}
    for a, b in itertools.combinations(VARIANTS, 2):
        why = same_path(one[a], one[b])
        k.check(not why, f"{case}: 1 rank, {a} and {b} take the same increments{why}")
        d = differences(one[a], one[b])
        spread[f"{a}-{b} ({max(d, key=d.get)})"] = max(d.values())
    s = max(spread.values())
    tol = K * s
    k.check(0 < s and tol < CEILING, f"{case}: round-off sensitivity S = {s:.1e}, TOL = {K} S = {tol:.1e} (above 0, "
                                     f"below {CEILING:g}); " + ", ".join(f"{p} {x:.1e}" for p, x in spread.items()))
    for v in VARIANTS:
        why = same_path(one[v], np2)
        k.check(not why, f"{case}: 2 ranks take the increments of 1 rank ({v}){why}")
        d = differences(one[v], np2)
        worst = max(d, key=d.get)
        k.check(d[worst] <= tol, f"{case}: 2 ranks against 1 ({v}): largest difference {d[worst]:.1e} ({worst}; "
                                 f"{d[worst] / s if s else np.inf:.2f} S), TOL {tol:.1e}; "
                                 + ", ".join(f"{c} {x:.1e}" for c, x in d.items() if c != worst))
k.done()
