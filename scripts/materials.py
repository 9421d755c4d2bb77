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


def main():
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
        sy, k, n = (float(o[key]) for key in ("-material_sy", "-material_k", "-material_n"))
        neck = considere(law, sy, k, n) if law in ("ludwik", "swift") else None
        tail = f"{neck[0]:.3f} | {neck[1]:.0f}" if neck and n < 1 else "- (linear: no necking) | -"
        print(f"| {os.path.basename(path)[:-5]} | {law} | {o['-material_e']} | {o['-material_nu']} | {sy:g} | {k:g} "
              f"| {n:g} | {o['-material_density']} | {tail} |")


if __name__ == "__main__":
    main()
