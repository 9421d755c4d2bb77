"""The springback's law (-springback) on the pure bending scene (options/bending.opts, scenes/bending.cpp) against
the closed form of a strip's release with reverse yield (docs/verification.md, "Scenes against closed forms").

The strip: 1 mm thick, plane strain, aluminum's E and sigma_y0 with nu = 0.49 and linear kinematic hardening alone
(Prager: Ludwik n = 1 with K = C = 16000 MPa and -hardening chaboche -material_kinematic 16000,0, so the yield
surface keeps its radius sigma_y0 and moves with the stress), bent to an outer strain e_m = 2 % and straightened;
its release is the first reversal up to where the moment passes zero. So strong a kinematic hardening makes the
release yield back over the outer 35 % of the thickness: 30 % of the springback is plastic.

The closed form, plane sections and small strains, each fibre in plane-strain uniaxial stress (exact for the
fibre as nu -> 1/2, where the elastic release changes the deviator along the direction of plastic flow):
  E' = E / (1 - nu^2), sigma_0 = 2 sigma_y0 / sqrt(3), I = t^3 / 12, c = t / 2;
  a fibre that flowed in bending reaches the yield surface again when the release has changed its stress by
  rho sigma_0 (rho = 2 at nu = 1/2; from the quadratic of the surface along the elastic path dev(1, 0, nu) for
  nu = 0.49: 1.9997); in reverse flow its tangent is E_t, 1/E_t = (1 - nu b)/E + (2 - b)/(2 C) with
  b = (2 C nu + E)/(2 C + 2 E) (the fully developed flow; b = 1/2 at nu = 1/2);
  a release of the curvature by dk yields back the fibres beyond y_r = rho sigma_0 / (E' dk), and its moment is
  dM(dk) = E' I dk - 2 (E' - E_t) [dk (c^3 - y_r^3)/3 - rho sigma_0/E' (c^2 - y_r^2)/2]  (y_r < c);
  the springback of the outer strain is dk c with dM(dk) = M, the moment at the end of bending (the run's);
  taken elastic, M c / (E' I).
Checks, each tolerance with its reason:
1. The closed form's premises (nu 0.49, small strains) against the exact plane-sections solution of J2 with
   finite strains (tests/plane_sections.py, 4000 fibres): the springback within 0.4 % (measured 0.16 %).
2. -springback material: the run's springback (where the moment passes zero) is the closed form's within 1 %:
   the closed form's own 0.4 % (1.) and the solver's moment error against plane sections, 2e-3 of the largest
   moment in tests/check_bending.py, which at the release's slope near its end (4000 N mm/mm per unit strain)
   moves the zero by 0.6 % of the springback (measured 0.11 %). The springback taken elastic differs by 30 %.
3. -springback elastic: its springback is M c / (E' I) within 1e-3 of it (elastic release: finite-strain terms
   over the release only, as item 2 of tests/check_bending.py).
4. Reverse yield begins where the closed form says: the first release row with a point yielded back (material)
   or carried past the surface (elastic) lies within one row (2e-4 of the strain) past the outermost Gauss
   point's onset, the release's change of outer strain rho sigma_0 c / (E' y_g), taken 3 % early or late (the
   compression side's log strain grows 2 % faster than the nominal; the outer row's stresses differ by 0.8 %
   along the strip: the scene's own, from its fields).
5. The points that reach the yield surface (release_yielded), at every release row: 4 Gauss points per Gauss row
   (2 cells x 2 along the strip) for each row beyond y_r of that row's change of strain, y_r taken 3 % either
   way (4.'s reasons); the same count for either law (the reverse plastic zone of a strip grows with dk alone).
6. How far the elastic release carries the outermost point past the surface (release_excess, sigma_eq / sigma_y
   - 1) at every release row: the closed form's at the outermost Gauss point, its elastic change of stress taken
   from its log strain on the compression side (the larger), within 0.05: 1.5 % of the release's stress change
   there (3.4 sigma_y), twice the 0.8 % by which the outer row's stresses differ along the strip (4.).
"""
import math

import h5py
import numpy as np

from plane_sections import Strip
from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
k = Checks("springback_bending")
E, NU, SY0, C, EM, T = 75000.0, 0.49, 165.3, 16000.0, 0.02, 1.0
CELLS, ROWS = 16, 100  # cells through the thickness, rows per stage
EP, S0, I, HALF = E / (1 - NU ** 2), 2 * SY0 / math.sqrt(3), T ** 3 / 12, T / 2
B = (2 * C * NU + E) / (2 * C + 2 * E)
ET = 1 / ((1 - NU * B) / E + (2 - B) / (2 * C))
X0 = SY0 / math.sqrt(3) * np.array([1.0, -1.0, 0.0])  # the relative stress xi of a fibre flowing in bending
DIR = np.array([2 - NU, -(1 + NU), 2 * NU - 1]) / 3  # dev of an elastic release's stress change (1, 0, nu)
QA, QB = 1.5 * DIR @ DIR, -3 * X0 @ DIR
RHO = -QB / QA / S0  # (the quadratic's root: X0 lies on the surface)
# The Gauss points' initial y: two per cell through the thickness, at +-1/sqrt(3) of its half height.
CENTRES = -HALF + T / CELLS * (np.arange(CELLS) + 0.5)
YG = np.sort(np.concatenate([CENTRES - T / CELLS / (2 * math.sqrt(3)), CENTRES + T / CELLS / (2 * math.sqrt(3))]))
Y_OUT = YG[-1]


def release_moment(dk):
    """dM(dk): the moment the release of the curvature by dk takes off."""
    yr = RHO * S0 / (EP * dk)
    plastic = 0.0 if yr >= HALF else dk * (HALF ** 3 - yr ** 3) / 3 - RHO * S0 / EP * (HALF ** 2 - yr ** 2) / 2
    return EP * I * dk - 2 * (EP - ET) * plastic


def springback(m):
    """The closed form's springback of the outer strain for the moment m at the end of bending."""
    lo, hi = 0.0, 4 * EM / T
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if release_moment(mid) < m else (lo, mid)
    return lo * HALF


def bend(law):
    f = out(f"springback_bending_{law}.h5")
    run(tf, mpirun, 1, ["-options_file", f"{src}/options/bending.opts", "-material_nu", NU, "-material_k", C,
                        "-material_n", 1, "-hardening", "chaboche", "-material_kinematic", f"{C:g},0", "-mesh_nt",
                        CELLS, "-bending_strain", EM, "-bending_cycle", 0, "-increments", ROWS, "-unload_increments",
                        ROWS, "-springback", law, "-output", f])
    with h5py.File(f, "r") as h:
        return {c: h["/history"][c][:] for c in ("stroke", "load", "stage", "release", "release_yielded",
                                                  "release_excess", "release_dep")}


def zero_crossing(h):
    """The strain where the moment passes zero in the release (linear between rows)."""
    e, m = h["stroke"], h["load"]
    i = np.flatnonzero((h["stage"] == 1)[1:] & (np.sign(m[1:]) != np.sign(m[:-1])))[0]
    return e[i] + (e[i + 1] - e[i]) * m[i] / (m[i] - m[i + 1])


def count_beyond(de, spread):
    """4 points per Gauss row beyond y_r of the outer strain's change de, y_r scaled by `spread`."""
    return 4 * int(np.count_nonzero(np.abs(YG) > spread * RHO * S0 * HALF / (EP * de)))


# 1. The closed form's premises against the plane-sections solution with finite strains.
path = np.concatenate([np.linspace(0, EM, 101), np.linspace(EM, 0, 401)[1:]])
ref = Strip(E, NU, SY0).moments(path, C, 0.0)
i = 100 + np.flatnonzero(np.sign(ref[101:]) != np.sign(ref[100:-1]))[0]
ref_back = EM - (path[i] + (path[i + 1] - path[i]) * ref[i] / (ref[i] - ref[i + 1]))
closed_back = springback(ref[100])
k.check(abs(closed_back / ref_back - 1) < 4e-3,
        f"closed form: springback {closed_back:.6f} against plane sections with finite strains {ref_back:.6f} "
        f"({closed_back / ref_back - 1:+.2%}, within 0.4 %); reverse yield range rho {RHO:.4f} sigma_0")

runs = {law: bend(law) for law in ("material", "elastic")}
for law, h in runs.items():
    top = int(np.flatnonzero(h["stage"] == 0)[-1])
    m, back = h["load"][top], EM - zero_crossing(h)
    elastic_back = m * HALF / (EP * I)
    if law == "material":
        # 2. The release by the material's law.
        want = springback(m)
        k.check(abs(back / want - 1) < 0.01,
                f"material: springback {back:.6f} (moment {m:.3f} at e {EM}), closed form with reverse yield "
                f"{want:.6f} ({back / want - 1:+.2%}, within 1 %; taken elastic it would be {elastic_back:.6f})")
    else:
        # 3. The release taken elastic.
        k.check(abs(back / elastic_back - 1) < 1e-3,
                f"elastic: springback {back:.6f}, closed form M c / (E' I) {elastic_back:.6f} (within 1e-3)")
    rel = np.flatnonzero(h["release"] > 0)
    k.check(len(rel) > 0 and h["stage"][rel].min() == 1 and h["load"][rel[-1]] < 0 < h["load"][rel[-2]] and
            np.all(h["release"][rel] == (2 if law == "elastic" else 1)),
            f"{law}: the release is stage 1's rows until the moment passes zero ({len(rel)} rows, release "
            f"{int(h['release'][rel[0]])})")
    de = EM - h["stroke"][rel]
    # 4. The onset of reverse yield.
    onset = RHO * S0 * HALF / (EP * Y_OUT)
    yielded = np.flatnonzero(h["release_yielded"][rel] > 0)
    if not k.check(len(yielded) > 0, f"{law}: points reach the yield surface in the release"):
        continue
    first = rel[yielded[0]]
    k.check(EM - h["stroke"][first - 1] < 1.03 * onset and EM - h["stroke"][first] >= 0.97 * onset,
            f"{law}: reverse yield begins between the release's strain changes {EM - h['stroke'][first - 1]:.5f} and "
            f"{EM - h['stroke'][first]:.5f}, closed form {onset:.5f} (3 %)")
    # 5. The points at the yield surface, row by row.
    got = h["release_yielded"][rel]
    lo, hi = np.array([count_beyond(d, 1.03) for d in de]), np.array([count_beyond(d, 0.97) for d in de])
    bad = np.flatnonzero((got < lo) | (got > hi))
    k.check(len(bad) == 0, f"{law}: points at the yield surface in the release, {int(got.max())} at its end, the "
            f"closed form's count at every row ({len(bad)} rows outside{': ' if len(bad) else ''}"
            f"{', '.join(f'{int(got[j])} not in [{lo[j]}, {hi[j]}]' for j in bad[:3])})")
# 6. How far the elastic release carries the outermost point past the surface.
h = runs["elastic"]
rel = np.flatnonzero(h["release"] > 0)
dlog = np.log1p(-2 * EM * Y_OUT) - np.log1p(-2 * h["stroke"][rel] * Y_OUT)  # (compression side: negative)
excess = np.array([math.sqrt(1.5 * (X0 + EP * d * DIR) @ (X0 + EP * d * DIR)) / SY0 - 1 for d in dlog])
want = np.maximum(excess, 0)
gap = np.abs(h["release_excess"][rel] - want)
j = int(np.argmax(gap))
k.check(gap.max() < 0.05, f"elastic: largest sigma_eq / sigma_y - 1 past the surface, {h['release_excess'][rel][-1]:.3f} "
        f"at the release's end (closed form {want[-1]:.3f}); worst row {h['release_excess'][rel][j]:.3f} against "
        f"{want[j]:.3f} (within 0.05)")
k.check(h["release_dep"].max() == 0 and runs["material"]["release_excess"].max() == 0,
        "each law fills its own column: no plastic strain in the elastic release, no excess in the material's")
k.done()
