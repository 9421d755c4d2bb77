#!/usr/bin/python3
"""Cook's membrane, solved independently of tubeform (NumPy/SciPy): the reference
values of tests/test_elements.cpp and docs/verification.md.

Geometry: corners (0,0), (48,44), (48,60), (0,44); left edge clamped;
uniform vertical traction on right edge, total force F.
Structured n x n mesh of Lagrange quads of order p (p=1: Q4, p=2: Q9, ...),
isoparametric, mapped by the bilinear map of the four corners
  x = 48 xi, y = 44 xi + eta (44 + 16 xi - 44 xi).
Quantity: vertical displacement of C = (48, 60).

Constitutive options:
  'stress'  : plane stress (E, nu) directly
  'strain'  : plane strain (E, nu), full integration
  'mixed'   : plane strain, volumetric part projected onto discontinuous
              P_{p-1} pressure (Q_p / P_{p-1} mixed element, statically
              condensed; for p=2 this is the Q9/P3 element) -> locking free
Usage: /usr/bin/python3 tools/reference_cook.py [--full]
  prints the vertical displacement at the corner C = (48, 60) and at the
  middle of the right edge (48, 52) on meshes graded towards the edges
  (cosine spacing), quadratic Q9 and quartic elements, with Richardson
  estimates: plane stress E = 1, nu = 1/3, F = 1, and nearly incompressible
  plane strain E = 250, nu = 0.4999, F = 100 (Q9/P3 mixed, locking free).
  --full adds uniform meshes and the finest quartic mesh (a few minutes).
"""
import sys
import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla


def lagrange_1d(p, s):
    """values and derivatives of 1D Lagrange polys on equispaced nodes in [-1,1]."""
    nodes = np.linspace(-1.0, 1.0, p + 1)
    N = np.ones(p + 1)
    dN = np.zeros(p + 1)
    for i in range(p + 1):
        others = [nodes[j] for j in range(p + 1) if j != i]
        den = np.prod([nodes[i] - o for o in others])
        N[i] = np.prod([s - o for o in others]) / den
        d = 0.0
        for k in range(len(others)):
            d += np.prod([s - o for m, o in enumerate(others) if m != k])
        dN[i] = d / den
    return N, dN


def geom(xi, eta):
    """bilinear map unit square -> Cook panel"""
    yb = 44.0 * xi
    yt = 44.0 + 16.0 * xi
    return 48.0 * xi, yb + eta * (yt - yb)


def solve(n, p=2, model='stress', E=1.0, nu=1.0 / 3.0, F=1.0, ngauss=None, profile=None, return_all=False,
          grading=None):
    """profile: optional traction shape g(eta), eta in [0,1] along right edge, mean 1 (default uniform)"""
    if ngauss is None:
        ngauss = p + 1
    nn = n * p + 1                       # nodes per direction
    if grading is None:
        s = np.linspace(0.0, 1.0, nn)
    else:   # element vertices graded (e.g. 'cos': refined towards both ends), p-nodes equispaced inside
        t = np.linspace(0.0, 1.0, n + 1)
        sv = 0.5 * (1 - np.cos(np.pi * t)) if grading == 'cos' else grading(t)
        s = np.concatenate([np.linspace(sv[k], sv[k + 1], p + 1)[:-1] for k in range(n)] + [[1.0]])
    XI, ETA = np.meshgrid(s, s, indexing='ij')   # node (i,j): i along xi (x), j along eta
    X, Y = geom(XI, ETA)
    X = X.ravel(); Y = Y.ravel()
    nid = lambda i, j: i * nn + j
    ndof = 2 * nn * nn

    # material
    if model == 'stress':
        c = E / (1 - nu ** 2)
        D = c * np.array([[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu) / 2]])
    else:
        lam = E * nu / ((1 + nu) * (1 - 2 * nu))
        mu = E / (2 * (1 + nu))
        D = np.array([[lam + 2 * mu, lam, 0], [lam, lam + 2 * mu, 0], [0, 0, mu]])
        if model == 'mixed':
            kappa = lam + 2.0 * mu / 3.0
            m = np.array([1.0, 1.0, 0.0])
            Dvol = kappa * np.outer(m, m)
            D = D - Dvol                 # deviatoric part (plane strain, 3D trace)

    gp, gw = np.polynomial.legendre.leggauss(ngauss)
    # reference shape functions at gauss points (tensor ordering a*(p+1)+b)
    npe = (p + 1) ** 2
    shp = []
    for a_, sa in enumerate(gp):
        for b_, sb in enumerate(gp):
            Na, dNa = lagrange_1d(p, sa)
            Nb, dNb = lagrange_1d(p, sb)
            N = np.outer(Na, Nb).ravel()
            dxi = np.outer(dNa, Nb).ravel()
            deta = np.outer(Na, dNb).ravel()
            shp.append((N, dxi, deta, gw[a_] * gw[b_]))

    rows, cols, vals = [], [], []
    for ei in range(n):
        for ej in range(n):
            conn = np.array([nid(ei * p + a, ej * p + b) for a in range(p + 1) for b in range(p + 1)])
            xe, ye = X[conn], Y[conn]
            dofs = np.empty(2 * npe, dtype=int)
            dofs[0::2] = 2 * conn; dofs[1::2] = 2 * conn + 1
            Ke = np.zeros((2 * npe, 2 * npe))
            if model == 'mixed':
                npres = p * (p + 1) // 2         # complete P_{p-1}
                G = np.zeros((npres, 2 * npe)); M = np.zeros((npres, npres))
                xc, yc = xe.mean(), ye.mean()
                hs = max(xe.max() - xe.min(), ye.max() - ye.min())
            for (N, dxi, deta, w) in shp:
                J = np.array([[dxi @ xe, dxi @ ye], [deta @ xe, deta @ ye]])
                detJ = np.linalg.det(J)
                dN = np.linalg.solve(J, np.vstack([dxi, deta]))   # rows d/dx, d/dy
                B = np.zeros((3, 2 * npe))
                B[0, 0::2] = dN[0]; B[1, 1::2] = dN[1]
                B[2, 0::2] = dN[1]; B[2, 1::2] = dN[0]
                Ke += B.T @ D @ B * detJ * w
                if model == 'mixed':
                    xg = (N @ xe - xc) / hs; yg = (N @ ye - yc) / hs
                    q = np.array([xg ** i * yg ** (k - i) for k in range(p) for i in range(k + 1)])
                    divB = B[0] + B[1]
                    G += np.outer(q, divB) * detJ * w
                    M += np.outer(q, q) * detJ * w
            if model == 'mixed':
                Ke += kappa * G.T @ np.linalg.solve(M, G)
            rows.append(np.repeat(dofs, 2 * npe)); cols.append(np.tile(dofs, 2 * npe))
            vals.append(Ke.ravel())
    K = sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                      shape=(ndof, ndof))

    # consistent traction load on right edge (xi = 1), t_y = F / 16 per unit length
    f = np.zeros(ndof)
    ty = F / 16.0
    g1, w1 = np.polynomial.legendre.leggauss(p + 4)
    for ej in range(n):
        conn = np.array([nid(nn - 1, ej * p + b) for b in range(p + 1)])
        ye = Y[conn]
        for sg, wg in zip(g1, w1):
            Nb, dNb = lagrange_1d(p, sg)
            ds = abs(dNb @ ye)           # x constant on right edge
            g = 1.0 if profile is None else profile((Nb @ ye - 44.0) / 16.0)
            f[2 * conn + 1] += Nb * ty * g * ds * wg
    assert abs(f.sum() - F) < 1e-9 * abs(F)

    fixed = np.concatenate([[2 * nid(0, j), 2 * nid(0, j) + 1] for j in range(nn)])
    free = np.setdiff1d(np.arange(ndof), fixed)
    u = np.zeros(ndof)
    Kff = K[free][:, free].tocsc()
    u[free] = spla.spsolve(Kff, f[free])
    C = nid(nn - 1, nn - 1)
    assert abs(X[C] - 48) < 1e-12 and abs(Y[C] - 60) < 1e-12
    energy = f @ u
    if return_all:
        return dict(vC=u[2 * C + 1], vMid=u[2 * nid(nn - 1, (nn - 1) // 2) + 1],
                    vMean=(f[1::2] @ u[1::2]) / F, energy=energy)
    return u[2 * C + 1], energy


def richardson(vals):
    """vals for h, h/2, h/4: observed order and extrapolated value"""
    a, b, c = vals
    r = (b - a) / (c - b)
    q = np.log2(r) if r > 0 else float('nan')
    ext = c + (c - b) / (r - 1)
    return q, ext


def table(title, p, ns, **kw):
    """vC (corner), vMid (48, 52) on successive halvings, with Richardson estimates."""
    print(f"{title}")
    hist = {"vC": [], "vMid": []}
    for n in ns:
        r = solve(n, p=p, return_all=True, **kw)
        line = f"  n = {n:3d}"
        for key in hist:
            hist[key].append(r[key])
            line += f"  {key} = {r[key]:.5f}"
            if len(hist[key]) >= 3:
                q, ext = richardson(hist[key][-3:])
                line += f" (order {q:.2f}, extrapolated {ext:.5f})"
        print(line, flush=True)


if __name__ == "__main__":
    full = "--full" in sys.argv
    stress = dict(model="stress", E=1.0, nu=1.0 / 3.0, F=1.0)
    incompressible = dict(model="mixed", E=250.0, nu=0.4999, F=100.0)
    if full:
        table("Q4 (2x2 Gauss), plane stress, uniform meshes", 1, [8, 16, 32, 64], **stress)
        table("Q9, plane stress, uniform meshes", 2, [8, 16, 32, 64], **stress)
    table("Q9, plane stress, graded meshes", 2, [8, 16, 32, 64], grading="cos", **stress)
    quartic = [8, 16, 32] + ([64] if full else [])
    table("Q25 (quartic), plane stress, graded meshes", 4, quartic, grading="cos", **stress)
    table("Q9/P3 mixed, plane strain nu = 0.4999, graded meshes", 2, [8, 16, 32, 64], grading="cos", **incompressible)
    table("Q25/P3 mixed (quartic), same, graded meshes", 4, [8, 16, 32], grading="cos", **incompressible)
