"""A force-controlled die (-die_force): its stroke an unknown of every increment.

Force control and stroke control press the same model along the same quasi-static path while the tube's
resistance rises, so the load-stroke curve of a run driven by its force is checked against a run driven by
its stroke (an independent control of the model: a different unknown, other increments):

A. The ring between plates (options/flattening.opts, fast preset): the stroke run to U = 0.6 mm gives the force
   P; the force run to P follows the stroke run's load along its stroke within 1e-2 of P (the two take
   different increments; measured 7e-4 with U = 0.6, 3e-5 with U = 0.4, where the ring is still elastic) and
   ends at P within -equilibrium_tol x the mean nodal force (what the equilibrium iterations accept: 6.3e-3 of
   P here; measured 4e-8). The same with the paper's method (no equilibrium
   iterations, r1 at the yield onset: a step cut by r_min is the trial scaled, the die's motion with it):
   within 1e-2 of P along the stroke, and at P within 1e-9 at the end (each linear step meets its force to
   round-off). In each run no node ends inside the die (its stroke is where the body's contact nodes are) and
   the energy balance from the reported load and stroke holds within tests/check_squaring.py's 5e-3 (a die
   whose stroke ran ahead of the scaled step: 1.0e-2 mm inside, 3.3e-2 energy). A checkpoint inside the force press, continued with
   -restart: the history of the run never stopped within 1e-12 of each column's largest value
   (tests/check_restart.py's bound).
B. The paper's tube in the V-dies with friction mu = 0.2 (options/squaring.opts, fast preset), then the paper's
   springback: the die's force along its travel includes the flanks' friction, so a controlled force that left
   the friction out would end on another curve. The stroke run to U = 1 mm gives P; the force run follows its
   load along the stroke within 1e-2 of P (measured 3.5e-3) and springs back (stage 1, the die removed): the
   history's stroke stays where the press left it (exactly: a removed die does not move; its force unknown,
   answering no contact, once took it 0.12 mm on by the springback's end).
C. Equilibrium with the controlled force (the half ring between a force-controlled plate and a fixed floor,
   -equilibrium_tol 1e-6): the reported punch load ends at P within 1e-6, and at every increment of the press
   the floor's vertical force, the reactions of other nodes through the tube, balances the plate's within 1e-6
   of the punch force (measured 2e-12: the balance is met to the equilibrium tolerance, and each tool's force
   is the sum of its nodes' reactions). 1 vs 2 ranks within tests/check_squaring.py's 1.3e-8.
D. A force above the tube's resistance where its load-stroke curve has a maximum (the paper's tube, 200 N/mm:
   the stroke run's load dips at U = 1.95 mm as the contact moves from node to node): the run stops with a
   one-line error naming force control, exit 1, its results up to there written, every load below 200. A force
   the dies cannot reach (their parting faces meet at U = 1 mm first): the run stops there with one line, its
   results written (the first increment past the faces: at most 0.1 mm beyond them).
E. A later pass pressed by a force (-pass2_die_force; the paper's tube in the V-dies, fast preset, the first pass to
   U = 1.5 mm and its springback): the same second pass pressed by its stroke to U = 2 mm reaches F = 120 N/mm (where
   its load rises slowly, contact moving from node to node) at U_s, its stroke interpolated between the two rows
   about F. The force pass's die starts where the stroke pass's first touches the sprung-back tube (between its last
   row without load and its first with, within 1e-6 mm as A's die, in U from -stroke's zero); it ends at F within -equilibrium_tol x the mean
   nodal force (as A; measured 6e-5 of F) and at U_s within the stroke run's row spacing there (its load is known
   only at its rows; measured 9e-4 mm of 0.019); the energy balance within 5e-3 (as A). Planted: the force pass's U
   not shifted to -stroke's zero (its die's own stroke from where it started) -> ends at U = 0.50 mm (FAILED).
   -pass2_die_force with -pass2_stroke is refused in one line naming the option.
F. Passes after a pass pressed by a force (the paper's tube in the V-dies, fast preset): the first pass pressed to
   P1, the load E's stroke run ends its first pass at (U = 1.5 mm), then -pass2_stroke 2 as E's stroke run. The first
   pass ends at P1 within -equilibrium_tol x the mean nodal force (as A), at a U short of 1.5 mm by dU (within
   0.01 mm, a tenth of the fast preset's row spacing here: the force's acceptance on a shallow load curve, 3e-3 mm
   measured); the second pass, from where that springback left
   the tube, follows E's stroke run's second pass moved by dU (a first pass that ended dU earlier reloads the tube
   dU earlier) within 1e-2 of its largest load (A's bound on two controls of one press; measured 2.8e-3; unmoved,
   the elastic reloading's slope times dU reads 1.7e-2 there, 1e-3 once the tube yields again); the energy balance
   within 5e-3 (as A). Before passes could follow a force pass, the run was refused (exit 1: FAILED).
"""
from concurrent.futures import ThreadPoolExecutor

import h5py
import numpy as np

from tfcheck import Checks, args, checkpoint_at, out, run

tf, mpirun, src = args()
k = Checks("force")


def press(scene, name, extra, n=1, check=True, checkpoint=None):
    """The history and the run; `checkpoint` (file, increment): run to that increment, its checkpoint written there
    (tfcheck.checkpoint_at)."""
    opts = ["-options_file", f"{src}/options/{scene}.opts", "-options_file", f"{src}/options/preset-fast.opts",
            "-error_estimate", 0, "-progress", 0, "-output", out(name)]
    if checkpoint:
        p = checkpoint_at(tf, mpirun, n, opts + extra, *checkpoint, timeout=600)
    else:
        p = run(tf, mpirun, n, opts + extra, check=check, timeout=600)
    with h5py.File(out(name), "r") as h:
        r = {c: h["/history"][c][:] for c in h["/history"]}
    return r, p


def follows(ref, h, P, bound, label):
    """h's load along its stroke against ref's (the stroke run), in units of P; h ends at P."""
    s = h["stage"] == 0
    dev = np.abs(h["load"][s] - np.interp(h["stroke"][s], ref["stroke"], ref["load"])).max() / P
    k.check(dev < bound, f"{label}: the load along the stroke against the stroke run's within {dev:.1e} of P "
            f"({bound:g}; P = {P:.4g} N/mm reached at U = {h['stroke'][s][-1]:.4f} mm, the stroke run's at "
            f"{ref['stroke'][-1]:.4f})")
    # The die where its stroke says (the body's nodes on it, none inside it: 1e-6 mm, ten times the contact
    # set's gap tolerance, which the stroke runs meet within 3e-9), and the work it did from the
    # reported load along that stroke against internal work (tests/check_squaring.py's (a): 5e-3).
    pen, energy = np.abs(h["penetration"]).max(), np.abs(h["energy_error"]).max()
    k.check(pen < 1e-6 and energy < 5e-3, f"{label}: no node inside the die ({pen:.1e} mm; 1e-6), the energy "
            f"balance from the reported load and stroke within {energy:.1e} (5e-3)")
    return abs(h["load"][s][-1] / P - 1)


def together(*calls):
    """press() calls (each a function of none) two at a time, the machine's two cores; their results in order."""
    with ThreadPoolExecutor(max_workers=2) as pool:
        return list(pool.map(lambda call: call(), calls))


# The single-rank runs two at a time, in rounds (the runs pressed by a force take it from the round before: A's and
# B's stroke runs, the checkpoint from A's force run), the longest first; then C's 2-rank run. The checks read them.
PAPER = ["-equilibrium_tol", 0, "-rmin_yield", "onset"]
FRICTION = ["-friction_mu", 0.2]
F, FIRST = 120.0, ["-stroke", 1.5]
(pass2_ref, _), (pass2_h, _), (lim, p_lim), (closed, p_closed), (sq_ref, _), (ring_ref, _), (ref0, _) = together(
    lambda: press("squaring", "force_pass2_u.h5", FIRST + ["-pass2_stroke", 2.0]),
    lambda: press("squaring", "force_pass2_f.h5", FIRST + ["-pass2_die_force", F]),
    lambda: press("squaring", "force_limit.h5", ["-die_force", 200, "-unload", "none"], check=False),
    lambda: press("squaring", "force_closed.h5", ["-die_force", 200, "-die_u_close", 1.0, "-unload", "none"],
                  check=False),
    lambda: press("squaring", "force_sq_u.h5", FRICTION + ["-stroke", 1.0, "-unload", "none"]),
    lambda: press("flattening", "force_ring_u.h5", ["-stroke", 0.6]),
    lambda: press("flattening", "force_ring_u0.h5", PAPER + ["-stroke", 0.6]))
P = ring_ref["load"][-1]


def first_load(h):
    """The load the first pass ends at (stage 0's last row)."""
    return float(h["load"][h["stage"] == 0][-1])


HALF = ["-model", "half", "-lower_die_motion", "fixed", "-equilibrium_tol", 1e-6, "-die_force", P]
# (-stroke sets the press's duration at -punch_speed: options/squaring.opts's inertia then matches the stroke run's)
(sq, _), (half1, _), (ring, _), (ring0, _), (then, p_then) = together(
    lambda: press("squaring", "force_sq_f.h5", FRICTION + ["-die_force", sq_ref["load"][-1], "-stroke", 1.0]),
    lambda: press("flattening", "force_half_np1.h5", HALF),
    lambda: press("flattening", "force_ring_f.h5", ["-die_force", P]),
    lambda: press("flattening", "force_ring_f0.h5", PAPER + ["-die_force", ref0["load"][-1]]),
    lambda: press("squaring", "force_then_stroke.h5", FIRST + ["-die_force", first_load(pass2_ref),
                                                               "-pass2_stroke", 2.0], check=False))
ck = out("force_ring_ck.h5")
every = 2 * len(ring["load"]) // 3  # (not a divisor of the increments: the last checkpoint is inside the press)
press("flattening", "force_ring_part.h5", ["-die_force", P], checkpoint=(ck, every))
part, _ = press("flattening", "force_ring_part.h5", ["-die_force", P, "-restart", ck])
halves = {1: half1, 2: press("flattening", "force_half_np2.h5", HALF, 2)[0]}

# A. The ring between plates.
ref = ring_ref
end = follows(ref, ring, P, 1e-2, "ring, force-controlled plate")
# The equilibrium iterations accept a state whose force misses by at most -equilibrium_tol (the fast preset's
# 5e-3) x the mean nodal force q_avg, of the model's force (half the punch load).
accept = 2 * 5e-3 * ring["q_avg"][ring["stage"] == 0][-1] / P
k.check(end <= accept, f"ring: the press ends at the force asked within {end:.1e} of it ({accept:.1e}: "
        f"-equilibrium_tol x q_avg)")
# The paper's method (no equilibrium iterations, r1 at the yield onset): a step cut by r_min is the trial's
# solution scaled, the die's motion with it.
end = follows(ref0, ring0, ref0["load"][-1], 1e-2, "ring, the paper's method (steps scaled by r_min)")
k.check(end < 1e-9, f"ring, the paper's method: the press ends at the force asked within {end:.1e} (1e-9: each "
        f"step meets its force exactly)")
with h5py.File(ck, "r") as c:
    lam = c["/run/lambda"][0]
same = all(part[c].shape == ring[c].shape for c in ring)
worst = max(np.abs(part[c] - ring[c]).max() / max(np.abs(ring[c]).max(), 1e-300) for c in ring) if same else 1
k.check(same and worst <= 1e-12 and 0 < lam < 1,
        f"ring: continued from a checkpoint inside the force press (lambda {lam:.3f}): the history within "
        f"{worst:.1e} (1e-12)")

# B. The V-dies with friction, then the springback.
ref = sq_ref
P = ref["load"][-1]
follows(ref, sq, P, 1e-2, "V-dies, mu 0.2, force-controlled die")
rel = sq["stage"] == 1
drift = np.abs(sq["stroke"][rel] - sq["stroke"][sq["stage"] == 0][-1]).max() if rel.any() else 1.0
k.check(rel.any() and sq["load"][-1] == 0 and drift == 0,
        f"V-dies, force-controlled: the springback follows (stage 1, the die's load released), the die removed "
        f"where the press left it: its stroke moves by {drift:.1e} mm in it (0)")

# C. Equilibrium: the half ring between a force-controlled plate and a fixed floor (A's stroke run's load).
P = ring_ref["load"][-1]
h = halves[1]
s = h["stage"] == 0
end = abs(h["load"][s][-1] / P - 1)
balance = (np.abs(h["tool_fy"][s] + h["lower_fy"][s]) / P).max()
k.check(end < 1e-6 and balance < 1e-6 and np.abs(h["lower_fy"][s]).max() > 0.4 * P,
        f"half ring over a floor: the plate's load ends at P within {end:.1e} (1e-6), the floor's force balances "
        f"it within {balance:.1e} of P at every increment (1e-6)")
a, b = halves[1], halves[2]
worst = max(np.abs(a[c] - b[c]).max() / np.abs(a[c]).max() for c in ("load", "stroke", "x_max", "y_max")) \
    if a["load"].shape == b["load"].shape else 1.0
k.check(worst < 1.3e-8, f"half ring over a floor, 1 vs 2 ranks: every row within {worst:.1e} (1.3e-8)")

# D. Past a maximum of the load.
p = p_lim
lines = [line for line in (p.stdout + p.stderr).splitlines() if "error" in line]
k.check(p.returncode == 1 and len(lines) == 1 and "force control cannot pass it" in lines[0]
        and len(lim["load"]) > 10 and lim["load"].max() < 200,
        f"a force above the load's maximum: exit {p.returncode}, one line ({lines[0][:60] if lines else ''}...), "
        f"{len(lim['load'])} rows written up to U = {lim['stroke'][-1]:.3f} mm, the largest load "
        f"{lim['load'].max():.1f} N/mm")
# A force the dies cannot reach: parting faces at U = 1 mm (-die_u_close), below where the tube would carry 200.
p = p_closed
lines = [line for line in (p.stdout + p.stderr).splitlines() if "error" in line]
k.check(p.returncode == 1 and len(lines) == 1 and "where the dies close on the tube or meet" in lines[0]
        and 1.0 <= closed["stroke"][-1] < 1.1,
        f"a force the dies cannot reach (parting faces at U = 1 mm): exit {p.returncode}, one line, results written "
        f"up to U = {closed['stroke'][-1]:.3f} mm")
# E. A later pass pressed by a force: where the same pass pressed by its stroke reaches that force.
ref, h = pass2_ref, pass2_h
r, s = ref["stage"] == 2, h["stage"] == 2
U, L = ref["stroke"][r], ref["load"][r]
i = int(np.argmax(L >= F))  # (the first row at F or above)
u_s = U[i - 1] + (F - L[i - 1]) / (L[i] - L[i - 1]) * (U[i] - U[i - 1])
t = int(np.argmax(L > 0))  # (the stroke run's first row with load)
u_f, end = h["stroke"][s][-1], abs(h["load"][s][-1] / F - 1)
accept = 2 * 5e-3 * h["q_avg"][s][-1] / F
with h5py.File(out("force_pass2_f.h5"), "r") as f:
    u0 = f["/history"].attrs["pass2_start_stroke"]
# (within 1e-6 mm: follows()'s bound on a node inside the die, ten times the contact set's gap tolerance)
k.check(U[t - 1] - 1e-6 <= u0 <= U[t], f"pass 2 by force: its die starts at U = {u0:.6f} mm, where the stroke pass's "
        f"first touches the tube (between U = {U[t - 1]:.6f} and {U[t]:.6f}, 1e-6)")
k.check(end <= accept and abs(u_f - u_s) <= U[i] - U[i - 1],
        f"pass 2 by force: ends at F = {F:g} N/mm within {end:.1e} of it ({accept:.1e}: -equilibrium_tol x q_avg), at "
        f"U = {u_f:.4f} mm, the stroke pass's U at F {u_s:.4f} within {abs(u_f - u_s):.1e} mm (its row spacing "
        f"{U[i] - U[i - 1]:.3f})")
energy = np.abs(h["energy_error"]).max()
k.check(energy < 5e-3, f"pass 2 by force: the energy balance within {energy:.1e} (5e-3)")
for bad, name in ((["-pass2_stroke", 2.0], "-pass2_die_force"),):
    p = run(tf, mpirun, 1, ["-options_file", f"{src}/options/squaring.opts", "-output", out("force_pass2_bad.h5")]
            + FIRST + ["-pass2_die_force", F] + bad, check=False)
    lines = [line for line in (p.stdout + p.stderr).splitlines() if "error" in line]
    k.check(p.returncode != 0 and len(lines) == 1 and name in lines[0],
            f"{' '.join(map(str, bad))} with -pass2_die_force: refused in one line ({lines[0] if lines else ''})")

# F. A later pass after a pass pressed by a force.
P1 = first_load(pass2_ref)
if p_then.returncode != 0:
    k.check(False, f"F. -die_force {P1:.6g} then -pass2_stroke 2: exit {p_then.returncode} "
            f"({(p_then.stdout + p_then.stderr).strip()[-200:]})")
else:
    h, s = then, then["stage"] == 0
    end, accept = abs(h["load"][s][-1] / P1 - 1), 2 * 5e-3 * h["q_avg"][s][-1] / P1
    k.check(end <= accept, f"F. the first pass by its force ends at P1 = {P1:.5g} N/mm within {end:.1e} of it "
            f"({accept:.1e}: -equilibrium_tol x q_avg), at U = {h['stroke'][s][-1]:.4f} mm")
    du = pass2_ref["stroke"][pass2_ref["stage"] == 0][-1] - h["stroke"][s][-1]
    r, s = pass2_ref["stage"] == 2, h["stage"] == 2
    top = pass2_ref["load"][r].max()
    ref_load = np.interp(h["stroke"][s] + du, pass2_ref["stroke"][r], pass2_ref["load"][r])
    dev = np.abs(h["load"][s] - ref_load).max() / top
    energy = np.abs(h["energy_error"]).max()
    k.check(s.any() and abs(du) < 0.01 and dev < 1e-2 and energy < 5e-3, f"F. its second pass (-pass2_stroke 2) "
            f"follows the stroke run's second pass, moved by dU = {du:.1e} mm, within {dev:.1e} of its largest load "
            f"{top:.4g} N/mm (1e-2), the energy balance within {energy:.1e} (5e-3)")
k.done()
