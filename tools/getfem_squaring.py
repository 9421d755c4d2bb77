#!/usr/bin/env python3
"""The paper's default squaring case solved by GetFEM: a reference independent of tubeform and CalculiX.

    OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 /usr/bin/python3 tools/getfem_squaring.py \
        [--nt 4] [--ntheta 90] [--du 0.04] [--r_aug 1e5] [--mu 0.05] [--stroke 4.2] [--csv OUT.csv]

Needs GetFEM's Python interface (Debian: apt-get install python3-getfem; 5.4.2 tested).

What it models (options/squaring.opts with the aluminum of options/materials/aluminum.opts):
- the quarter (x >= 0, y >= 0) of the tube Ro 17.5 mm, t 1.5 mm, plane strain; nt x ntheta 9-node
  quadrilaterals (Q2, isoparametric: their edges follow the circles), 3 x 3 Gauss points, with a
  continuous Q1 pressure (mixed u-p: the plastic flow is isochoric);
- the material: GetFEM's finite strain J2 plasticity of Simo and Miehe (multiplicative F = Fe Fp,
  Hencky elasticity on the elastic left Cauchy-Green tensor, exponential-map return), E 75000 MPa,
  nu 0.34, Ludwik's flow curve sigma_y = 165.3 + 673.5 ep^0.927 MPa (isotropic hardening); the plastic
  multiplier is an internal variable at every Gauss point (statically condensed: a pointwise return
  mapping solved inside the global Newton iteration);
- the die: the rigid 90-degree V of docs/dies.md ("The V-die of the options"): flanks x + y = Ro sqrt 2,
  the apex rounded by a 3 mm arc; friction Coulomb mu 0.05;
- contact: GetFEM's integral large-sliding contact brick (raytracing to the die's signed distance),
  enforced with a Lagrange multiplier (the contact traction on the outer surface, Q1) by the augmented
  Lagrangian of Alart and Curnier: exact non-penetration and Coulomb's law at the solution, so the
  augmentation parameter --r_aug should change the iterations only (not yet shown by a full run);
- the loading: in the frame of the upper die. The die stays put and the tube's symmetry plane y = 0
  moves up by the stroke U (the lower die is the mirror image: the plane's normal displacement is U);
  x = 0 is a symmetry plane. Friction's slip is then the surface's own displacement increment, which is
  what the brick takes as the relative slip against a fixed rigid obstacle. Quasi-static, U in steps of
  --du (a step that does not converge is halved, up to 5 times).

Output: per step the stroke U, the punch load on the whole tube (2 x the quarter's vertical force,
tubeform's `load`, docs/output.md), from the contact multiplier and, as a check, from the reaction of
the symmetry plane y = 0; C/t as tubeform measures it loaded (docs/theory.md, "Metrics": the largest
gap between the flank line and the outer surface over the span of the flank's contact, from the
fillet's end when the fillet touches); x_max, y_max (half extents). A node touches where its gap to the
die is below --touch_tol (mm).

The convergence ladder meant for a reference: meshes 4 x 90 -> 8 x 180 (or one direction at a time,
8 x 90 and 4 x 180), steps 0.04 -> 0.02 mm, r_aug 1e5 -> 1e6; the reference the finest, its uncertainty
the largest change between neighbouring levels.

What it reached (2026-11-29, GetFEM 5.4.2, one core of a shared machine) -- NOT yet a reference:
- 4 x 90, --du 0.02 --r_aug 1e4: converged to U = 1.0 mm (run stopped there): load 70.56, 90.12, 96.23,
  98.37, 100.37, 103.77 N/mm at U = 0.1, 0.2, 0.4, 0.6, 0.8, 1.0; C/t 0.0026 at 1.0. 4 x 90 with
  --du 0.04 --r_aug 1e4 stalls at U = 0.16 mm.
- 4 x 90, --du 0.04 --r_aug 1e5: 90.08, 96.30, 98.47, 100.35, 103.73, 107.14 at U = 0.2, 0.4, 0.6, 0.8,
  1.0, 1.2 (C/t 0.0027, 0.0077 at 1.0, 1.2), then no convergence at U = 1.4 mm with the step halved 5 times (4 x 180: at U = 0.2 mm).
- 4 x 90, --du 0.02 --r_aug 1e5 (the furthest): 90.15, 96.31, 98.48, 100.37, 103.75, 107.15, 110.81,
  123.85, 163.78 N/mm at U = 0.2, 0.4, 0.6, 0.8, 1.0, 1.2, 1.4, 2.0, 3.0 (C/t 0.0027, 0.0329, 0.0812 at
  1, 2, 3 mm), then no convergence at U = 3.1 mm with the step halved 5 times. Against the --du 0.04 run:
  within 0.03 % to 1.2 mm; against --du 0.02 --r_aug 1e4: within 0.08 % to 1.0 mm.
- 8 x 90 died at the first steps on a cell turned inside out by a Newton iterate (now a failed step, halved);
  8 x 180 and 4 x 180 did not pass U = 0.4 mm in 10 minutes (the first yield steps need many halvings).
Against CalculiX (tests/reference/calculix/default.csv) and tubeform's accurate preset the 4 x 90 load is
1.0-1.3 % lower from U = 0.4 to 1.2 mm (103.75 against 104.93 and 104.70 at U = 1 mm), 0.9 % at 2 mm,
-0.15 % / +0.28 % at 3 mm: the mesh's share of that is not measured (no finer mesh got through). What
fails: Newton stalls at some contact transitions (U 0.16, 1.4, 3.1 mm) with every step halving tried; a
remedy to try is a smaller release distance, another --r_aug, or more halvings.
"""
import argparse
import csv
import math
import sys
import time

import numpy as np

import getfem as gf

# Region numbers of the quarter annulus's edges.
INNER, OUTER, BOTTOM, LEFT = 1, 2, 3, 4
NOISY = False


def parse():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--ro", type=float, default=17.5, help="outer radius (mm)")
    p.add_argument("--t", type=float, default=1.5, help="wall thickness (mm)")
    p.add_argument("--nt", type=int, default=4, help="Q2 cells through the wall")
    p.add_argument("--ntheta", type=int, default=90, help="Q2 cells around the quarter")
    p.add_argument("--E", type=float, default=75000.0)
    p.add_argument("--nu", type=float, default=0.34)
    p.add_argument("--sy", type=float, default=165.3)
    p.add_argument("--K", type=float, default=673.5)
    p.add_argument("--n", type=float, default=0.927)
    p.add_argument("--mu", type=float, default=0.05, help="Coulomb friction coefficient")
    p.add_argument("--r_apex", type=float, default=3.0, help="apex fillet radius (mm)")
    p.add_argument("--stroke", type=float, default=4.2, help="final stroke U (mm)")
    p.add_argument("--du", type=float, default=0.04, help="stroke step (mm)")
    p.add_argument("--r_aug", type=float, default=1e5,
                   help="augmentation parameter (MPa/mm; 1e4 stalled at U = 0.16 mm with --du 0.04)")
    p.add_argument("--release", type=float, default=0.5, help="contact release distance (mm)")
    p.add_argument("--tol", type=float, default=1e-7, help="Newton residual (relative to the load scale)")
    p.add_argument("--touch_tol", type=float, default=1e-3, help="gap under which a node touches (mm)")
    p.add_argument("--report", default="1,2,3,4.2", help="strokes to print (mm)")
    p.add_argument("--csv", default="", help="write every step here")
    p.add_argument("--lsearch", default="simplest",
                   help="GetFEM's line search (simplest: backtracking; GetFEM's 'default' stalls here)")
    p.add_argument("--noisy", action="store_true", help="print Newton's iterations")
    p.add_argument("--pure", action="store_true", help="no mixed pressure (displacement only)")
    return p.parse_args()


def build_mesh(a):
    m = gf.Mesh("import", "structured",
                'GT="GT_QK(2,2)";ORG=[0,0];SIZES=[1,1];NSUBDIV=[%d,%d]' % (a.nt, a.ntheta))
    faces = m.outer_faces()
    nrm = m.normal_of_faces(faces)
    m.set_region(INNER, faces[:, nrm[0] < -0.5])
    m.set_region(OUTER, faces[:, nrm[0] > 0.5])
    m.set_region(BOTTOM, faces[:, nrm[1] < -0.5])
    m.set_region(LEFT, faces[:, nrm[1] > 0.5])
    P = m.pts()
    r = a.ro - a.t + a.t * P[0]
    th = 0.5 * math.pi * P[1]
    m.set_pts(np.vstack([r * np.cos(th), r * np.sin(th)]))
    return m


def die_geometry(a):
    """The flank x + y = h (h = Ro sqrt 2) and the fillet's centre height yc on the axis."""
    h = a.ro * math.sqrt(2.0)
    yc = h - a.r_apex * math.sqrt(2.0)
    return h, yc


def die_expr(a):
    """Signed distance to the fixed upper die (positive in the cavity), GetFEM's language, x >= 0.

    In the frame of the fillet's centre turned by 45 degrees, a = (x + y - yc)/sqrt 2 (towards the
    flank), b = (y - yc - x)/sqrt 2: the distance to the cavity shrunk by r_apex is a beside the cone
    b > 0 and sqrt(a^2 + b^2) in it, written a + c^2 / (a + sqrt(a^2 + c^2)), c = pos_part(b), to stay
    differentiable (GetFEM cannot differentiate Heaviside)."""
    _, yc = die_geometry(a)
    A = "((x+y-%.17g)/sqrt(2))" % yc
    C = "pos_part((y-%.17g-x)/sqrt(2))" % yc
    return "%.17g-(%s+sqr(%s)/(%s+sqrt(sqr(%s)+sqr(%s))+1e-30))" % (a.r_apex, A, C, A, A, C)


def die_gap(a, x, y):
    _, yc = die_geometry(a)
    cone = (y - yc - x) > 0
    core = np.where(cone, np.hypot(x, y - yc), (x + y - yc) / math.sqrt(2.0))
    return a.r_apex - core


def hardening(a):
    """Ludwik's law in GetFEM's Frobenius norms: |dev sigma| = sqrt(2/3) sigma_y, |eps_p| = sqrt(3/2) ep."""
    c0 = math.sqrt(2.0 / 3.0) * a.sy
    c1 = math.sqrt(2.0 / 3.0) * a.K * (2.0 / 3.0) ** (a.n / 2.0)
    eps = 1e-12  # keeps t^(n-1) finite at first yield
    # pos_part: a Newton iterate may take the plastic strain below 0 on its way (pow would give NaN)
    gf.asm_define_function("ludwik", 1, "%.17g+%.17g*pow(pos_part(t)+%g,%.17g)" % (c0, c1, eps, a.n),
                           "%.17g*pow(pos_part(t)+%g,%.17g)" % (c1 * a.n, eps, a.n - 1.0))


def hencky_log(b3):
    """log of the plane strain elastic left Cauchy-Green tensor b3 (3 x 3, b13 = b23 = 0) in closed form.

    GetFEM 5.4.2's Logm has a wrong derivative (its tangent test fails by a factor ~1e3), so Newton
    stalls. The in-plane block B (eigenvalues m +- R) has log B = ln(det B)/2 I + atanh(x)/(x m) (B - m I),
    x = R/m; atanh(x)/x = 1 + x^2/3 + x^4/5 + ... is summed to x^10 (b is the elastic part: x < 0.05, the
    series' remainder below 1e-16)."""
    pb = "[[1,0,0],[0,1,0]]"  # 3 x 2 (GetFEM's nested lists are columns): the in-plane embedding
    B = "(%s'*%s*%s)" % (pb, b3, pb)
    m = "(Trace(%s)/2)" % B
    dev = "(%s-%s*Id(2))" % (B, m)
    q = "((%s:%s)/(2*sqr(%s)))" % (dev, dev, m)
    f = "(1+%s*(1/3+%s*(1/5+%s*(1/7+%s*(1/9+%s/11)))))" % (q, q, q, q, q)
    L2 = "(%s/%s*%s+(0.5*log(Det(%s)))*Id(2))" % (f, m, dev, B)
    return "(%s*%s*%s'+log(%s(3,3))*[[0,0,0],[0,0,0],[0,0,1]])" % (pb, L2, pb, b3)


def simo_miehe(a, mixed):
    """GetFEM's Simo-Miehe plane strain expressions (src/getfem_plasticity.cc), ksi pointwise.

    Returns (weak form, accumulated plastic strain, new invCp (4 components), von Mises)."""
    G = a.E / (2 * (1 + a.nu))
    K = a.E / (3 * (1 - 2 * a.nu))
    F = "(Id(2)+Grad_u)"
    J = "Det" + F
    P = "(-p*%s)" % J if mixed else "(%.17g*log(%s))" % (K, J)
    invcp0 = ("([[[1,0,0],[0,0,0],[0,0,0]],[[0,0,0],[0,1,0],[0,0,0]],"
              "[[0,0,0],[0,0,0],[0,0,1]],[[0,1,0],[1,0,0],[0,0,0]]].invCp0)")
    F3 = "(Id(3)+[[1,0,0],[0,1,0]]*Grad_u*[[1,0,0],[0,1,0]]')"
    dlb3 = "(Deviator(%s))" % hencky_log("(%s*%s*%s')" % (F3, invcp0, F3))
    dlb2 = ("([[[[1,0],[0,0]],[[0,1],[0,0]],[[0,0],[0,0]]],[[[0,0],[1,0]],[[0,0],[0,1]],[[0,0],[0,0]]],"
            "[[[0,0],[0,0]],[[0,0],[0,0]],[[0,0],[0,0]]]]:%s)" % dlb3)
    devtau = "(%.17g*pow(%s,-2/3)*(1-2*ksi)*%s)" % (G, J, dlb2)
    tau = "(%s*Id(2)+%s)" % (P, devtau)
    plast = "(gamma0+ksi*Norm%s)" % dlb3
    devsig = "(%.17g*pow(%s,-5/3)*(1-2*ksi)*%s)" % (G, J, dlb3)
    devsigtr = "(%.17g*pow(%s,-5/3)*%s)" % (G, J, dlb3)
    expr = "%s:(Grad_Test_u*Inv%s)" % (tau, F)
    if mixed:
        expr += "+(p/%.17g+log(%s)/%s)*Test_p" % (K, J, J)
    expr += "+(Norm%s-min(ludwik%s,Norm%s+1e-12*ksi))*Test_ksi" % (devsig, plast, devsigtr)
    newcp = ("[[[1,0,0,0.0],[0,0,0,0.5],[0,0,0,0]],[[0,0,0,0.5],[0,1,0,0.0],[0,0,0,0]],"
             "[[0,0,0,0.0],[0,0,0,0.0],[0,0,1,0]]]"
             ":((Inv{F3}*Expm(-ksi*{d})*{F3})*{c}*(Inv{F3}*Expm(-ksi*{d})*{F3})')").format(F3=F3, d=dlb3, c=invcp0)
    vm = "1.2247448713915889407*Norm(%s)" % devsig
    return expr, plast, newcp, vm


class Squaring:
    def __init__(self, a):
        self.a = a
        self.mesh = build_mesh(a)
        m = self.mesh
        mfN = gf.MeshFem(m, 2)
        mfN.set_classical_fem(2)
        xl = mfN.basic_dof_on_region(LEFT)[0::2]  # x = 0: u_x = 0 (symmetry)
        self.mfu = gf.MeshFem("partial", mfN, np.setdiff1d(np.arange(mfN.nb_basic_dof()), xl))
        self.mfN = mfN
        self.mim = gf.MeshIm(m, 5)
        mimd1 = gf.MeshImData(self.mim, -1, [1])
        mimd4 = gf.MeshImData(self.mim, -1, [4])
        md = gf.Model("real")
        self.md = md
        md.add_fem_variable("u", self.mfu)
        mixed = not a.pure
        if mixed:
            mfp = gf.MeshFem(m, 1)
            mfp.set_classical_fem(1)
            md.add_fem_variable("p", mfp)
        md.add_internal_im_variable("ksi", mimd1)  # condensed: a return mapping at each Gauss point
        md.add_im_data("gamma0", mimd1)
        md.add_im_data("invCp0", mimd4)
        md.set_variable("invCp0", np.tile([1.0, 1.0, 1.0, 0.0], mimd4.nbpts()))
        self._mimd = {"gamma0": mimd1, "invCp0": mimd4}
        hardening(a)
        expr, self.plast, self.newcp, self.vm = simo_miehe(a, mixed)
        md.add_nonlinear_term(self.mim, expr)
        # y = 0: the normal displacement u . (0,-1) = -U (the tube's plane moves up to the fixed die).
        md.add_initialized_data("ubot", [0.0])
        self.ibot = md.add_normal_Dirichlet_condition_with_multipliers(self.mim, "u", 1, BOTTOM, "ubot")
        self.botmult = md.mult_varname_Dirichlet(self.ibot)
        # contact with the die
        mfl = gf.MeshFem(m, 2)
        mfl.set_classical_fem(1)
        md.add_filtered_fem_variable("lam", mfl, OUTER)
        md.add_initialized_data("r_aug", [a.r_aug])
        md.add_initialized_data("fr", [a.mu])
        md.add_initialized_data("alpha", [1.0])
        md.add_fem_data("w", self.mfu)
        ib = md.add_integral_large_sliding_contact_brick_raytracing("r_aug", a.release, "fr", "alpha", 0)
        md.add_slave_contact_boundary_to_large_sliding_contact_brick(ib, self.mim, OUTER, "u", "lam", "w")
        md.add_rigid_obstacle_to_large_sliding_contact_brick(ib, die_expr(a), 2)
        self.outer_dofs = self.outer_nodes()
        self.vars = ("u", "lam") + (("p",) if mixed else ())
        self.last, self.last_back, self.Uconv, self.pending = None, None, 0.0, None

    def outer_nodes(self):
        """The outer surface's x-dof numbers of mfN in order of the angle from the x axis."""
        d = self.mfN.basic_dof_on_region(OUTER)[0::2]
        xy = self.mfN.basic_dof_nodes(d)
        return d[np.argsort(np.arctan2(xy[1], xy[0]))]

    def load(self):
        """Punch load on the whole tube: 2 x the quarter's vertical contact force (N/mm)."""
        fy_c = gf.asm("generic", self.mim, 0, "lam(2)", OUTER, self.md)
        fy_b = gf.asm("generic", self.mim, 0, self.botmult, BOTTOM, self.md)
        return -2.0 * fy_c, 2.0 * fy_b

    def shape(self, U):
        a = self.a
        u = self.md.variable("u")
        full = self.mfu_to_full(u)
        d = self.outer_dofs
        X = self.mfN.basic_dof_nodes(d)
        x = X[0] + full[d]
        y = X[1] + full[d + 1]
        gap = die_gap(a, x, y)
        h, yc = die_geometry(a)
        tx, ty = a.r_apex / math.sqrt(2.0), yc + a.r_apex / math.sqrt(2.0)
        s = ((x - tx) - (y - ty)) / math.sqrt(2.0)
        touch = gap < a.touch_tol
        flank = touch & (s >= 0)
        apex = touch & (s < 0)
        c = 0.0
        if flank.any():
            smin, smax = s[flank].min(), s[flank].max()
            if apex.any():
                smin = min(smin, 0.0)
            inside = (s >= smin) & (s <= smax)
            c = max(0.0, ((h - x - y) / math.sqrt(2.0))[inside].max())
        return c / a.t, x.max(), y.max() - U, int(touch.sum()), int(apex.sum())

    def mfu_to_full(self, u):
        return self.mfu.extension_matrix().mult(u)

    def update_state(self):
        md = self.md
        g = md.interpolation(self.plast, self.mimd("gamma0"))
        c = md.interpolation(self.newcp, self.mimd("invCp0"))
        md.set_variable("gamma0", g)
        md.set_variable("invCp0", c)
        md.set_variable("ksi", np.zeros(md.variable("ksi").size))

    def predict(self, U):
        """Start Newton from the last two converged states' secant (u, p, lam), scaled to the step."""
        names = [n for n in ("u", "p", "lam") if n in self.vars]
        now = {n: self.md.variable(n).copy() for n in names}
        if self.last is not None and self.last[0] != self.Uconv:
            f = (U - self.Uconv) / (self.Uconv - self.last[0])
            for n in names:
                self.md.set_variable(n, now[n] + f * (now[n] - self.last[1][n]))
        self.pending = (self.Uconv, now)

    def accept(self, U):
        self.last = self.pending
        self.Uconv = U

    def mimd(self, name):
        return self._mimd[name]


def solve_step(s, U, w):
    """Newton from the last converged state to the stroke U; True if it converged."""
    md = s.md
    md.set_variable("ubot", [-U])
    md.set_variable("w", w)
    ls = ("lsearch", s.a.lsearch) if s.a.lsearch != "simplest" else \
        ("lsearch", "simplest", "alpha max ratio", 1.5, "alpha min", 0.2, "alpha mult", 0.6)
    try:
        it, conv = md.solve(*(("noisy",) if NOISY else ()), "max_iter", 25, "max_res", s.a.tol * s.scale,
                            "lsolver", "mumps", *ls)
    except RuntimeError as e:  # an iterate that turned a cell inside out: a failed step, halved
        print("getfem_squaring: U = %g: %s" % (U, str(e).strip().splitlines()[-1]), flush=True)
        return False, 25
    return bool(conv) and np.all(np.isfinite(md.variable("u"))), it


def run(a):
    s = Squaring(a)
    s.scale = a.sy * a.t  # a force per unit length (N/mm) the residual is measured against
    print("getfem_squaring: %d x %d Q2, dofs %d, du %g, r_aug %g, mu %g, %s"
          % (a.nt, a.ntheta, s.md.nbdof(), a.du, a.r_aug, a.mu, "u" if a.pure else "u-p"), flush=True)
    report = [float(v) for v in a.report.split(",") if v]
    nsteps = int(round(a.stroke / a.du))
    rows, t0, U, iters = [], time.time(), 0.0, 0
    for k in range(1, nsteps + 1):
        target = min(k * a.du, a.stroke)
        parts, done = 1, False
        while not done:
            back = s.md.from_variables()
            s.last_back = s.last
            w = s.md.variable("u").copy()
            ok, Uc = True, U
            for j in range(1, parts + 1):
                Uj = U + (target - U) * j / parts
                s.predict(Uj)
                conv, it = solve_step(s, Uj, w)
                iters += it
                if not conv:
                    ok = False
                    break
                s.update_state()
                s.accept(Uj)
                w = s.md.variable("u").copy()
            if ok:
                done = True
            else:
                s.md.to_variables(back)
                s.last = s.last_back
                parts *= 2
                if parts > 32:
                    sys.exit("getfem_squaring: no convergence at U = %g mm" % target)
        U = target
        lc, lb = s.load()
        c, xm, ym, nc, na = s.shape(U)
        rows.append((U, lc, lb, c, xm, ym, nc, na))
        if any(abs(U - r) < 1e-9 for r in report) or k % 10 == 0:
            print("U %.4f load %.4f (plane %.4f) C/t %.4f x_max %.4f y_max %.4f touching %d apex %d  "
                  "[%d steps, %d its, %.0f s]" % (U, lc, lb, c, xm, ym, nc, na, k, iters, time.time() - t0),
                  flush=True)
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            wr = csv.writer(f)
            f.write("# getfem_squaring %s\n" % " ".join(sys.argv[1:]))
            wr.writerow(["stroke", "load", "load_plane", "c_over_t", "x_max", "y_max", "n_touch", "n_apex"])
            wr.writerows(rows)
    return rows


def main():
    global NOISY
    a = parse()
    NOISY = a.noisy
    run(a)


if __name__ == "__main__":
    main()
