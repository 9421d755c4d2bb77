"""The default preset against the independent CalculiX references
(tests/reference/calculix/, CPE8R converged in mesh and step as far as
tools/calculix/README.md shows; the die withdrawn, so these runs withdraw
it too): the subset of docs/accuracy.md's validation that scripts/test runs.

- default tube (aluminum 17.5/1.5, mu 0.05): the load at U = 1, 2, 3, 4.2 mm
  within the preset's target 1.5 % and C/t at 2, 3, 4.2 mm within its 0.03
  (the reference's own uncertainty is ~0.3 % in the load and ~0.01 in C/t at
  4.2 mm, included in the margins the measured errors leave: 0.29 %, 0.022);
  and the run's own error estimate at least its true load error (the
  estimate must bound it: never report 1 % when it is 5 %);
- the mild steel tube (20/2, mu 0.1, 5 mm): the load within 1.5 % up
  to U = 3 mm; at 4.2 and 5 mm within 1.5 % + 1 %: the reference's contact
  penalty (1e6 MPa/mm) makes its end-of-stroke load soft, by 0.9 % at 4.2 mm
  and 2.4 % at 5 mm against a penalty of 3e7 on its 4 x 90 mesh
  (docs/accuracy.md, "The references' contact penalty"); the extra 1 %
  covers that much of it; the estimate bounds the load error.
- a thick wall (aluminum 15/2.5, R/t 6, mu 0.2, 3 mm; 8 cells through the
  wall, qm6bar by the presets' element rule): the load at U = 1, 2, 3 mm
  within the preset's 1.5 % and C/t at 2, 3 mm within its 0.03 (the
  reference's own uncertainty, its 4 x 90 mesh against this 8 x 180 one:
  0.62 % and 0.0005); the estimate bounds the load error. With 4 cells
  through the wall (the presets before the rule) it is +2.43 % at 3 mm and
  fails.
- the default tube's springback, its die withdrawn as the reference's (the one reference whose withdrawal finished):
  C/t after springback within the preset's 0.03 (the reference's own 4 x 90 -> 8 x 180 change is 0.018 there,
  as loaded); the springback of C/t (loaded less sprung back) within 0.01 of the reference's 0.0932 (its mesh,
  step and penalty studies move it by at most 0.0004; the fast and default presets differ by 0.0033 in it); the
  springback of C1 and C2 (their change over the release) within 0.005 mm of the reference's (+0.022, +0.007 mm).
  Planted: the sprung-back C/t read against the flank of the withdrawn die (as before) reads 0.0 -> FAILED.
Measured (docs/accuracy.md, "Against CalculiX"): default tube +0.13, +0.19,
+0.20, -0.29 %, C/t within 0.022, estimate 12 %; steel (5 cells through its
wall, qm6bar) -0.35, -0.63, +0.01, +0.96, +1.02 %; thick wall +0.09, -0.14,
+0.53 %, C/t within 0.0021.
"""
import csv
import os
import sys

import h5py
import numpy as np

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
sys.path.insert(0, os.path.join(src, "python"))  # the helper package (python/README.md)
from tubeform_py import tfruns  # noqa: E402
k = Checks("against_calculix")


def springback(A, path):
    """The run's answer after the die's withdrawal (attributes A) against the reference's last (sprung-back) row."""
    rows = list(csv.DictReader(l for l in open(path) if not l.startswith("#")))
    loaded = [r for r in rows if float(r["stage"]) == 0][-1]
    ref = {s: {c: float(r[c]) for c in ("c_over_t", "x_max", "y_max")} for s, r in (("loaded", loaded),
                                                                                      ("unloaded", rows[-1]))}
    ours = {s: {c: A[f"{s}_{c}"] for c in ("c_over_t", "x_max", "y_max")} for s in ("loaded", "unloaded")}
    e = ours["unloaded"]["c_over_t"] - ref["unloaded"]["c_over_t"]
    k.check(abs(e) <= 0.03, f"default, die withdrawn: C/t after springback {ours['unloaded']['c_over_t']:.4f} "
            f"against {ref['unloaded']['c_over_t']:.4f} ({e:+.4f}; 0.03)")
    drop = {w: v["loaded"]["c_over_t"] - v["unloaded"]["c_over_t"] for w, v in (("ours", ours), ("ref", ref))}
    k.check(abs(drop["ours"] - drop["ref"]) <= 0.01, f"default, die withdrawn: the springback of C/t "
            f"{drop['ours']:.4f} against {drop['ref']:.4f} (0.01)")
    grow = {c: [v["unloaded"][c] - v["loaded"][c] for v in (ours, ref)] for c in ("x_max", "y_max")}
    k.check(all(abs(a - b) <= 0.005 for a, b in grow.values()), "default, die withdrawn: the springback of C1, C2 "
            + ", ".join(f"{a:+.4f} against {b:+.4f} mm" for a, b in grow.values()) + " (0.005)")


for name, slack in (("default", 0.0), ("steel", 0.01), ("thick", 0.0)):
    opts, R, _, stroke = tfruns.calculix_reference(name)
    f = out(f"ccx_{name}.h5")
    run(tf, mpirun, 1, ["-options_file", f"{src}/options/squaring.opts", "-options_file",
                        f"{src}/options/preset-default.opts"] + opts + ["-progress", 0, "-output", f])
    with h5py.File(f, "r") as h:
        H = {c: h["/history"][c][:] for c in ("stroke", "load", "c_over_t", "stage")}
        estimate = float(h["/history"].attrs["error_load"])
        A = {a: float(h["/history"].attrs[a]) for a in h["/history"].attrs if a.startswith(("loaded_", "unloaded_"))}
    if name == "default":
        springback(A, os.path.join(src, "tests", "reference", "calculix", "default.csv"))
    keep = H["stage"] == 0
    U, P, C = H["stroke"][keep], H["load"][keep], H["c_over_t"][keep]
    strokes = [u for u in (1.0, 2.0, 3.0, 4.2) if u < stroke - 1e-9] + [stroke]
    err = [np.interp(u, U, P) / np.interp(u, R["stroke"], R["load"]) - 1 for u in strokes]
    allowed = [0.015 + (slack if u > 3.0 + 1e-9 else 0.0) for u in strokes]
    k.check(all(abs(e) <= a for e, a in zip(err, allowed)),
            f"{name}: load error at U = {strokes}: " + ", ".join(f"{100 * e:+.2f}" for e in err)
            + f" % (allowed " + ", ".join(f"{100 * a:.1f}" for a in allowed) + " %)")
    if name in ("default", "thick"):
        cerr = [np.interp(u, U, C) - np.interp(u, R["stroke"], R["c_over_t"]) for u in strokes if u >= 2]
        k.check(all(abs(e) <= 0.03 for e in cerr), f"{name}: C/t error at U >= 2 mm: "
                + ", ".join(f"{e:+.4f}" for e in cerr) + " (0.03)")
    worst = max(abs(e) for e in err)
    k.check(estimate >= worst, f"{name}: the estimate {100 * estimate:.2f} % bounds the load error {100 * worst:.2f} %")
k.done()
