"""-dynamics implicit (lumped mass, backward Euler; docs/theory.md "Inertia").

1. Breathing of a thin ring (R/t = 20, elastic, plane strain) under an
   internal pressure ramped over five periods. Reference: the ring's
   extensional mode, omega^2 = E / ((1 - nu^2) rho R^2). The dynamic minus the
   quasi-static response oscillates with that period (half-periods within 1 %:
   the thin-ring formula is exact to O((t/R)^2) = 2.5e-3, backward Euler
   lengthens the period by (omega dt)^2 / 3 = 8e-4 at 20 steps per radian);
   its first swing is the undamped ramp response p/(k omega T) less backward
   Euler's damping over a quarter period (about 4 % here): within 10 %. The
   energy balance including the inertia work holds to 1e-4 of the external
   work although the kinetic energy reaches 3e-3 of it (leaving the inertia
   work out would show that much error); the error is 5.3e-7 on every
   OpenBLAS kernel tried, so the bound is 5e-5 (about 100 times). 1 and 2
   ranks agree to 7e-13 (100 times the largest difference measured: 6.7e-15
   Haswell, 4.2e-15 SkylakeX).
2. The quasi-static limit: the default squaring pressed to U = 1 mm at
   1 mm/s gives the quasi-static punch load within 1e-4 (the inertia forces
   are ~(period / process time)^2 smaller than the load).
3. Aluminum 18.5/0.5 at mu = 0.35, whose quasi-static path stalls at
   U = 1.40 mm (docs/theory.md, "Stalls"), pressed to U = 2 mm at 1 and at
   0.1 mm/s: both get there with every friction iteration settled; between
   the local snaps the path is quasi-static: the median kinetic energy (from
   the point where the external work is 1 % of its final value) is below
   1e-7 of the external work and scales with the speed squared (0.1 mm/s
   against 1 mm/s: 0.005-0.02, v^2 gives 0.01; measured 0.009-0.010 at
   130-160 trial increments); the snaps themselves, as a node leaves the die
   (U = 0.83 and 1.03 mm), release up to 1e-3 of the work whatever the
   speed, so their peak is not bounded here (a bound of 1e-5 on it, asserted
   before, held at 143 increments only: at 150 and 160 the same code
   released 2-5e-4 at those snaps, `scripts/history_stats.py snaps` on these
   runs with `-increments 150`); and
   the loads at U = 1, 1.25 and 1.5 mm agree within 0.5 % (a rate-independent
   result; 0.5 % is the path sensitivity to the order of near-simultaneous
   contact events, seen between 1 and 2 ranks). Past U ~ 1.5 mm this tube
   follows one of several branches after local snaps, and which one depends
   on the speed and on details of the event handling (docs/results.md): not
   asserted.
4. A separation inside the shortest step: the same tube on a 4 x 96 mesh to
   U = 0.2 mm (15 trial increments), where a node leaves the die through a
   chain of ever shorter r5 steps down to the 1e-6 floor. With inertia at
   1 mm/s the load at U = 0.2 mm equals the quasi-static one within 3e-5
   (the two are the same path there: measured 2.6e-7 on Haswell and
   SkylakeX, 100 times that), and no step is left unsettled. (A node
   released only at the commit of the floor step left the ring's
   readjustment to the next full step, which never settled and tripled the
   load.)
5. The largest load is the quasi-static curve's: the thin aluminum 18.5/0.5
   at mu 0.05 on the fast preset resolves a local snap at U = 1.19 mm inside
   inertia's shortest step, and that one row reads 42.7 N/mm between rows of
   9.4 and 7.5 (the wall's impact on the die in some 1e-7 s). The reported
   `max_load` must be the largest of the rows that are not such one-row
   spikes (a row more than 5 % above both neighbours; the curve's own rise
   between rows is under 1 % on this preset), within 1e-9 (the same row's
   value), and a spike above it must be reported apart (`max_load_transient`).
   Before the answer told the two apart, `max_load` was 42.7 against the
   curve's 18.0.
6. Inertia's steps through a fold of the springback: the copper 14.5/0.5 at
   mu 0.2 on the fast preset springs back (load-controlled, the paper's way)
   towards a fold of its unloading path, where one cell's rotation bound,
   estimated by scaling the trial step linearly, cut every step to 1e-7 of
   its trial while the step taken (mass-dominated at its dt) rotated it far
   less: 14,423 springback increments (83 s). Steps cut by a size bound are
   now lengthened while their re-solve stays within its limits (docs/theory.md,
   "Events bound what they say"): 275-330 springback increments on OpenBLAS
   Haswell, SkylakeX and Prescott. Asserted: at most 1,500 (some 5 times
   that, a tenth of the creep), none unsettled, and the energy balance of the
   whole run within 1 % (measured 0.44-0.50 %).
7. -dynamics auto where quasi-static steps cannot meet a contact event: the
   steel tube of tests/reference/calculix (R/t 10, mu 0.1) on the default
   preset, 0.3 mm in 12 trial increments (the trial step of its 5 mm in
   200): at U = 0.14 mm a node touches and leaves the die by turns and the
   quasi-static re-solves shrink to 8e-11 of the trial (`-dynamics
   quasistatic` stops there, as auto did before it turned inertia on for
   this too). Asserted: auto finishes, says it turned inertia on, and its load
   is the implicit run's: to 1e-6 at U = 0.14 mm (up to the switch the two
   follow one path: measured 2.4e-8), within 2e-3 at 0.3 mm (after it,
   auto's inertia starts from quasi-static velocities: measured 3.8e-4; the
   bound is five times that, inside the 0.5 % path sensitivity of item 3).
"""
from concurrent.futures import ThreadPoolExecutor

import h5py
import numpy as np

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
k = Checks("dynamics")


def history(f):
    with h5py.File(f, "r") as h:
        return {c: h["/history"][c][:] for c in h["/history"]}


# 1. Ring breathing.
E, nu, rho, Rm, t = 75000.0, 0.34, 2.7e-9, 20.0, 1.0
omega = np.sqrt(E / ((1 - nu**2) * rho * Rm**2))
T = 5 * 2 * np.pi / omega
N = int(round(omega * T / 0.05))
ring = ["-options_file", f"{src}/options/pressure.opts", "-tube_ro", Rm + t / 2, "-tube_t", t, "-mesh_nt", 2, "-mesh_ntheta", 6,
        "-pressure_p", 1, "-increments", N, "-dynamics_time", repr(T), "-output_every", 100000]
H = {}
for name, np_, dyn in (("qs", 1, "quasistatic"), ("dyn", 1, "implicit"), ("dyn2", 2, "implicit")):
    f = out(f"ring_{name}.h5")
    run(tf, mpirun, np_, ring + ["-dynamics", dyn, "-output", f])
    H[name] = history(f)
d = H["dyn"]["stroke"] - H["qs"]["stroke"]
time = np.linspace(0, T, N + 1)
zeros = np.array([time[i] - d[i] * (time[i + 1] - time[i]) / (d[i + 1] - d[i]) for i in range(1, N) if d[i] * d[i + 1] < 0])
half = np.diff(zeros) / (np.pi / omega)
k.check(len(half) >= 8 and np.abs(half - 1).max() < 0.01, f"ring breathing: {len(half)} half-periods, {half.min():.4f} to {half.max():.4f} of pi/omega (1 %)")
first = np.abs(d[time < 0.5 * np.pi / omega]).max()
swing = H["qs"]["stroke"][-1] / (omega * T)
k.check(abs(first / swing - 1) < 0.1, f"first swing {first:.4e} mm, ramp response {swing:.4e} mm ({first / swing - 1:+.1%}, 10 %)")
dyn = H["dyn"]
ke = dyn["w_kinetic"].max() / dyn["w_ext"][-1]
err = np.abs(dyn["energy_error"][1:]).max()
k.check(ke > 1e-3 and err < 5e-5, f"energy balance with inertia: error {err:.1e} (< 5e-5) while the kinetic energy reaches {ke:.1e} of the external work")
k.check(np.all(dyn["w_inertia"] >= dyn["w_kinetic"] - 1e-12 * dyn["w_ext"][-1]), "backward Euler dissipates: inertia work >= kinetic energy at every increment")
rel = np.abs(H["dyn2"]["stroke"] - dyn["stroke"]).max() / np.abs(dyn["stroke"]).max()
k.check(rel < 7e-13, f"1 and 2 ranks: displacement histories agree to {rel:.1e} (7e-13)")


# 2 and 3: squaring runs, two at a time.
def squaring(name, opts):
    f = out(f"dyn_{name}.h5")
    run(tf, mpirun, 1, opts + ["-output", f, "-output_every", 100000], timeout=900)
    return name, history(f)


base = ["-options_file", f"{src}/options/squaring.opts", "-unload", "none"]
thin = ["-options_file", f"{src}/options/squaring_al_37_mu0.35.opts", "-unload", "none", "-stroke", 2, "-increments", 143, "-dynamics", "implicit"]
fine = ["-options_file", f"{src}/options/squaring_al_37_mu0.35.opts", "-unload", "none", "-mesh_ntheta", 96, "-stroke", 0.2, "-increments", 15]
jobs = {  # (the longest first, the fold and the snap: the pool's two cores end together)
    "fold": ["-options_file", f"{src}/options/squaring_cu_29_mu0.20.opts", "-options_file", f"{src}/options/preset-fast.opts",
             "-error_estimate", 0],
    "snap": ["-options_file", f"{src}/options/squaring_al_37_mu0.05.opts", "-options_file", f"{src}/options/preset-fast.opts",
             "-unload", "none", "-error_estimate", 0],
    "thin1": thin + ["-punch_speed", 1],
    "thin01": thin + ["-punch_speed", 0.1],
    "qs": base + ["-stroke", 1, "-increments", 72, "-dynamics", "quasistatic"],
    "slow": base + ["-stroke", 1, "-increments", 72, "-dynamics", "implicit", "-punch_speed", 1],
    "fine_qs": fine + ["-dynamics", "quasistatic"],
    "fine_dyn": fine + ["-dynamics", "implicit"],
}
with ThreadPoolExecutor(max_workers=2) as pool:
    S = dict(pool.map(lambda kv: squaring(*kv), jobs.items()))

for u in (0.25, 0.5, 1.0):
    a, b = (np.interp(u, S[n]["stroke"], S[n]["load"]) for n in ("qs", "slow"))
    k.check(abs(b - a) < 1e-4 * a, f"squaring at 1 mm/s vs quasi-static, U = {u}: {b:.5f} vs {a:.5f} N/mm ({(b - a) / a:+.1e}, 1e-4)")
median_ke = {}
for n in ("thin1", "thin01"):
    h = S[n]
    k.check(h["stroke"][-1] >= 2 - 1e-9 and h["unsettled"][-1] == 0, f"{n}: aluminum 18.5/0.5, mu 0.35 reaches U = {h['stroke'][-1]:.3f} mm, unsettled steps {int(h['unsettled'][-1])}")
    on = h["w_ext"] > 0.01 * h["w_ext"][-1]
    median_ke[n] = np.median(h["w_kinetic"][on] / h["w_ext"][on])
    k.check(median_ke[n] < 1e-7, f"{n}: median kinetic energy {median_ke[n]:.1e} of the external work (1e-7)")
    e = np.abs(h["energy_error"][10:]).max()
    k.check(e < 0.02, f"{n}: energy balance error {e:.1e} (2 %)")
ratio = median_ke["thin01"] / median_ke["thin1"]
k.check(0.005 < ratio < 0.02, f"median kinetic energy, 0.1 against 1 mm/s: ratio {ratio:.4f} (v^2: 0.01; 0.005-0.02)")
for u in (1.0, 1.25, 1.5):
    a, b = (np.interp(u, S[n]["stroke"], S[n]["load"]) for n in ("thin1", "thin01"))
    k.check(abs(b - a) < 5e-3 * a, f"mu 0.35 thin tube, 1 vs 0.1 mm/s at U = {u}: {a:.4f} vs {b:.4f} N/mm ({(b - a) / a:+.1e}, 0.5 %)")
a, b = (S[n]["load"][-1] for n in ("fine_qs", "fine_dyn"))
k.check(abs(b - a) < 3e-5 * a and S["fine_dyn"]["unsettled"][-1] == 0, f"separation in the shortest step (4 x 96 mesh), load at U = 0.2 mm: inertia {b:.5f}, quasi-static {a:.5f} N/mm ({(b - a) / a:+.1e}, 3e-5), unsettled steps {int(S['fine_dyn']['unsettled'][-1])}")
# 5. The largest load of a run with a snap.
with h5py.File(out("dyn_snap.h5"), "r") as f:
    attrs = dict(f["/history"].attrs)
P = S["snap"]["load"][S["snap"]["stage"] == 0]
spike = np.zeros(len(P), bool)
spike[1:-1] = (P[1:-1] > 1.05 * P[:-2]) & (P[1:-1] > 1.05 * P[2:])
curve = P[~spike].max()
k.check(abs(attrs["max_load"] - curve) <= 1e-9 * curve, f"snap: max_load {attrs['max_load']:.4f} N/mm, the curve's largest {curve:.4f} (one-row spikes: {np.round(P[spike], 2).tolist()})")
above = P[spike][P[spike] > curve]
k.check(len(above) == 0 or abs(attrs.get("max_load_transient", 0) - above.max()) <= 1e-9 * above.max(),
        f"snap: a spike above the curve is reported apart: max_load_transient {attrs.get('max_load_transient', 0):.4f}, spikes above the curve {np.round(above, 2).tolist()}")
# 6. Through the springback's fold.
F = S["fold"]
back = int((F["stage"] > 0).sum())
e = np.abs(F["energy_error"][10:]).max()
k.check(back <= 1500 and F["unsettled"][-1] == 0 and e < 0.01,
        f"fold: copper 14.5/0.5 mu 0.2 springs back in {back} increments (1,500; 14,423 when the trial's scaling cut them), "
        f"unsettled {int(F['unsettled'][-1])}, energy balance error {e:.1e} (1 %)")
# 7. -dynamics auto at a contact event quasi-static steps cannot meet.
steel = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-default.opts",
         "-tube_ro", 20, "-tube_t", 2, "-material", "custom", "-material_e", 210000, "-material_nu", 0.3,
         "-material_sy", 350, "-material_k", 500, "-material_n", 0.3, "-material_density", 7.85e-9, "-friction_mu", 0.1,
         "-die_r_apex", 3, "-unload", "none", "-error_estimate", 0, "-progress", 0, "-stroke", 0.3, "-increments", 12]
with ThreadPoolExecutor(max_workers=2) as pool:
    A = list(pool.map(lambda d: run(tf, mpirun, 1, steel + ["-dynamics", d, "-output", out(f"dyn_steel_{d}.h5")], check=False),
                      ("auto", "implicit")))
switched = "inertia on from here" in A[0].stdout
k.check(A[0].returncode == 0 and A[1].returncode == 0 and switched,
        f"steel tube, -dynamics auto: exit {A[0].returncode} (implicit {A[1].returncode}), turned inertia on: {switched}")
if A[0].returncode == 0 and A[1].returncode == 0:
    ha, hi = history(out("dyn_steel_auto.h5")), history(out("dyn_steel_implicit.h5"))
    for u, tol in ((0.14, 1e-6), (0.3, 2e-3)):
        a, b = np.interp(u, ha["stroke"], ha["load"]), np.interp(u, hi["stroke"], hi["load"])
        k.check(abs(a - b) <= tol * b, f"steel tube at U = {u}: auto {a:.4f}, implicit {b:.4f} N/mm ({(a - b) / b:+.1e}, {tol:g})")
k.done()
