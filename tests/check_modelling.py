"""Model only what a scene requires, shown by PETSc's -log_view event counts:
a frictionless run does no friction work (TfFriction: friction iterates and
forces), an elastic run no plasticity work (TfYield: loading states, yield
onsets, transitions in the scans), a scene without tools no contact work
(TfContact: projections, limits, commits). Each zero count is paired with a
run where the same event is counted, so a renamed or unreached event cannot
pass for a skipped computation.
"""
import re

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
k = Checks("modelling")


def counts(name, opts):
    log = out(f"model_{name}.txt")
    run(tf, mpirun, 1, opts + ["-output", out(f"model_{name}.h5"), "-log_view", f":{log}"])
    text = open(log).read()
    c = {}
    for ev in ("TfFriction", "TfYield", "TfContact", "TfScan"):
        c[ev] = sum(int(m.group(1)) for m in re.finditer(rf"^{ev}\s+(\d+)", text, re.M))
    return c


squaring = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
            "-stroke", 0.6, "-unload", "none"]
runs = {
    "friction": counts("friction", squaring),
    "frictionless": counts("frictionless", squaring + ["-friction_mu", 0]),
    "elastic": counts("elastic", squaring + ["-material_law", "elastic"]),
    "pressure": counts("pressure", ["-options_file", f"{src}/options/pressure.opts", "-increments", 3]),
}
for name, c in runs.items():
    print(f"{name}: {c}")
k.check(runs["friction"]["TfFriction"] > 0, f"mu 0.05: friction work done ({runs['friction']['TfFriction']} events)")
k.check(runs["frictionless"]["TfFriction"] == 0, "mu 0: no friction work (TfFriction 0)")
k.check(runs["friction"]["TfYield"] > 0, f"plastic law: yield scans done ({runs['friction']['TfYield']} events)")
k.check(runs["elastic"]["TfYield"] == 0 and runs["elastic"]["TfScan"] > 0,
        f"-material_law elastic: no plasticity work (TfYield 0) in {runs['elastic']['TfScan']} scans")
k.check(runs["friction"]["TfContact"] > 0, f"squaring: contact work done ({runs['friction']['TfContact']} events)")
k.check(runs["pressure"]["TfContact"] == 0 and runs["pressure"]["TfFriction"] == 0,
        "pressure scene (no tools): no contact or friction work")
k.done()
