#!/usr/bin/python3
"""Per-increment cost of the incremental loop, from PETSc's -log_view.

    /usr/bin/python3 tools/bench_increment.py [NP] [SOLVER]

SOLVER: mumps (default, options/solver.opts) or petsc (PETSc's own sparse LU
as the redundant factorization: -redundant_pc_factor_mat_solver_type petsc).

Runs the pressure scene (elastic, output only at the end) on meshes from the
default (8 x 24) upwards, and prints, per increment, the time of assembly,
boundary rows, MUMPS numeric factorization + solve, and the commit (state update); also
how many symbolic factorizations MUMPS did (1 = analysis reused).
"""
import os
import re
import subprocess
import sys

# The helper package python/tubeform_py (python/README.md).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from tubeform_py.tfruns import runs_env  # noqa: E402

np_ = sys.argv[1] if len(sys.argv) > 1 else "1"
solver = sys.argv[2] if len(sys.argv) > 2 else "mumps"
root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
env = runs_env(os.environ)  # (scripts/runs.env: the environment of tubeform's runs)
incs = 20
print(f"ranks {np_}, {incs} increments, factorization {solver}; times in ms per increment (max over ranks)")
print(f"{'mesh':>12} {'dofs':>8} {'assemble':>9} {'bc':>7} {'solve':>8} {'  factor':>8} {'commit':>7} {'total':>8} {'sym.fact':>8}")
for nt, nth in ((8, 24), (4, 48), (8, 192), (16, 384), (32, 768)):
    cmd = ["mpirun", "-q", "-n", np_, f"{root}/build/tubeform", "-options_file", "options/pressure.opts", "-mesh_nt", str(nt),
           "-mesh_ntheta", str(nth), "-increments", str(incs), "-output_every", str(incs), "-output", "/tmp/tubeform_bench.h5",
           "-history_csv", "/tmp/tubeform_bench.csv", "-log_view", "-redundant_pc_factor_mat_solver_type", solver]
    out = subprocess.run(cmd, capture_output=True, text=True, cwd=root, env=env, check=True).stdout

    def ev(name):
        m = re.search(rf"^{name}\s+(\d+)\s+\S+\s+(\S+)", out, re.M)
        return (int(m.group(1)), float(m.group(2))) if m else (0, 0.0)

    t = {k: ev(k)[1] / incs * 1e3 for k in ("TfAssemble", "TfApplyBC", "TfSolve", "MatLUFactorNum", "TfCommit")}
    total = t["TfAssemble"] + t["TfApplyBC"] + t["TfSolve"] + t["TfCommit"]
    dofs = 2 * (nt + 1) * (nth + 1)
    print(f"{nt:>4} x {nth:<5} {dofs:>8} {t['TfAssemble']:>9.2f} {t['TfApplyBC']:>7.2f} {t['TfSolve']:>8.2f} {t['MatLUFactorNum']:>8.2f} {t['TfCommit']:>7.2f} {total:>8.2f} {ev('MatLUFactorSym')[0]:>8d}")
