"""Squaring, aluminum 17.5/1.5, mu = 0.05 (options/squaring.opts), with the
paper's springback, on 1 and 2 ranks; and the frictionless case.
  - energy balance (tool work = internal work + friction dissipation) within
    1 % of the external work at every increment (the issue's tolerance;
    measured 0.8 % with 300 trial increments, first-order in the step);
  - no node penetrates a tool by more than 1e-6 mm; no contact node in
    tension beyond a millionth of the punch load (the contact code's "zero":
    a node whose force change is smaller is grazing, neither pulled nor
    pressed; steps re-solved for friction and inertia end such nodes a few
    micro-newtons either side of zero);
    every step's friction iterations settle (none taken unsettled);
  - 1 vs 2 ranks (the default: inertia at 1 mm/s, docs/theory.md "Inertia"):
    load, C1, C2, C/t and external work interpolated at the same strokes
    within 1e-6 relative up to U = 2.6 mm (increments are cut at events found
    to round-off, so rows do not pair one to one; measured ~1e-11), and within
    1e-4 beyond, where the wall collapses: there the difference grows from
    1e-12 at U = 2.6 mm to 1e-6..2e-5 at 4.2 mm, depending on the run's
    round-off (1.1e-6 and 1.9e-5 for C/t in two runs of one commit): the
    collapse amplifies it, and the dynamic steps follow (quasi-static steps
    keep 1e-9). A missing or doubled contribution at the partition boundary
    would show at 1e-2 or more;
  - mu = 0: the problem is symmetric about the 45-degree line while no node
    touches the apex fillet, so C1/C2 = 1 within 1e-6 up to U = 3.5 mm
    (beyond, the collapsing side amplifies round-off: reported).
"""
import h5py
import numpy as np

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
k = Checks("squaring")
H = {}
for n in (1, 2):
    f = out(f"squaring_np{n}.h5")
    run(tf, mpirun, n, ["-options_file", f"{src}/options/squaring.opts", "-output", f, "-output_every", 100000], timeout=900)
    with h5py.File(f, "r") as h:
        H[n] = {c: h["/history"][c][:] for c in h["/history"]}
h = H[1]
load_stage = h["stage"] == 0
e = np.abs(h["energy_error"][1:][load_stage[1:]]).max()
k.check(e < 0.01, f"energy balance over the loading: max error {e:.2e}")
k.check(h["penetration"].max() <= 1e-6, f"largest penetration {h['penetration'].max():.1e} mm")
k.check(h["tension"].max() <= 1e-6 * h["load"].max(), f"largest tensile contact force {h['tension'].max():.1e} N/mm (1e-6 of the largest load, {h['load'].max():.0f} N/mm)")
k.check(H[1]["unsettled"][-1] == 0 and H[2]["unsettled"][-1] == 0, "every trial step's friction iterations settled (no step taken unsettled)")
grid = np.linspace(0.2, 4.2, 41)
before = grid <= 2.6
for col in ("load", "x_max", "y_max", "c_over_t", "w_ext"):
    curves = [np.interp(grid, H[n]["stroke"][H[n]["stage"] == 0], H[n][col][H[n]["stage"] == 0]) for n in (1, 2)]
    rel = np.abs(curves[0] - curves[1]) / np.abs(curves[0]).max()
    k.check(rel[before].max() < 1e-6 and rel.max() < 1e-4, f"1 vs 2 ranks, {col}(U): {rel[before].max():.1e} relative up to U = 2.6 mm (1e-6), {rel.max():.1e} to 4.2 mm (1e-4)")
for col in ("x_max", "y_max", "c_over_t"):
    rel = abs(H[1][col][-1] - H[2][col][-1]) / max(abs(H[1][col][-1]), 1e-12)
    k.check(rel < 1e-4, f"1 vs 2 ranks after springback, {col}: {rel:.1e} (1e-4)")
print(f"       U = 4.2: load {np.interp(4.2, h['stroke'][load_stage], h['load'][load_stage]):.2f} N/mm, "
      f"C/t {h['c_over_t'][load_stage][-1]:.3f}, C1/C2 {h['deviation_ratio'][load_stage][-1]:.4f}; "
      f"after springback C/t {h['c_over_t'][-1]:.3f}, C1/C2 {h['deviation_ratio'][-1]:.4f}")

f = out("squaring_mu0.h5")
run(tf, mpirun, 1, ["-options_file", f"{src}/options/squaring.opts", "-friction_mu", 0, "-unload", "none", "-output", f, "-output_every", 100000])
with h5py.File(f, "r") as hf:
    h0 = {c: hf["/history"][c][:] for c in hf["/history"]}
free = np.cumsum(h0["n_contact_apex"]) == 0
early = free & (h0["stroke"] <= 3.5)
dev = np.abs(h0["deviation_ratio"] - 1)
k.check(early.sum() > 10 and dev[early].max() < 1e-6, f"mu = 0, no apex contact, U <= 3.5: |C1/C2 - 1| <= {dev[early].max():.1e}")
print(f"       mu = 0: |C1/C2 - 1| up to U = 4.2 (apex contact: {'yes' if (~free).any() else 'no'}): {dev[free].max():.1e}")
k.done()
