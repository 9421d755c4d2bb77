"""The result file read back with h5py: mesh, fields (one time-series entry
per output increment, in the shapes ParaView's XDMF reader expects), the
/history group with every documented column, the options attribute and the
.xmf beside it; the CSV with its header. Sizes are computed from the options
(structured mesh: (nt+1)(ntheta+1) nodes, nt*ntheta cells), not from the code.
The CSV's columns begin with the files' in their order (FILE_COLUMNS: the
header the release before the tools declared their own columns wrote, which
readers by position rely on; a new column goes after them), and /history
has the CSV's; the tools' columns are there in a scene without tools too, 0
(exactly: nothing fills them).
"""
import csv
import math
import os
import xml.etree.ElementTree as ET

import h5py
import numpy as np

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
k = Checks("hdf5")
nt, nth, incs, every = 3, 10, 5, 2
run(tf, mpirun, 2, ["-options_file", f"{src}/options/pressure.opts", "-mesh_nt", nt, "-mesh_ntheta", nth,
                    "-increments", incs, "-output_every", every, "-output", out("io.h5"), "-history_csv", out("io.csv")])
nv, nc = (nt + 1) * (nth + 1), nt * nth
steps = 1 + len([i for i in range(1, incs + 1) if i % every == 0 or i == incs])  # initial state + outputs
columns = ["increment", "stroke", "load", "rmin", "limiter", "n_contact", "n_plastic", "friction_iters", "residual",
           "w_ext", "w_int", "w_plastic", "w_friction", "w_elastic", "energy_error", "c_over_t", "x_max", "y_max",
           "deviation_ratio"]
# The files' columns in order (the CSV header of the release before the tools declared theirs; new columns go after
# these), and the tools' columns among them.
FILE_COLUMNS = (
    "increment,stroke,load,rmin,limiter,limiter_where,n_contact,n_plastic,friction_iters,residual,r_max,q_avg,w_ext,"
    "w_int,w_plastic,w_friction,w_elastic,energy_error,c_over_t,x_max,y_max,deviation_ratio,redo,unsettled,"
    "events_inside,inconsistent,drift,r_corner_x,r_corner_y,penetration,tension,release_force,contact_gap,det_sign,"
    "fn_mismatch,stage,n_contact_apex,tool_fx,tool_fy,tool_moment,w_kinetic,w_inertia,w_damped,w_tool,internal_error,"
    "inertia,slip,fn_sum,lower_fx,lower_fy,side_load,lower_moment,side_stroke,hold_moment,hold_friction,die_x,die_turn,"
    "release,release_yielded,release_excess,release_dep").split(",")
TOOL_COLUMNS = ("n_contact_apex tool_fx tool_fy tool_moment lower_fx lower_fy side_load lower_moment side_stroke "
                "hold_moment hold_friction die_x die_turn").split()
with h5py.File("io.h5", "r") as h:
    datasets = sorted(h["/history"])
    unfilled = [c for c in TOOL_COLUMNS if c not in h["/history"] or np.any(h["/history"][c][:] != 0)]
    k.check(not unfilled, f"a scene without tools has the tools' columns, 0 (not: {unfilled})")
    k.check(h["/geometry/vertices"].shape == (nv, 2), f"/geometry/vertices {h['/geometry/vertices'].shape} == ({nv}, 2)")
    k.check(h["/viz/topology/cells"].shape == (nc, 4), f"/viz/topology/cells {h['/viz/topology/cells'].shape} == ({nc}, 4)")
    k.check(h["/vertex_fields/displacement_u"].shape == (steps, nv, 2), f"displacement {h['/vertex_fields/displacement_u'].shape} == ({steps}, {nv}, 2)")
    for f in ("sigma_xx", "sigma_yy", "sigma_zz", "sigma_xy", "von_mises", "eps_p"):
        shape = h[f"/cell_fields/{f}_c"].shape
        k.check(shape == (steps, nc), f"cell field {f} {shape} == ({steps}, {nc})")
    k.check(h["/time"].shape[0] == steps, f"/time has {steps} entries")
    for c in columns:
        k.check(c in h["/history"] and h["/history"][c].shape == (incs + 1,), f"/history/{c} has {incs + 1} rows")
    load = h["/history/load"][:]
    k.check(np.allclose(load, np.linspace(0, 50, incs + 1), rtol=1e-12), "history load = pressure ramp 0..50")
    opts = h.attrs["options"]
    opts = opts.decode() if isinstance(opts, bytes) else str(opts)
    k.check("-mesh_ntheta 10" in opts and "-scene pressure" in opts, "options attribute holds the run's options")
    k.check("limiter_names" in h["/history"].attrs, "limiter names attribute")
    # Cells reference existing vertices; all are counter-clockwise with positive area.
    X, C = h["/geometry/vertices"][:], h["/viz/topology/cells"][:]
    k.check(C.min() == 0 and C.max() == nv - 1, "cell connectivity covers the vertices")
    P = X[C]
    area = 0.5 * sum(P[:, i, 0] * P[:, (i + 1) % 4, 1] - P[:, (i + 1) % 4, 0] * P[:, i, 1] for i in range(4))
    k.check((area > 0).all(), "all cells counter-clockwise")
k.check(not os.path.exists("io.h5.partial"), "no .partial file left behind")
xmf = ET.parse("io.xmf").getroot()
grids = xmf.findall(".//Grid[@GridType='Uniform']")
k.check(len(grids) == steps, f"io.xmf has {steps} time steps")
with open("io.csv") as f:
    rows = list(csv.reader(f))
k.check(rows[0][:len(columns)] != [] and all(c in rows[0] for c in columns), "CSV header has every column")
moved = [f"{c} at {rows[0].index(c) if c in rows[0] else None}, not {i}" for i, c in enumerate(FILE_COLUMNS)
         if i >= len(rows[0]) or rows[0][i] != c]
k.check(rows[0][:len(FILE_COLUMNS)] == FILE_COLUMNS,
        f"the CSV's columns are the files' in their order ({'; '.join(moved[:3]) or 'the same'})")
k.check(datasets == sorted(rows[0]), f"/history has the CSV's columns (more: {sorted(set(datasets) - set(rows[0]))}, "
        f"missing: {sorted(set(rows[0]) - set(datasets))})")
k.check(len(rows) == incs + 2, f"CSV has header + {incs + 1} rows")

# -output_stroke D: fields whenever the loading passes a multiple of D mm of
# stroke, at the end of the loading stage and at the end; the expected writes
# follow from the history's stroke column (lambda = U / stroke in loading).
D, U_end = 0.1, 0.6
run(tf, mpirun, 2, ["-options_file", f"{src}/options/squaring.opts", "-stroke", U_end, "-rmin_yield", "inside",
                    "-increments", 40, "-output_stroke", D, "-output", out("stroke.h5")])
with h5py.File("stroke.h5", "r") as h:
    t = h["/time"][:, 0]
    H = {c: h["/history"][c][:] for c in ("stroke", "stage")}
    steps = h["/vertex_fields/displacement_u"].shape[0]
U = H["stroke"][H["stage"] == 0]
expect, last_bin = [0.0], 0
for i in range(1, len(U)):
    b = np.floor(U[i] / D + 1e-9)
    if b > last_bin or i == len(U) - 1:
        expect.append(U[i] / U_end)
        last_bin = b
loading = t[t <= 1 + 1e-12]
k.check(len(loading) == len(expect) and np.allclose(loading, expect, rtol=0, atol=1e-12),
        f"-output_stroke {D}: loading writes at the {len(expect)} strokes the history gives (got {len(loading)})")
k.check(abs(loading[-1] - 1) < 1e-12, "-output_stroke: the end of loading is written")
unloading = t[t > 1 + 1e-12]
k.check(1 <= len(unloading) <= U_end / D + 1 and abs(t[-1] - 2) < 1e-12,
        f"-output_stroke: unloading written {len(unloading)} times (1..{U_end / D + 1:g}), ending at its end")
k.check(steps == len(t), "one field entry per /time entry")

# Contact fields (a tool scene, 2 ranks): at the end of loading the nodal
# contact forces read back from the file (each node once, whichever rank owned
# it) add up to the punch load of the history (2 x the quarter's vertical
# force: the file's gather against the run's own sum), the nodes carrying a
# force are flagged in contact, and the xmf offers both fields to ParaView.
with h5py.File("stroke.h5", "r") as h:
    t = h["/time"][:, 0]
    j = int(np.flatnonzero(t <= 1 + 1e-12)[-1])
    F, S = h["/vertex_fields/contact_force"][j], h["/vertex_fields/contact_state"][j]
    load = h["/history/load"][:][h["/history/stage"][:] == 0][-1]
    shapes = (h["/vertex_fields/contact_force"].shape, h["/vertex_fields/contact_state"].shape)
nv = h5py.File("stroke.h5", "r")["/geometry/vertices"].shape[0]
k.check(shapes == ((len(t), nv, 2), (len(t), nv)), f"contact fields {shapes}")
dF = abs(2 * abs(F[:, 1].sum()) - load) / load
# Measured 0 (OpenBLAS Haswell, SkylakeX, Prescott); the bound is the worst round-off of summing the nodes'
# forces in another order (245 nodes x 2.2e-16 = 5e-14), twice over.
k.check(dF <= 1e-13, f"2 x sum of nodal contact forces {2 * abs(F[:, 1].sum()):.10g} == punch load {load:.10g} "
        f"({dF:.1e} relative)")
loaded = np.hypot(F[:, 0], F[:, 1]) > 1e-9 * load
k.check(loaded.any() and (S[loaded] == 1).all(), f"{loaded.sum()} nodes carry force, all flagged in contact")

# The tool in the results: its outline at the start against the V-die of docs/dies.md (apex fillet of
# -die_r_apex on the flanks x + y = Ro sqrt2, read from the options here), its displacement at every field step
# the stroke of that step (lambda x U while pressing, U after: the paper's unloading leaves it in place), and the
# moment on it in the history against the one the written contact forces give about the tool's origin (a
# consistency check: both sum the same forces, through the file here). Tolerances: round-off (1e-12 mm) for
# the geometry; the moment 1e-9 relative (the file's node order sums differently).
RO, RA, S2 = 17.5, 3.0, math.sqrt(2)  # options/squaring.opts
with h5py.File("stroke.h5", "r") as h:
    V, L, Dsp = h["/tools/V-die/vertices"][:], h["/tools/V-die/lines"][:], h["/tools/V-die/displacement"][:]
    X, u = h["/geometry/vertices"][:], h["/vertex_fields/displacement_u"][j]
    moment = h["/history/tool_moment"][:][h["/history/stage"][:] == 0][-1]
on_arc = np.abs(np.hypot(V[:, 0], V[:, 1] - (RO * S2 - RA * S2)) - RA) < 1e-12
on_flank = np.abs(V[:, 0] + V[:, 1] - RO * S2) < 1e-12
top = V[:, 1].max()
k.check(on_arc.sum() >= 3 and (on_arc | on_flank).all() and abs(top - (RO * S2 - RA * (S2 - 1))) < 1e-12
        and L.min() == 0 and L.max() == len(V) - 1,
        f"the V-die's outline: {on_arc.sum()} points on the apex fillet, the rest on the flank, apex at y {top:.6f}")
want = -np.minimum(t, 1.0) * U_end
k.check(Dsp.shape == (len(t), len(V), 2) and np.abs(Dsp[:, :, 0]).max() < 1e-12
        and np.abs(Dsp[:, :, 1] - want[:, None]).max() < 1e-12,
        f"the V-die's displacement at each of the {len(t)} field steps is (0, -U) of the step")
xc, o = X + u, np.array([0.0, -U_end])
fm = -((xc[:, 0] - o[0]) * F[:, 1] - (xc[:, 1] - o[1]) * F[:, 0]).sum()
k.check(abs(fm - moment) <= 1e-9 * abs(moment),
        f"tool_moment {moment:.6f} N mm/mm at the end of loading: the written contact forces give {fm:.6f}")
xmf = ET.parse("stroke.xmf").getroot()
steps_x = xmf.findall("./Domain/Grid/Grid")
times = [float(g.find("Time").get("Value")) for g in steps_x]
kids = [[c.get("Name") for c in g.findall("Grid")] for g in steps_x]
k.check(len(steps_x) == len(t) and all(c == ["body", "V-die"] for c in kids)
        and np.allclose(times, t * U_end, rtol=1e-5),
        f"stroke.xmf: {len(steps_x)} steps of the body and the V-die, times lambda x U / 1 mm/s "
        f"({times[1]:g} ... {times[-1]:g})")
names = {a.get("Name") for a in ET.parse("stroke.xmf").getroot().iter("Attribute")}
k.check({"displacement_u", "contact_state", "contact_force", "eps_p", "von_mises"} <= names,
        f"the xmf's fields: {sorted(names)}")
k.done()
