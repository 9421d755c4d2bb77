#!/usr/bin/env python3
"""The lowest eigenvalues of the tangent's free block, from what the diagnostic
patch of studies/rotation_mode writes to DIR (the matrix in PETSc's binary format,
DIR/K_<solve>.bin; its prescribed rows, K_<solve>_rows.txt; each node's x dof
and coordinates, K_<solve>_nodes.txt). Run by studies/rotation_mode.

usage: tangent_eigs.py DIR SOLVE...
A negative real eigenvalue of the unsymmetric free block is a static
divergence of the quasi-static increment: the path is unstable along its
eigenvector, whose share in a rigid rotation and in a slide along x is
printed. The symmetric part's lowest eigenvalue is printed beside it (the
friction rows make it indefinite without making the matrix unstable)."""
import os
import sys

import numpy as np


def read_petsc_aij(path):
    """A sequential AIJ matrix in PETSc's binary format (big-endian int32 header, row lengths, columns, float64)."""
    b = open(path, "rb").read()
    _, m, n, nz = np.frombuffer(b[:16], ">i4")
    off = 16
    lengths = np.frombuffer(b[off:off + 4 * m], ">i4")
    off += 4 * m
    cols = np.frombuffer(b[off:off + 4 * nz], ">i4")
    off += 4 * nz
    vals = np.frombuffer(b[off:off + 8 * nz], ">f8")
    k = np.zeros((m, n))
    k[np.repeat(np.arange(m), lengths), cols] = vals
    return k


def main():
    where = sys.argv[1]
    for solve in sys.argv[2:]:
        k = read_petsc_aij(os.path.join(where, f"K_{solve}.bin"))
        rows = np.loadtxt(os.path.join(where, f"K_{solve}_rows.txt"), dtype=int, ndmin=1)
        free = np.setdiff1d(np.arange(k.shape[0]), rows)
        kf = k[np.ix_(free, free)]
        w, v = np.linalg.eig(kf)
        order = np.argsort(w.real)
        w, v = w[order], v[:, order]
        ws = np.linalg.eigvalsh(0.5 * (kf + kf.T))
        # The lowest mode's shape: its share (cosine) in a rigid rotation about the tube's centre and in a slide
        # along x, on the nodes' starting coordinates (the contact nodes' dofs are in their frames: a few per cent).
        nodes = np.loadtxt(os.path.join(where, f"K_{solve}_nodes.txt"), ndmin=2)
        dof, x, y = nodes[:, 0].astype(int), nodes[:, 1], nodes[:, 2]
        rigid = {"rotation": np.zeros(k.shape[0]), "slide": np.zeros(k.shape[0])}
        rigid["rotation"][dof], rigid["rotation"][dof + 1] = -y, x
        rigid["slide"][dof] = 1.0
        mode = np.zeros(k.shape[0])
        mode[free] = np.real(v[:, 0])
        share = {n: abs(mode @ r) / (np.linalg.norm(mode) * np.linalg.norm(r)) for n, r in rigid.items()}
        print(f"solve {solve:>4}: {len(free)} free dofs, lowest eigenvalues "
              + " ".join(f"{x.real:+.2e}" + (f"{x.imag:+.1e}j" if x.imag else "") for x in w[:3])
              + f" (largest {abs(w[-1]):.2e}); symmetric part's lowest {ws[0]:+.2e}; the lowest mode "
              f"{share['rotation']:.2f} a rotation, {share['slide']:.2f} a slide")


if __name__ == "__main__":
    main()
