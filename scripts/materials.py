#!/usr/bin/python3
"""The material library (options/materials/*.opts) at a glance, and the hardening laws fitted to a tensile test.

    /usr/bin/python3 scripts/materials.py
        Each material's constants, and its uniaxial tensile test as the flow
        curve implies it: where it necks (Considere: d sigma / d eps = sigma),
        the uniform elongation there (true strain, and engineering Ag) and the
        engineering tensile strength Rm, with the elastic strain neglected. A
        file's comment names the standard or handbook values it stands for;
        this table shows it meets them.

    /usr/bin/python3 scripts/materials.py --fit swift|ludwik RP RM AG [--true]
        The law through the yield stress RP (MPa) whose tensile test reaches
        the engineering tensile strength RM (the maximum force over the
        original section, MPa) at the uniform elongation AG: the engineering
        strain at the maximum force, as a fraction (EN ISO 6892-1's Ag, 0.20
        for 20 %), or with --true the true (logarithmic) strain there,
        ln(1 + Ag). Necking by Considere with the elastic strain neglected, so
        Ag counts as plastic (the standard's Ag is). Prints the lines of a
        material file (-material_law, _sy, _k, _n).
          swift  K (ep0 + ep)^n, ep0 = (RP / K)^(1/n): necks at ep = n - ep0
                 with RM = K n^n exp(-(n - ep0)); n solved from
                 n ln(n / (n - eu)) = ln(RM / RP) + eu.
          ludwik RP + K ep^n: with A = RM exp(eu) - RP (= K eu^n),
                 n = eu (1 + RP / A), K = A / eu^n.

    /usr/bin/python3 scripts/materials.py --swift SY RM N
        The Swift law of exponent N through sigma(0) = SY whose necking gives
        the engineering tensile strength RM: the K a material file takes.

    /usr/bin/python3 scripts/materials.py --uvc E FY QINF B DINF A C1 G1 [C2 G2 ...]
        A material file's lines for an Updated Voce-Chaboche calibration
        (Hartloper, de Castro e Sousa, Lignos, J. Struct. Eng.,
        doi:10.1061/(ASCE)ST.1943-541X.0002964): the monotonic curve
        fy + QINF (1 - exp(-B p)) - DINF (1 - exp(-A p)) + sum C/G (1 - exp(-G p))
        tabulated at 100 plastic strains from 0 to 2 (geometric from 1e-4:
        within 0.1 MPa of the curve between points), and the backstresses; with
        -hardening chaboche the isotropic part is the Voce terms again
        (docs/theory.md, "Kinematic hardening").

Data no such law fits (a tensile strength not above the yield stress, a
uniform elongation not positive, an exponent past tubeform's 0 < n <= 1) is
refused in one line on the standard error, exit code 1.
"""
import argparse
import glob
import math
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
N_MAX = 1.0  # tubeform's laws take hardening exponents 0 < n <= 1 (-material_n)
N_SLACK = 1e-9  # an exponent of 1 computed as 1 + round-off is 1
BISECTIONS = 200  # halvings of a bracket: far below double precision


class Refused(Exception):
    """Input no law fits: one line for the user."""


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
    for _ in range(BISECTIONS):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if g(mid) > 0 else (lo, mid)
    e = 0.5 * (lo + hi)
    return e, sig(e) * math.exp(-e)


def bisect(f, lo, hi):
    """The root of f, decreasing on [lo, hi] with f(lo) > 0 > f(hi)."""
    for _ in range(BISECTIONS):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if f(mid) > 0 else (lo, mid)
    return 0.5 * (lo + hi)


def check_test(rp, rm, eu=None):
    """The tensile test's data in range (eu None: no elongation given), else Refused."""
    if not (math.isfinite(rp) and rp > 0):
        raise Refused(f"the yield stress {rp:g} must be a positive number of MPa")
    if not (math.isfinite(rm) and rm > rp):
        raise Refused(f"the tensile strength {rm:g} MPa must exceed the yield stress {rp:g} MPa (the engineering "
                      f"stress rises from the one to the other until necking{'; swapped?' if rm < rp else ''})")
    if eu is not None and not (math.isfinite(eu) and eu > 0):
        raise Refused(f"the uniform elongation must be positive (a true strain {eu:g}): the test necks after yield")


def swift_fit(rp, rm, eu):
    """K, n of the Swift law through rp that necks at the true strain eu with the engineering strength rm."""
    check_test(rp, rm, eu)
    target = math.log(rm / rp) + eu
    g = lambda n: n * math.log(n / (n - eu)) - target  # decreasing in n > eu, from +inf to eu - target < 0
    if eu >= N_MAX or g(N_MAX + N_SLACK) > 0:
        n = bisect(g, eu * (1 + 1e-15), 1e12) if g(1e12) < 0 else math.inf
        raise Refused(f"--fit swift: RP {rp:g}, RM {rm:g} MPa at a uniform true strain of {eu:g} need a hardening "
                      f"exponent n = {n:.6g}, above the {N_MAX:g} tubeform takes (a tensile strength this close to "
                      f"the yield stress after so long a uniform elongation: a yield plateau? tabulate the curve, "
                      f"-material_law table)")
    n = min(bisect(g, eu * (1 + 1e-15), N_MAX + N_SLACK), N_MAX)
    return rp / (n - eu) ** n, n


def ludwik_fit(rp, rm, eu):
    """K, n of the Ludwik law rp + K ep^n that necks at the true strain eu with the engineering strength rm."""
    check_test(rp, rm, eu)
    a = rm * math.exp(eu) - rp  # K eu^n: the hardening at necking (> 0 as rm > rp)
    n = eu * (1 + rp / a)
    if n > N_MAX + N_SLACK:
        raise Refused(f"--fit ludwik: RP {rp:g}, RM {rm:g} MPa at a uniform true strain of {eu:g} need a hardening "
                      f"exponent n = {n:.6g}, above the {N_MAX:g} tubeform takes (a tensile strength this close to "
                      f"the yield stress after so long a uniform elongation: a yield plateau? tabulate the curve, "
                      f"-material_law table)")
    n = min(n, N_MAX)
    return a / eu ** n, n


def swift_k(sy, rm, n):
    """K of the Swift law of exponent n through sigma(0) = sy whose necking gives the engineering strength rm."""
    if not (math.isfinite(n) and 0 < n <= N_MAX):
        raise Refused(f"--swift: the hardening exponent N {n:g} must lie in (0, {N_MAX:g}]")
    check_test(sy, rm)
    # ep0 in (0, n): rm / sy = (n / ep0)^n exp(ep0 - n), decreasing from +inf at 0 to 1 at n.
    q = lambda ep0: n * math.log(n / ep0) + ep0 - n - math.log(rm / sy)
    lo = n * 1e-300
    if q(lo) > 0 and q(n) < 0:
        ep0 = math.exp(bisect(lambda x: q(math.exp(x)), math.log(lo), math.log(n)))
    else:
        raise Refused(f"--swift: RM / SY = {rm / sy:g} is beyond any Swift law of exponent {n:g}")
    return sy / ep0 ** n


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


def table():
    print("| material | law | E (MPa) | nu | sy (MPa) | K (MPa) | n | density (t/mm^3) | uniform strain (true) | "
          "Ag (engineering) | Rm (MPa) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for path in sorted(glob.glob(os.path.join(ROOT, "options", "materials", "*.opts"))):
        o = read_opts(path)
        law = o.get("-material_law", "ludwik")
        if law == "table":
            print(f"| {os.path.basename(path)[:-5]} | table | {o['-material_e']} | {o['-material_nu']} | "
                  f"{o['-material_sy']} | - | - | {o['-material_density']} | - | - | - |")
            continue
        sy, k, n = (float(o[key]) for key in ("-material_sy", "-material_k", "-material_n"))
        neck = considere(law, sy, k, n) if law in ("ludwik", "swift") else None
        tail = f"{neck[0]:.3f} | {math.expm1(neck[0]):.3f} | {neck[1]:.0f}" if neck else "- | - | -"
        print(f"| {os.path.basename(path)[:-5]} | {law} | {o['-material_e']} | {o['-material_nu']} | {sy:g} | {k:g} "
              f"| {n:g} | {o['-material_density']} | {tail} |")


class Parser(argparse.ArgumentParser):
    def error(self, message):
        raise Refused(f"{message} (--help)")


def main():
    p = Parser(description=__doc__.split("\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter,
               epilog=__doc__.split("\n", 2)[2])
    g = p.add_mutually_exclusive_group()
    g.add_argument("--fit", nargs=4, metavar=("LAW", "RP", "RM", "AG"))
    g.add_argument("--swift", nargs=3, type=float, metavar=("SY", "RM", "N"))
    g.add_argument("--uvc", nargs="+", type=float, metavar="X")
    p.add_argument("--true", action="store_true", help="with --fit: AG is the true uniform strain, not Ag")
    a = p.parse_args()
    if a.true and not a.fit:
        raise Refused("--true goes with --fit")
    if a.uvc:
        if len(a.uvc) < 8 or len(a.uvc) % 2:
            raise Refused("--uvc takes E FY QINF B DINF A and pairs C G (at least one)")
        print("\n".join(uvc_lines(*a.uvc)))
    elif a.swift:
        sy, rm, n = a.swift
        k = swift_k(sy, rm, n)
        print(f"K = {k:.1f} MPa (ep0 = {(sy / k) ** (1 / n):.5f}; check: Rm = {considere('swift', sy, k, n)[1]:.1f})")
    elif a.fit:
        law = a.fit[0]
        if law not in ("swift", "ludwik"):
            raise Refused(f"--fit {law}: the laws are swift and ludwik")
        try:
            rp, rm, ag = (float(v) for v in a.fit[1:])
        except ValueError:
            raise Refused(f"--fit {' '.join(a.fit)}: RP, RM and AG must be numbers")
        if not a.true and ag >= math.e - 1:
            raise Refused(f"--fit: Ag {ag:g} is beyond any law tubeform takes (n <= 1 necks before Ag = e - 1); give "
                          f"it as a fraction (0.2 for 20 %)")
        eu = ag if a.true else math.log1p(ag) if ag > -1 else -math.inf
        k, n = (swift_fit if law == "swift" else ludwik_fit)(rp, rm, eu)
        neck = considere(law, rp, k, n)
        print(f"-material_law {law}\n-material_sy {rp:.10g}\n-material_k {k:.10g}\n-material_n {n:.10g}")
        print(f"# check: necks at the true strain {neck[0]:.6g} (Ag {math.expm1(neck[0]):.6g}), Rm {neck[1]:.6g} MPa")
    else:
        table()


if __name__ == "__main__":
    try:
        main()
    except Refused as e:
        sys.exit(f"materials.py: {e}")
