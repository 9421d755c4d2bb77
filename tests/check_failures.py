"""Failing runs (issue 12): a factorization that fails is reported in words a
user can act on, with MUMPS's own code, instead of KSP's DIVERGED_PC_FAILED.
MUMPS is given 1 MB of working memory (-mat_mumps_icntl_23 1) for a 3,500-dof
system that needs about 100 times that: INFOG(1) = -19. On 1 and 2 ranks the
run must stop with one line naming ICNTL(23) and the code, a non-zero exit,
and the results so far written and flagged.
"""
import os

import h5py

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
k = Checks("failures")
for np_ in (1, 2):
    f = out(f"mumps_np{np_}.h5")
    p = run(tf, mpirun, np_, ["-options_file", f"{src}/options/pressure.opts", "-mesh_nt", 16, "-mesh_ntheta", 48,
                              "-redundant_mat_mumps_icntl_23", 1, "-output", f], check=False, timeout=120)
    lines = [l for l in (p.stdout + p.stderr).splitlines() if l.startswith("tubeform: error")]
    k.check(p.returncode != 0 and len(lines) == 1 and "icntl_23" in lines[0] and "INFOG(1) = -19" in lines[0],
            f"np={np_}: exit {p.returncode}, {lines}")
    ok = os.path.exists(f)
    if ok:
        with h5py.File(f, "r") as h:
            ok = h["/history"].attrs["stopped"] == 1
    k.check(ok, f"np={np_}: results written and flagged stopped")
k.done()
