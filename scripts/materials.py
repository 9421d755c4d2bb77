#!/usr/bin/python3
"""The material library (options/materials/*.opts) at a glance, and the fit behind its Swift laws.

    /usr/bin/python3 scripts/materials.py
        Each material's constants, and its uniaxial tensile test as the flow
        curve implies it: the uniform strain (Considere: d sigma / d eps = sigma,
        necking) and the engineering tensile strength Rm there, with the
        elastic strain neglected. A file's comment names the standard or
        handbook values it stands for; this table shows it meets them.

    /usr/bin/python3 scripts/materials.py --swift SY RM N
        The Swift law sigma = K (ep0 + ep)^N with sigma(0) = SY whose
        Considere necking gives the engineering tensile strength RM: the K a
        material file takes (ep0 = (SY / K)^(1 / N) follows from SY).

    /usr/bin/python3 scripts/materials.py --uvc E FY QINF B DINF A C1 G1 [C2 G2 ...]
        A material file's lines for an Updated Voce-Chaboche calibration
        (Hartloper, de Castro e Sousa, Lignos, J. Struct. Eng.,
        doi:10.1061/(ASCE)ST.1943-541X.0002964): the monotonic curve
        fy + QINF (1 - exp(-B p)) - DINF (1 - exp(-A p)) + sum C/G (1 - exp(-G p))
        tabulated at 100 plastic strains from 0 to 2 (geometric from 1e-4:
        within 0.1 MPa of the curve between points), and the backstresses; with
        -hardening chaboche the isotropic part is the Voce terms again
        (docs/theory.md, "Kinematic hardening").
"""
import glob
import math
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def read_opts(path):
    """The options of one file as a dict (comments dropped)."""
    opts = {}
    for line in open(path):
        words = line.split("#", 1)[0].split()
        for i, w in enumerate(words):
            if w.startswith("-") and not _number(w):
                opts[w] = words[i + 1] if i + 1 < len(words) and not words[i + 1].startswith("-material") else ""
    return opts


def _number(w):
    try:
        float(w)
        return True
    except ValueError:
        return False


def flow(law, sy, k, n):
    if law == "ludwik":
        return lambda e: sy + k * e ** n, lambda e: (n * k * e ** (n - 1) if e > 0 else math.inf)
    ep0 = (sy / k) ** (1 / n)
    return lambda e: k * (ep0 + e) ** n, lambda e: n * k * (ep0 + e) ** (n - 1)


def considere(law, sy, k, n):
    """Uniform (true plastic) strain and engineering tensile strength, or None where the curve never necks."""
    sig, slope = flow(law, sy, k, n)
    g = lambda e: slope(e) - sig(e)
    lo, hi = 1e-9, 5.0
    if g(hi) > 0:
        return None
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if g(mid) > 0 else (lo, mid)
    e = 0.5 * (lo + hi)
    return e, sig(e) * math.exp(-e)


def swift_k(sy, rm, n):
    """K of the Swift law through sigma(0) = sy whose necking stress gives rm (fixed point on ep0)."""
    ep0 = 0.0
    for _ in range(200):
        k = rm * math.exp(n - ep0) / n ** n
        ep0 = (sy / k) ** (1 / n)
    return k


UVC_POINTS = 100  # -material_table takes at most 100 (ep, sigma) pairs
UVC_FIRST, UVC_LAST = 1e-4, 2.0  # plastic strains of the first point past 0 and of the last (the check's p = 2)


def uvc_lines(e, fy, q, b, d, a, *back):
    """-material_* lines of a UVC calibration (E and stresses in MPa)."""
    pairs = list(zip(back[::2], back[1::2]))

    def curve(p):
        return fy + q * (1 - math.exp(-b * p)) - d * (1 - math.exp(-a * p)) + sum(
            c / g * (1 - math.exp(-g * p)) for c, g in pairs)

    ps = [0.0] + [UVC_FIRST * (UVC_LAST / UVC_FIRST) ** (k / (UVC_POINTS - 2)) for k in range(UVC_POINTS - 1)]
    table = ",".join(f"{p:.6g},{curve(p):.6g}" for p in ps)
    kin = ",".join(f"{v:g}" for cg in pairs for v in cg)
    return [f"-material_law table", f"-material_e {e:g}", f"-material_sy {fy:g}", f"-material_table {table}",
            f"-material_kinematic {kin}"]


def main():
    if len(sys.argv) >= 10 and sys.argv[1] == "--uvc" and len(sys.argv) % 2 == 0:
        print("\n".join(uvc_lines(*map(float, sys.argv[2:]))))
        return
    if len(sys.argv) == 5 and sys.argv[1] == "--swift":
        sy, rm, n = map(float, sys.argv[2:])
        k = swift_k(sy, rm, n)
        print(f"K = {k:.1f} MPa (ep0 = {(sy / k) ** (1 / n):.5f}; check: Rm = {considere('swift', sy, k, n)[1]:.1f})")
        return
    print("| material | law | E (MPa) | nu | sy (MPa) | K (MPa) | n | density (t/mm^3) | uniform strain | Rm (MPa) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for path in sorted(glob.glob(os.path.join(ROOT, "options", "materials", "*.opts"))):
        o = read_opts(path)
        law = o.get("-material_law", "ludwik")
        if law == "table":
            print(f"| {os.path.basename(path)[:-5]} | table | {o['-material_e']} | {o['-material_nu']} | "
                  f"{o['-material_sy']} | - | - | {o['-material_density']} | - | - |")
            continue
        sy, k, n = (float(o[key]) for key in ("-material_sy", "-material_k", "-material_n"))
        neck = considere(law, sy, k, n) if law in ("ludwik", "swift") else None
        tail = f"{neck[0]:.3f} | {neck[1]:.0f}" if neck and n < 1 else "- (linear: no necking) | -"
        print(f"| {os.path.basename(path)[:-5]} | {law} | {o['-material_e']} | {o['-material_nu']} | {sy:g} | {k:g} "
              f"| {n:g} | {o['-material_density']} | {tail} |")


if __name__ == "__main__":
    main()
