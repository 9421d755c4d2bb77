"""Unloading by withdrawing the tool against the paper's unloading (contact
forces reversed, tools removed), on the ring crushed between plates
(options/flattening.opts pressed to U = 3 mm, 2 ranks).
Reference: elastic unloading from one state to zero load ends in one shape,
whichever way the load is removed; the two paths differ only by the geometric
non-linearity of the springback itself (second order in springback / radius,
about (1/20)^2 here), so the springback of C2 (y_max) and C1 (x_max) must agree
within 1 %. Also: the withdrawn tool leaves every node (no contact, zero load at
the end), no point yields again while unloading, and the energy balance holds
over the whole path within 1 % of the external work.
The squaring scene likewise (the default tube, fast preset, 1 rank): the sprung-back C/t is the gap of the side
against the chord through the material points that were the side's ends at the end of loading, whatever released
the tube (docs/theory.md, "Metrics"), so the withdrawn die and the reversed loads give one C/t and one C1, C2
after springback: within 1e-3 in C/t and 1e-3 mm (measured 1e-5 and 0: the two paths differ by the springback's
own geometric non-linearity and the order the nodes leave the die; a C/t read against the flank of a die that has
left reads 0, and an extent read in the wrong state moves by the springback itself, 0.01-0.02 mm).
"""
import h5py
import numpy as np

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
k = Checks("unload")
H = {}
for how in ("reverse", "withdraw"):
    f = out(f"unload_{how}.h5")
    run(tf, mpirun, 2, ["-options_file", f"{src}/options/flattening.opts", "-stroke", 3, "-unload", how, "-output", f, "-output_every", 100000])
    with h5py.File(f, "r") as h:
        H[how] = {c: h["/history"][c][:] for c in h["/history"]}
spring = {}
for how, h in H.items():
    loaded = np.nonzero(h["stage"] == 0)[0][-1]
    spring[how] = (h["y_max"][-1] - h["y_max"][loaded], h["x_max"][-1] - h["x_max"][loaded])
w = H["withdraw"]
k.check(w["n_contact"][-1] == 0 and w["load"][-1] == 0 and w["stroke"][-1] == 0, f"withdraw ends free: {int(w['n_contact'][-1])} contact nodes, load {w['load'][-1]:.3g}, stroke {w['stroke'][-1]:.3g}")
k.check(w["n_plastic"][w["stage"] == 1].max() == 0, "no point yields again while the tool withdraws")
for i, axis in enumerate(("C2 (y_max)", "C1 (x_max)")):
    a, b = spring["reverse"][i], spring["withdraw"][i]
    k.check(abs(b - a) < 0.01 * abs(a), f"springback of {axis}: reverse {a:.5f} mm, withdraw {b:.5f} mm ({(b - a) / a:+.2%})")
for how, h in H.items():
    e = np.abs(h["energy_error"][1:]).max()
    k.check(e < 0.01, f"{how}: energy balance error {e:.2e} < 1 %")
SQ = {}
for how in ("reverse", "withdraw"):
    f = out(f"unload_square_{how}.h5")
    run(tf, mpirun, 1, ["-options_file", f"{src}/options/squaring.opts", "-options_file",
                        f"{src}/options/preset-fast.opts", "-error_estimate", 0, "-unload", how, "-output", f])
    with h5py.File(f, "r") as h:
        SQ[how] = {c: float(h["/history"].attrs[f"unloaded_{c}"]) for c in ("c_over_t", "x_max", "y_max")}
r, w = SQ["reverse"], SQ["withdraw"]
k.check(abs(r["c_over_t"] - w["c_over_t"]) < 1e-3 and r["c_over_t"] > 0.1,
        f"squaring, after springback: C/t {w['c_over_t']:.5f} with the die withdrawn, {r['c_over_t']:.5f} with the "
        f"reversed loads (1e-3)")
dx = max(abs(r[c] - w[c]) for c in ("x_max", "y_max"))
k.check(dx < 1e-3, f"squaring, after springback: C1, C2 with the die withdrawn as with the reversed loads within "
        f"{dx:.1e} mm (1e-3)")
k.done()
