"""The material library (options/materials/*.opts, -material NAME): every
file reaches the constitutive law with the constants it states.

Each file is read here by this test's own parser and run in homogeneous
plane-strain tension (options/tension.opts, -material NAME) with the paper's
increments, so that r1 ends the first increment at the yield onset, and with
-drift_correction, which puts every plastic point's sbar on sigma_y(ep):
1. The onset: sigma_xx of the increment r1 ended (the last elastic one) against sigma_y0 / sqrt(1 - nu +
   nu^2) (plane strain, sigma_zz = nu sigma_xx, sigma_yy = 0), and its ratio to
   the log strain in the first increment against E / (1 - nu^2). Within 3e-3: the closed forms are
   small-strain ones, and the run's Cauchy stress and logarithmic strain differ
   from them by the order of the yield strain (sigma_y0 / E <= 4e-3 here);
   measured below 2e-3 on every file. A constant off by 1 % fails.
2. The flow curve: at every plastic increment sbar against the file's law,
   Ludwik sy + K ep^n, Swift K (ep0 + ep)^n with ep0 = (sy / K)^(1/n), or the
   table interpolated linearly, to 1e-9 (the correction is exact to
   round-off, ~1e-15): a wrong K, n, law or sy fails by orders of magnitude
   more. A file with backstresses, run with -hardening chaboche: the shifted
   stress sbar(sigma' - alpha) on the remainder curve(p) - sum C/gamma (1 -
   exp(-gamma p)), to 1e-9 (the correction acts on the shifted surface).
3. Precedence: an option given after the name overrides the file's value
   (-material dc04 -material_sy 200: the Swift curve through 200).
4. The paper's two materials in their files are the paper's Table 1 (Huang
   2008; its numbers written out here, not read from the code or the files),
   so that -material aluminum, the default, is the paper's; and the table
   docs/scenes.md shows ("The paper's squaring case") is the same, so the user
   doc cannot drift from it. Exact: the values are typed constants.
"""
import glob
import math
import os
import re

import h5py
import numpy as np

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
k = Checks("materials")


def parse(path):
    """Options of a material file (comments dropped), as this test reads them."""
    words = " ".join(l.split("#", 1)[0] for l in open(path)).split()
    return {w: words[i + 1] for i, w in enumerate(words) if w.startswith("-material_")}


def law(o, sy_override=None):
    if o["-material_law"] == "table":
        t = np.array([float(v) for v in o["-material_table"].split(",")])
        return lambda ep: float(np.interp(ep, t[0::2], t[1::2]))
    sy, kk, n = float(sy_override or o["-material_sy"]), float(o["-material_k"]), float(o["-material_n"])
    if o["-material_law"] == "ludwik":
        return lambda ep: sy + kk * ep ** n
    ep0 = (sy / kk) ** (1 / n)
    return lambda ep: kk * (ep0 + ep) ** n


def tension(extra):
    f = out("material.h5")
    run(tf, mpirun, 1, ["-options_file", f"{src}/options/tension.opts", "-tension_strain", 0.05, "-increments", 50,
                        "-rmin_deps", 0.5, "-equilibrium_tol", 0, "-drift_correction", "-output", f] + extra)
    with h5py.File(f, "r") as h:
        return (h["/history"]["stroke"][:], h["/history"]["load"][:], h["/cell_fields/von_mises_c"][:].mean(axis=1),
                h["/cell_fields/eps_p_c"][:].mean(axis=1))


files = sorted(glob.glob(os.path.join(src, "options", "materials", "*.opts")))
k.check(len(files) >= 7, f"{len(files)} materials in the library (at least the paper's two and five others)")
for path in files:
    name, o = os.path.basename(path)[:-5], parse(path)
    E, nu, sy = float(o["-material_e"]), float(o["-material_nu"]), float(o["-material_sy"])
    stroke, load, vm, ep = tension(["-material", name])
    onset, last = sy / math.sqrt(1 - nu + nu * nu), np.flatnonzero(ep == 0)[-1]  # the increment r1 ended
    modulus = load[1] / math.log1p(stroke[1]) / (E / (1 - nu * nu))
    k.check(abs(load[last] / onset - 1) < 3e-3 and abs(modulus - 1) < 3e-3,
            f"{name}: yield onset sigma_xx {load[last]:.2f} against {onset:.2f} MPa ({load[last] / onset - 1:+.1e}), "
            f"modulus ratio {modulus:.5f} (both within 3e-3)")
    m = ep > 0
    curve = law(o)
    err = max(abs(v / curve(x) - 1) for v, x in zip(vm[m], ep[m]))
    k.check(m.sum() > 10 and err < 1e-9,
            f"{name}: sbar on the file's {o['-material_law']} curve to {err:.1e} (1e-9), ep(end) {ep[-1]:.4f}")
    if "-material_kinematic" in o:
        # Its backstresses: the shifted stress sigma' - alpha on the isotropic part, the remainder
        # R(p) = curve(p) - sum C/gamma (1 - exp(-gamma p)) (docs/theory.md "Kinematic hardening"), to 1e-9 as above.
        f = out("material_kinematic.h5")
        run(tf, mpirun, 1, ["-options_file", f"{src}/options/tension.opts", "-tension_strain", 0.05, "-increments", 50,
                            "-rmin_deps", 0.5, "-equilibrium_tol", 0, "-drift_correction", "-output", f, "-material",
                            name, "-hardening", "chaboche"])
        with h5py.File(f, "r") as h:
            c = {x: h[f"/cell_fields/{x}_c"][:].mean(axis=1) for x in ("sigma_xx", "sigma_yy", "sigma_zz", "sigma_xy",
                                                                      "backstress_xx", "backstress_yy", "backstress_zz",
                                                                      "backstress_xy", "eps_p")}
        mean = (c["sigma_xx"] + c["sigma_yy"] + c["sigma_zz"]) / 3
        xi = [c[f"sigma_{x}"] - (mean if x != "xy" else 0) - c[f"backstress_{x}"] for x in ("xx", "yy", "zz", "xy")]
        shifted = np.sqrt(1.5 * (xi[0] ** 2 + xi[1] ** 2 + xi[2] ** 2 + 2 * xi[3] ** 2))
        pairs = [float(v) for v in o["-material_kinematic"].split(",")]
        rest = lambda p: curve(p) - sum(cc / g * (1 - math.exp(-g * p)) if g > 0 else cc * p
                                        for cc, g in zip(pairs[0::2], pairs[1::2]))
        m = c["eps_p"] > 0
        err = max(abs(v / rest(x) - 1) for v, x in zip(shifted[m], c["eps_p"][m]))
        k.check(m.sum() > 10 and err < 1e-9,
                f"{name} -hardening chaboche (its backstresses {o['-material_kinematic']}): the shifted stress on the "
                f"isotropic remainder to {err:.1e} (1e-9)")

stroke, load, vm, ep = tension(["-material", "dc04", "-material_sy", 200])
m, curve = ep > 0, law(parse(os.path.join(src, "options", "materials", "dc04.opts")), 200)
err = max(abs(v / curve(x) - 1) for v, x in zip(vm[m], ep[m]))
k.check(err < 1e-9, f"-material dc04 -material_sy 200: the Swift curve through 200 MPa, to {err:.1e}")

# The paper's Table 1 (Huang 2008): E (MPa), nu, initial yield stress (MPa), K (MPa), n; hardening read as Ludwik's law.
TABLE1 = {"aluminum": (75000, 0.34, 165.3, 673.5, 0.927), "copper": (112000, 0.34, 445.0, 3628.6, 0.987)}
scenes = open(os.path.join(src, "docs", "scenes.md")).read()
for name, paper in TABLE1.items():
    o = parse(os.path.join(src, "options", "materials", f"{name}.opts"))
    mine = [float(o[f"-material_{c}"]) for c in ("e", "nu", "sy", "k", "n")]
    k.check(mine == list(paper) and o["-material_law"] == "ludwik",
            f"{name}.opts is the paper's Table 1 ({', '.join(map(str, paper))}; Ludwik): {mine}")
    row = re.search(rf"^\| {name} \| (\S+) \| (\S+) \| (\S+) \| (\S+) \| (\S+) \|", scenes, re.M)
    doc = [float(c) for c in row.groups()] if row else None
    k.check(doc == list(paper), f"docs/scenes.md's Table 1 row for {name} is the paper's: {doc}")
k.done()
