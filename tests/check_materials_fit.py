"""scripts/materials.py fits a hardening law to a tensile test: the yield
stress Rp, the engineering tensile strength Rm and the uniform elongation
(engineering Ag, or the true strain with --true); it refuses data no law
fits in one line.

1. Round trip. For Swift laws K (ep0 + ep)^n (ep0 = (Rp / K)^(1/n)) and
   Ludwik laws Rp + K ep^n, the law's own tensile test in closed form
   (Considere, d sigma / d eps = sigma, the elastic strain neglected):
     Swift:            eu = n - ep0,                        Rm = K n^n exp(-eu)
     Ludwik, n = 1/2:  sqrt(eu) = (sqrt(Rp^2 + 2 K^2) - Rp) / (2 K)
     Ludwik, n = 1:    eu = 1 - Rp / K,              both:  Rm = (Rp + K eu^n) exp(-eu)
   and Ag = exp(eu) - 1, go to `--fit LAW RP RM AG` (and `--fit LAW RP RM eu
   --true`), whose -material_k and -material_n must be the law's within 1e-8
   relative: the script prints 10 significant digits (5e-10) and solves by
   bisection to round-off (Swift; its K = Rp / ep0^n magnifies an error of n
   by n ln(ep0) / ep0, at most 50 here) or in closed form (Ludwik); data off
   in their 6th digit move K or n by 1e-6 or more, and fail. `--swift RP RM N`
   (the material files' command, printing K to 0.1 MPa) gives K within 0.05
   MPa. The laws: the library's Swift files (dc04, aa6061_t6),
   --swift 145 186 0.3 (a traceback before), the library's brass (Ludwik n =
   1/2), s355 (Ludwik n = 1) and one more of each.
2. Refusals: swapped strengths, a uniform elongation not positive or given in
   percent, data that need an exponent above 1, numbers that are not, a law
   that is not: exit code 1, one line on the standard error starting
   "materials.py:" and naming the problem, nothing on the standard output, no
   traceback.
"""
import math
import os
import subprocess

from tfcheck import Checks, args

tf, mpirun, src = args()
k = Checks("materials_fit")
SCRIPT = os.path.join(src, "scripts", "materials.py")


def script(*argv):
    return subprocess.run(["/usr/bin/python3", SCRIPT] + [str(a) for a in argv], capture_output=True, text=True)


def fitted(p):
    """(K, n) of a --fit's material-file lines, or None."""
    v = dict(l.split() for l in p.stdout.splitlines() if l.startswith("-material_"))
    return (float(v["-material_k"]), float(v["-material_n"])) if p.returncode == 0 else None


def swift_test(rp, kk, n):
    ep0 = (rp / kk) ** (1 / n)
    eu = n - ep0
    return eu, kk * n ** n * math.exp(-eu)


def ludwik_test(rp, kk, n):
    if n == 0.5:
        eu = ((math.sqrt(rp * rp + 2 * kk * kk) - rp) / (2 * kk)) ** 2
    else:  # n = 1
        eu = 1 - rp / kk
    return eu, (rp + kk * eu ** n) * math.exp(-eu)


LAWS = [("swift", 175, 520.2, 0.2), ("swift", 276, 407.9, 0.08), ("swift", 145, 339.8, 0.3),
        ("swift", 400, 900, 0.35), ("ludwik", 150, 700, 0.5), ("ludwik", 300, 900, 0.5), ("ludwik", 355, 2100, 1.0),
        ("ludwik", 200, 600, 1.0)]
for law, rp, kk, n in LAWS:
    eu, rm = (swift_test if law == "swift" else ludwik_test)(rp, kk, n)
    for given, extra in ((math.expm1(eu), []), (eu, ["--true"])):
        p = script("--fit", law, repr(rp), repr(rm), repr(given), *extra)
        got = fitted(p)
        err = max(abs(got[0] / kk - 1), abs(got[1] / n - 1)) if got else math.inf
        k.check(err < 1e-8, f"{law} {rp}, {kk}, {n}: Rm {rm:.2f} MPa, {'eu' if extra else 'Ag'} {given:.4f} fitted "
                f"back to K {got[0] if got else '-'}, n {got[1] if got else '-'} ({err:.1e}, 1e-8)"
                f"{'' if got else ': ' + (p.stderr + p.stdout).strip()}")
    if law == "swift":
        p = script("--swift", rp, repr(rm), n)
        got = float(p.stdout.split("K = ")[1].split()[0]) if p.returncode == 0 else math.nan
        k.check(abs(got - kk) <= 0.05 + 1e-9, f"--swift {rp} {rm:.2f} {n}: K = {got} MPa (law {kk}, 0.05)"
                f"{'' if p.returncode == 0 else ': ' + p.stderr.strip()}")

REFUSED = [
    (["--swift", 310, 175, 0.2], "must exceed the yield stress 310 MPa"),  # swapped
    (["--fit", "swift", 310, 175, 0.2], "swapped?"),
    (["--fit", "ludwik", 310, 175, 0.2], "swapped?"),
    (["--fit", "swift", 175, 175, 0.2], "must exceed the yield stress"),
    (["--fit", "swift", 175, 310, 0], "uniform elongation must be positive"),
    (["--fit", "ludwik", 175, 310, -0.1], "uniform elongation must be positive"),
    (["--fit", "swift", 175, 310, 0, "--true"], "uniform elongation must be positive"),
    (["--fit", "swift", 175, 310, 20], "as a fraction"),  # 20 % as 20
    (["--fit", "swift", 300, 310, 0.3], "need a hardening exponent n = 1.2"),
    (["--fit", "ludwik", 300, 310, 0.3], "need a hardening exponent n = 1.0"),
    (["--fit", "swift", 175, "abc", 0.2], "must be numbers"),
    (["--fit", "swift", 175, "inf", 0.2], "must exceed the yield stress"),
    (["--fit", "voce", 175, 310, 0.2], "the laws are swift and ludwik"),
    (["--fit", "swift", 175, 310], "expected 4 arguments"),
    (["--swift", 175, 310, 1.5], "must lie in (0, 1]"),
    (["--swift", 0, 186, 0.3], "must be a positive number"),
    (["--swift", "nan", 186, 0.3], "must be a positive number"),
    (["--swift", 175, 310], "expected 3 arguments"),
    (["--true"], "--true goes with --fit"),
]
for argv, needle in REFUSED:
    p = script(*argv)
    lines = p.stderr.splitlines()
    ok = (p.returncode == 1 and len(lines) == 1 and lines[0].startswith("materials.py:") and needle in lines[0]
          and not p.stdout and "Traceback" not in p.stderr)
    k.check(ok, f"{' '.join(map(str, argv))}: exit {p.returncode}, {p.stderr.strip() or '(no message)'}")
k.done()
