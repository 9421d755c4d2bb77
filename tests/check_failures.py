"""Failing runs: a factorization that fails is reported in words a
user can act on, with MUMPS's own code, instead of KSP's DIVERGED_PC_FAILED.
MUMPS is given 1 MB of working memory (ICNTL(23) = 1) for a system that needs
about 100 times that: INFOG(1) = -19. The run must stop with one line naming
the code and the very option that set it, a non-zero exit, and the results so
far written and flagged. The option's prefix depends on the solver's path:
below 20,000 dofs every rank factors the whole matrix (PCREDUNDANT, whose
inner solver reads -redundant_mat_mumps_*: the 1,666-dof case on 1 and 2
ranks), above it on 2 ranks MUMPS factors it distributed (-mat_mumps_*: the
24,682-dof case); the other prefix is read by no one (-options_left lists it),
so advice naming it would do nothing. The option the message names is the one
that made the run fail, so it demonstrably acts on that path. The same for
MUMPS's workspace cut to half its estimate (ICNTL(14) = -50 %: INFOG(1) =
-9) on 1 rank and distributed on 2: the line names that path's icntl_14, and
the run given it at 50, as the line says, goes through.

Numbers that overflow: a press speed of 1e300 mm/s (the stroke in 4e-300 s:
the inertia term M / dt^2 of the first increment overflows; a modulus of
1e306 MPa, which once did the same, is refused as input now) makes the first
increment's load, out-of-balance norm and energies Inf or NaN; the load is
the first of them in column order. The run must stop naming the increment
and the column (and the first element, when a stress is not finite), with
every number written finite: the history up to the increment before and the
fields of the last finite step.

Friction iterations that never settle stop the run after
-friction_max_unsettled increments in a row (here 4, with a tolerance no
iterate can meet).

The 1-rank runs are the `np1` part, the 2-rank ones the `np2` part (tests/CMakeLists.txt: the first on one core
beside another test, the second with both cores).
"""
import os
import sys

import h5py
import numpy as np

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
part = sys.argv[4] if len(sys.argv) > 4 else "both"
NPS = {"np1": (1,), "np2": (2,)}.get(part, (1, 2))
k = Checks("failures" + (f" ({part})" if part != "both" else ""))
for np_, mesh, option in [c for c in [(1, (16, 48), "-redundant_mat_mumps_icntl_23"), (2, (16, 48), "-redundant_mat_mumps_icntl_23"),
                          (2, (40, 300), "-mat_mumps_icntl_23")] if c[0] in NPS]:
    f = out(f"mumps_np{np_}_{mesh[0]}.h5")
    p = run(tf, mpirun, np_, ["-options_file", f"{src}/options/pressure.opts", "-mesh_nt", mesh[0], "-mesh_ntheta",
                              mesh[1], "-increments", 2, option, 1, "-output", f], check=False, timeout=120)
    lines = [l for l in (p.stdout + p.stderr).splitlines() if l.startswith("tubeform: error")]
    named = [w.strip(",:;()") for w in lines[0].split() if "mumps_icntl" in w] if lines else []
    k.check(p.returncode != 0 and len(lines) == 1 and named == [option] and "INFOG(1) = -19" in lines[0],
            f"np={np_} {mesh[0]} x {mesh[1]} with {option} 1: exit {p.returncode}, it names {named}: {lines}")
    ok = os.path.exists(f)
    if ok:
        with h5py.File(f, "r") as h:
            ok = h["/history"].attrs["stopped"] == 1
    k.check(ok, f"np={np_}: results written and flagged stopped")

# MUMPS's workspace cut to half its own estimate (ICNTL(14) = -50 percent): INFOG(1) = -9. The line names the
# workspace option of the path in use, and that option, raised as the line says, lets the same run through.
for np_, mesh, option in [c for c in [(1, (16, 48), "-redundant_mat_mumps_icntl_14"),
                                      (2, (40, 300), "-mat_mumps_icntl_14")] if c[0] in NPS]:
    case = ["-options_file", f"{src}/options/pressure.opts", "-mesh_nt", mesh[0], "-mesh_ntheta", mesh[1],
            "-increments", 2, "-output", out(f"workspace_np{np_}.h5")]
    p = run(tf, mpirun, np_, case + [option, -50], check=False, timeout=120)
    lines = [l for l in (p.stdout + p.stderr).splitlines() if l.startswith("tubeform: error")]
    named = [w.strip(",:;()") for w in lines[0].split() if "mumps_icntl" in w] if lines else []
    k.check(p.returncode != 0 and len(lines) == 1 and named == [option] and "INFOG(1) = -9" in lines[0],
            f"np={np_} {mesh[0]} x {mesh[1]} with {option} -50: exit {p.returncode}, it names {named}: {lines}")
    p = run(tf, mpirun, np_, case + [option, 50], check=False, timeout=120)
    k.check(p.returncode == 0, f"np={np_} with {option} 50, as the line says: exit {p.returncode}")

for np_ in NPS:
    f = out(f"overflow_np{np_}.h5")
    p = run(tf, mpirun, np_, ["-options_file", f"{src}/options/squaring.opts", "-options_file",
                              f"{src}/options/preset-fast.opts", "-punch_speed", "1e300", "-output", f], check=False)
    lines = [l for l in (p.stdout + p.stderr).splitlines() if l.startswith("tubeform: error")]
    k.check(p.returncode != 0 and len(lines) == 1 and "increment 1 gave load = NaN or Inf" in lines[0],
            f"np={np_} speed 1e300: exit {p.returncode}, {lines}")
    ok = os.path.exists(f)
    if ok:
        with h5py.File(f, "r") as h:
            # (Inf is a flat side's corner radius, the only column where it is a value)
            finite = [all(np.isfinite(h[g][d][()]).all() or (d.startswith("r_corner") and not np.isnan(h[g][d][()]).any())
                          for d in h[g]) for g in ("history", "vertex_fields", "cell_fields")]
            ok = h["/history"].attrs["stopped"] == 1 and all(finite)
    k.check(ok, f"np={np_} speed 1e300: results flagged stopped, every number in them finite")

# Iterations that never settle (a tolerance no iterate meets): the run stops
# after -friction_max_unsettled increments in a row, naming the option, with
# the history up to there. Quasi-static (-dynamics quasistatic), each of those
# increments is taken unsettled (every row's unsettled count rising): the
# paper's friction iterations (-equilibrium_tol 0, -friction_tol 1e-300) and
# the default equilibrium iterations (-equilibrium_tol 1e-12: below round-off
# of the out-of-balance forces), each on 1 and 2 ranks. With inertia (the
# squaring default) a trial is halved further, where the mass balances a
# step; steps that settle only there count too, or the run would creep on at
# 1e-6 of a step: twenty of them count as one unsettled step, so it stops
# after 4 x 20 of them, saying so.
for np_, case in [(n, c) for c in (["-equilibrium_tol", 0, "-friction_tol", "1e-300"], ["-equilibrium_tol", "1e-12"])
                  for n in NPS]:
    f = out(f"unsettled_np{np_}_{case[-2][1:]}.h5")
    p = run(tf, mpirun, np_, ["-options_file", f"{src}/options/squaring.opts", "-options_file",
                              f"{src}/options/preset-fast.opts", "-friction_max_iters", "2",
                              "-friction_max_unsettled", "4", "-dynamics", "quasistatic", "-output", f] + case,
            check=False)
    lines = [l for l in (p.stdout + p.stderr).splitlines() if l.startswith("tubeform: error")]
    k.check(p.returncode != 0 and len(lines) == 1 and "-friction_max_unsettled" in lines[0] and case[-2] in lines[0],
            f"np={np_} unsettled {case[-2]}: exit {p.returncode}, {lines}")
    ok = os.path.exists(f)
    if ok:
        with h5py.File(f, "r") as h:
            u = h["/history/unsettled"][:]
            ok = h["/history"].attrs["stopped"] == 1 and len(u) >= 5 and bool(np.all(np.diff(u[-5:]) >= 1))
    k.check(ok, f"np={np_} unsettled {case[-2]}: results flagged, the last 4 increments each unsettled")
if 1 in NPS:  # (inertia's halvings: one rank is enough)
    f = out("unsettled_inertia.h5")
    p = run(tf, mpirun, 1, ["-options_file", f"{src}/options/squaring.opts", "-options_file",
                            f"{src}/options/preset-fast.opts", "-friction_max_iters", "2", "-friction_max_unsettled",
                            "4", "-equilibrium_tol", "1e-12", "-output", f], check=False)
    lines = [l for l in (p.stdout + p.stderr).splitlines() if l.startswith("tubeform: error")]
    k.check(p.returncode != 0 and len(lines) == 1 and "-friction_max_unsettled" in lines[0] and
            "with inertia" in lines[0],
            f"inertia, unsettled -equilibrium_tol: exit {p.returncode}, one line naming the option and inertia's "
            f"halvings ({lines})")
    if os.path.exists(f):
        with h5py.File(f, "r") as h:
            stopped, rows = h["/history"].attrs["stopped"], h["/history"].attrs["rows"]
        k.check(stopped == 1 and rows < 4 * 20 + 10,
                f"inertia: results flagged stopped after {rows:g} rows (4 x 20 steps settled only on inertia's "
                f"halvings, each a twentieth of an unsettled one; a creep would go on)")
k.done()
