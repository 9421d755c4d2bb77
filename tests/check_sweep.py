"""scripts/sweep (issue 11): a grid of three cases on a coarse mesh, one of
them with a friction coefficient tubeform refuses. The sweep must run the two
good cases, report the bad one with tubeform's own error line and go on, exit
non-zero, and write summary.csv with one row per case whose numbers are those
of the result files (the punch load interpolated at U = 2 mm from the
history, the collapse ratio from the file's attribute); run again it must
skip the finished cases and try only the failed one. --list numbers the
cases without running any.
"""
import csv
import os
import shutil
import subprocess

import h5py
import numpy as np

from tfcheck import Checks, args

tf, mpirun, src = args()
k = Checks("sweep")
d = os.path.join(os.getcwd(), "sweeps")
shutil.rmtree(d, ignore_errors=True)  # a rerun starts from nothing (the sweep itself resumes)
grid = ["--name", "t", "--dir", d, "--exe", tf, "-j", "2", "--axis", "friction_mu=0,0.2,-1"]
cmd = ["/usr/bin/python3", f"{src}/scripts/sweep"] + grid + ["--", "-mesh_nt", "2", "-mesh_ntheta", "24",
                                                             "-stroke", "2.5"]
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
p = subprocess.run(cmd[:2] + grid + ["--list"], capture_output=True, text=True, env=env, cwd=src)
k.check(p.returncode == 0 and len(p.stdout.splitlines()) == 3 and not os.path.exists(os.path.join(d, "t")),
        f"--list: 3 cases, nothing run ({p.stdout.strip()!r})")
p = subprocess.run(cmd, capture_output=True, text=True, env=env, cwd=src, timeout=600)
print(p.stdout[-1500:], p.stderr[-1500:])
k.check(p.returncode != 0, f"a failed case makes the sweep exit non-zero (exit {p.returncode})")
k.check(any("failed: friction_mu--1" in l and "-friction_mu" in l for l in p.stdout.splitlines()),
        "the failed case is reported with tubeform's error line naming the option")
with open(os.path.join(d, "t", "summary.csv")) as f:
    rows = {r["friction_mu"]: r for r in csv.DictReader(f)}
k.check(sorted(rows) == ["-1", "0", "0.2"] and rows["-1"]["status"] == "failed"
        and {rows["0"]["status"], rows["0.2"]["status"]} <= {"done", "inaccurate"},
        "summary: one row per case with its status")
for mu in ("0", "0.2"):
    with h5py.File(os.path.join(d, "t", f"friction_mu-{mu}.h5"), "r") as h:
        H = h["/history"]
        load = H["stage"][:] == 0
        p2 = np.interp(2.0, H["stroke"][:][load], H["load"][:][load])
        ct = H.attrs["loaded_c_over_t"]
        a = dict(H.attrs)
    r = rows[mu]
    # The status from the file's estimate and targets (the run's own attributes, not the sweep's reading).
    loose = a["error_load"] > a["target_load"] or a["error_c_over_t"] > a["target_c_over_t"]
    k.check(r["status"] == ("inaccurate" if loose else "done") and float(r["error_load"]) == float(f"{a['error_load']:.3g}")
            and float(r["P_final"]) == float(f"{a['loaded_load']:.6g}") and float(r["U_final"]) == 2.5,
            f"mu {mu}: status {r['status']} from the estimate (load {a['error_load']:.3g} against "
            f"{a['target_load']:g}, C/t {a['error_c_over_t']:.3g} against {a['target_c_over_t']:g}); the load "
            f"{r['P_final']} at the final stroke {r['U_final']}")
    k.check(abs(float(r["P_2"]) - p2) <= 1e-5 * abs(p2) and abs(float(r["C_over_t_loaded"]) - ct) <= 1e-5 * abs(ct)
            and r["P_4.2"] == "" and float(r["energy_error_a"]) < 0.05,
            f"mu {mu}: P(2) {r['P_2']} and C/t {r['C_over_t_loaded']} as in the result file, no P(4.2) past the "
            f"2.5 mm stroke, (a) {r['energy_error_a']}")
k.check(float(rows["0.2"]["P_2"]) > float(rows["0"]["P_2"]), "friction raises the punch load")
p = subprocess.run(cmd, capture_output=True, text=True, env=env, cwd=src, timeout=600)
k.check("3 cases (2 done before)" in p.stdout and p.stdout.count("failed:") == 1,
        "run again: the two finished cases skipped, the failed one tried again")
k.done()
