"""scripts/figures --quick from nothing: runs the fast preset's cases of its
quick grid into the test directory (22 real runs, under a minute on 2 cores)
and draws every figure as PNG and PDF. Checks that each of the 16 figures
exists in both formats and is not empty, that every case finished, that the
two tables (critical R/t, apex radius) were written, and the one claim of
the paper's Fig. 3 that does not depend on its unknown die: at mu 0.05 the
thick aluminum tube (R/t 11.67) needs the largest punch load at every stroke
and the thin aluminum one (R/t 37) the smallest, copper (R/t 29) between (the
thin aluminum tube's 0.5 mm wall on a smaller radius, with 2.7 times
aluminum's initial yield stress); and copper needs more load than aluminum
on the same tube (R/t 29), as the paper says.
"""
import csv
import glob
import os
import shutil
import subprocess

from tfcheck import Checks, args

tf, mpirun, src = args()
k = Checks("figures")
out, res = os.path.join(os.getcwd(), "figs"), os.path.join(os.getcwd(), "figsweeps")
for d in (out, res):
    shutil.rmtree(d, ignore_errors=True)  # from nothing, as on a clean checkout
p = subprocess.run(["/usr/bin/python3", f"{src}/scripts/figures", "--quick", "--out", out, "--results", res,
                    "--exe", tf],
                   capture_output=True, text=True, timeout=540,
                   env=dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1"))
print(p.stdout[-1500:], p.stderr[-1500:])
k.check(p.returncode == 0 and "16 figures" in p.stdout, f"scripts/figures exit {p.returncode}")
names = ["fig03_load_stroke", "fig04_shapes", "fig05_increments", "fig06_deviation", "fig07_asymmetric",
         "fig08_collapse", "fig09_deviation_rt", "fig10_collapse_rt", "fig11_deviation_mu", "fig12_collapse_mu",
         "eqps_loaded", "fig09b_deviation_rt_rule", "fig10b_collapse_rt_rule", "collapse_map", "press_force_rt",
         "hardening_springback_tubes"]
for ext in ("png", "pdf"):
    sizes = [os.path.getsize(os.path.join(out, f"{n}.{ext}")) if os.path.exists(os.path.join(out, f"{n}.{ext}"))
             else 0 for n in names]
    k.check(min(sizes) > 5000, f"every figure as {ext}, none smaller than 5 kB (smallest {min(sizes)} B)")
status = []
for f in glob.glob(os.path.join(res, "fig_fast_*", "summary.csv")):
    with open(f) as fh:
        status += [r["status"] for r in csv.DictReader(fh)]
# The --quick grid: 3 paper tubes x 2 mu, 2 R/t x 2 mu (3.2 mm), 3 R/t x 2 mu (the rule), one material, 1 R/t x 2
# apex radii, the 3 paper tubes with a backstress. --quick runs without error estimates, so a finished case is "done"
# (never "inaccurate").
expected = 3 * 2 + 2 * 2 + 3 * 2 + 1 + 1 * 2 + 3
k.check(len(status) == expected and all(s == "done" for s in status),
        f"{sum(s == 'done' for s in status)} of {len(status)} cases done ({expected} in the grid)")
# The critical R/t table has a row per friction coefficient of the rule grid (2), the apex table one per case (2).
rows = {"critical_rt_fast.md": 2, "die_apex_fast.md": 2}
k.check(all(os.path.exists(os.path.join(out, t)) and open(os.path.join(out, t)).read().count("\n| ") - 1 == n
            for t, n in rows.items()), "both tables written, a row per case")
P = {}
for tube in ("al_11.67", "al_37", "cu_29"):
    with open(os.path.join(res, f"fig_fast_paper_{tube}", "summary.csv")) as fh:
        row = next(r for r in csv.DictReader(fh) if r["friction_mu"] == "0.05")
    P[tube] = [float(row[f"P_{u}"]) for u in ("1", "2", "3")]
with open(os.path.join(res, "fig_fast_material", "summary.csv")) as fh:
    row = next(csv.DictReader(fh))
P["al_29"] = [float(row[f"P_{u}"]) for u in ("1", "2", "3")]
k.check(all(P["al_11.67"][i] > P["cu_29"][i] > P["al_37"][i] for i in range(3)),
        f"Fig. 3 ordering at U = 1, 2, 3 mm: {P}")
k.check(all(P["cu_29"][i] > P["al_29"][i] for i in range(3)), "copper needs more load than aluminum at equal R/t")
k.done()
