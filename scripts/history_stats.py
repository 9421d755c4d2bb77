#!/usr/bin/python3
"""Numbers read from result histories (the commands behind figures quoted in docs/).

    /usr/bin/python3 scripts/history_stats.py compare A.h5 B.h5
        Two runs of one tool scene (e.g. 1 and 2 ranks) at equal strokes over
        the loading (41 strokes from 0.2 mm to the end): the largest difference
        of load, x_max, y_max, c_over_t and w_ext relative to the column's
        largest value, and the first stroke where it passes 1e-6.

    /usr/bin/python3 scripts/history_stats.py same A.h5 B.h5
        Two runs expected to be identical (e.g. before and after a change that
        must not alter results, or two runs of one commit): for every history
        column the two files share, whether it is bitwise equal, else the first
        row that differs and the largest relative difference; columns found in
        one file only are listed. Exit code 1 if any shared column differs.

    /usr/bin/python3 scripts/history_stats.py checks F.h5 [F.h5 ...]
        The run's self-checks (docs/theory.md, "Self-checks"), one line per
        file: the largest |energy_error| (a) and |internal_error| (b) after the
        first 10 increments, the damped energy (c) and the largest kinetic
        energy as fractions of the work put in, the largest tension before
        release and force dropped by a release as fractions of the largest
        load, the largest normal-force mismatch of a node as a fraction of
        the largest total normal force, penetration, the compromises (steps
        past an event, unsettled, inconsistent) and the increments r6 limited.

    /usr/bin/python3 scripts/history_stats.py windows F.h5 [F.h5 ...]
        The smallest advance of the load path (stroke / target stroke) over any
        100, 300 and 1000 consecutive increments of the loading: what the stall
        watch (-rmin_stall_increments, threshold 1e-6) sees.

    /usr/bin/python3 scripts/history_stats.py snaps F.h5 [F.h5 ...]
        Runs with inertia: the median kinetic energy of the loading (the tube
        moving with the punch) and every local peak above ten times it (a
        local snap), with its stroke and its share of the work done by then;
        and when the run's largest load is one such row's transient (a row
        that advanced under 1e-4 mm reading > 5 % above both neighbours), its
        neighbours and the load at the end of loading.

    /usr/bin/python3 scripts/history_stats.py metrics F.h5 [F.h5 ...]
        A tool scene's numbers of docs/accuracy.md, one line per file: the
        punch load at U = 1, 2, 3, 4.2 mm, C/t at 2, 3, 4.2 mm (loading) and
        the largest |energy_error| (a) over the whole run after the first 10
        increments (as `checks` and the run's own self-check line).

    /usr/bin/python3 scripts/history_stats.py limiters F.h5 [F.h5 ...]
        What ended the loading increments: the count per limiter name
        (history column `limiter`), and solves (friction_iters) per increment;
        and the touch follow-ups: increments ended by the touch of the node
        that also ended the increment before, at most 0.01 of its r_min (a
        touch the step before left just past its end,
        docs/notes/where-the-time-went.md).

    /usr/bin/python3 scripts/history_stats.py die F.h5 [F.h5 ...]
        A -die_path press (docs/motions.md): U, load, die_x and die_turn at the
        path's points (the loading's rows where the die's motion turns), the
        largest sideways force, die moment (about its pivot) and hold couple,
        the die's sideways work and its turn's work (tool_fx over die_x,
        tool_moment over die_turn) and their shares of the work put in, and
        the largest |energy_error| from U = 0.1 mm.
"""
import os
import sys

import h5py
import numpy as np

# The helper package python/tubeform_py (python/README.md).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))


def loading(path):
    """The loading rows of a history, and the stroke the loading aims at."""
    with h5py.File(path, "r") as h:
        H = {c: h["/history"][c][:] for c in h["/history"]}
        target = h["/history"].attrs.get("final_stroke_target", H["stroke"][-1])
    keep = H["stage"] == 0
    H = {c: v[keep] for c, v in H.items()}
    H["target"] = float(target)
    return H


def compare(a, b):
    A, B = loading(a), loading(b)
    end = min(A["stroke"][-1], B["stroke"][-1])
    grid = np.linspace(0.2, end, 41)
    for col in ("load", "x_max", "y_max", "c_over_t", "w_ext"):
        ca, cb = np.interp(grid, A["stroke"], A[col]), np.interp(grid, B["stroke"], B[col])
        rel = np.abs(ca - cb) / max(np.abs(ca).max(), 1e-300)
        first = f"{grid[np.argmax(rel > 1e-6)]:.2f}" if (rel > 1e-6).any() else "never"
        print(f"{col:9s} largest difference {rel.max():.2e} (at U = {grid[np.argmax(rel)]:.2f}); first above 1e-6 at U = {first}")


def same(a, b):
    with h5py.File(a, "r") as ha, h5py.File(b, "r") as hb:
        A = {c: ha["/history"][c][:] for c in ha["/history"]}
        B = {c: hb["/history"][c][:] for c in hb["/history"]}
    print(f"{a}: {len(A['stroke'])} rows; {b}: {len(B['stroke'])} rows")
    differ = []
    for c in sorted(set(A) & set(B)):
        x, y = A[c], B[c]
        n = min(len(x), len(y))
        bad = np.nonzero(x[:n] != y[:n])[0]
        if len(x) == len(y) and not len(bad):
            continue
        first = bad[0] if len(bad) else n
        scale = max(np.abs(x[:n]).max(), np.abs(y[:n]).max(), 1e-300)
        rel = np.abs(x[:n] - y[:n]).max() / scale
        differ.append(c)
        print(f"  {c:16s} differs from row {first} (largest difference {rel:.1e} of the column's largest value)")
    for c in sorted(set(A) ^ set(B)):
        print(f"  {c:16s} only in {a if c in A else b}")
    print("identical" if not differ else f"{len(differ)} shared columns differ")
    return 1 if differ else 0


def checks(paths):
    print("run | energy (a) | internal (b) | damped/w_ext (c) | max kinetic/w_ext | tension/load | released/load "
          "| fn mismatch | penetration (mm) | past event | unsettled | inconsistent | r6-limited")
    for path in paths:
        with h5py.File(path, "r") as h:
            H = {c: h["/history"][c][:] for c in h["/history"]}
        late = slice(11, None)
        w = np.maximum(np.abs(H["w_ext"]), 1e-300)
        load = max(np.abs(H["load"]).max(), 1e-300)
        print(f"{path} | {np.abs(H['energy_error'][late]).max():.1e} | {np.abs(H['internal_error'][late]).max():.1e}"
              f" | {H['w_damped'][-1] / w[-1]:.1e} | {(H['w_kinetic'][late] / w[late]).max():.1e}"
              f" | {H['tension'].max() / load:.1e} | {H['release_force'].max() / load:.1e}"
              f" | {H['fn_mismatch'].max() / max(H['fn_sum'].max(), 1e-300):.1e}"
              f" | {H['penetration'].max():.1e} | {int(H['events_inside'][-1])} | {int(H['unsettled'][-1])}"
              f" | {int(H['inconsistent'][-1])} | {int((H['limiter'] == 7).sum())}")


def windows(paths):
    for path in paths:
        H = loading(path)
        lam = H["stroke"] / H["target"]  # lambda of the loading
        out = [f"{n}: {np.min(lam[n:] - lam[:-n]):.1e}" for n in (100, 300, 1000) if len(lam) > n]
        print(f"{path}: smallest advance over " + ", ".join(out))


def snaps(paths):
    for path in paths:
        H = loading(path)
        ke = H["w_kinetic"]
        base = np.median(ke[1:])
        peaks = [i for i in range(1, len(ke) - 1) if ke[i] > ke[i - 1] and ke[i] >= ke[i + 1] and ke[i] > 10 * base]
        print(f"{path}: median kinetic energy {base:.1e} N mm/mm; peaks above 10x: " +
              (", ".join(f"U = {H['stroke'][i]:.2f} mm {ke[i]:.1e} ({ke[i] / H['w_ext'][i]:.1e} of w_ext)" for i in peaks) or "none"))
        # The largest load, and whether it is one row's transient: a row that
        # advanced the stroke by less than 1e-4 mm reading more than 5 % above
        # both neighbours (docs/results.md, "The largest load of a thin tube").
        U, P = H["stroke"], H["load"]
        j = int(np.argmax(P))
        if 0 < j < len(P) - 1 and U[j] - U[j - 1] < 1e-4 and P[j] > 1.05 * max(P[j - 1], P[j + 1]):
            print(f"    largest load {P[j]:.1f} N/mm at U = {U[j]:.3f} mm is a transient: its neighbours "
                  f"{P[j - 1]:.1f}, {P[j + 1]:.1f}; kinetic energy {ke[j] / H['w_ext'][j]:.1e} of w_ext; "
                  f"end of loading {P[-1]:.1f}")


def metrics(paths):
    from tubeform_py import tfruns

    for path in paths:
        P, C, _, _ = tfruns.metrics(tfruns.history(path))
        with h5py.File(path, "r") as h:
            a = np.abs(h["/history/energy_error"][11:]).max()
        print(f"{path}: P(1, 2, 3, 4.2) = " + ", ".join(f"{x:.2f}" for x in P) + " N/mm; C/t(2, 3, 4.2) = "
              + ", ".join(f"{x:.3f}" for x in C) + f"; (a) {100 * a:.2f} %")


def limiters(paths):
    for path in paths:
        H = loading(path)
        with h5py.File(path, "r") as h:
            names = h["/history"].attrs["limiter_names"]
        names = (names.decode() if isinstance(names, bytes) else str(names)).split(",")
        codes = H["limiter"][1:].astype(int)
        counts = ", ".join(f"{names[c]} {int((codes == c).sum())}" for c in sorted(set(codes)))
        touch, where, r = names.index("contact"), H["limiter_where"], H["rmin"]
        follow = sum(1 for i in range(2, len(codes) + 1) if H["limiter"][i] == touch == H["limiter"][i - 1]
                     and where[i] == where[i - 1] and r[i] <= 0.01 * r[i - 1])
        print(f"{path}: {len(codes)} loading increments: {counts}; "
              f"{H['friction_iters'][1:].mean():.1f} solves per increment; {follow} touch follow-ups")


def die(paths):
    for path in paths:
        H = loading(path)
        U, x, t, load = H["stroke"], H["die_x"], H["die_turn"], H["load"]
        motion = np.stack([np.diff(U), np.diff(x), np.diff(t)], axis=1)
        unit = motion / np.maximum(np.linalg.norm(motion, axis=1), 1e-300)[:, None]
        turns = [i for i in range(1, len(unit)) if np.abs(unit[i] - unit[i - 1]).max() > 1e-6] + [len(U) - 1]
        print(f"{path}: at the path's points (U, load, die_x, die_turn): " +
              "; ".join(f"{U[i]:.4g} mm, {load[i]:.2f} N/mm, {x[i]:.4g} mm, {t[i]:.4g} deg" for i in turns))
        side = -np.sum(0.5 * (H["tool_fx"][1:] + H["tool_fx"][:-1]) * np.diff(x))
        turn = -np.sum(0.5 * (H["tool_moment"][1:] + H["tool_moment"][:-1]) * np.radians(np.diff(t)))
        put = H["w_ext"][-1]
        late = U >= 0.1
        print(f"  largest |tool_fx| {np.abs(H['tool_fx']).max():.2f} N/mm, |tool_moment| "
              f"{np.abs(H['tool_moment']).max():.1f} N mm/mm, |hold_moment| {np.abs(H['hold_moment']).max():.1f} "
              f"N mm/mm; sideways work {side:.3g} ({side / put:.1%}), the turn's {turn:.3g} ({turn / put:.1%}) of "
              f"{put:.4g} N mm/mm put in; energy balance within {np.abs(H['energy_error'][late]).max():.1e}")


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "compare":
        compare(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 4 and sys.argv[1] == "same":
        sys.exit(same(sys.argv[2], sys.argv[3]))
    elif len(sys.argv) >= 3 and sys.argv[1] == "checks":
        checks(sys.argv[2:])
    elif len(sys.argv) >= 3 and sys.argv[1] == "windows":
        windows(sys.argv[2:])
    elif len(sys.argv) >= 3 and sys.argv[1] == "snaps":
        snaps(sys.argv[2:])
    elif len(sys.argv) >= 3 and sys.argv[1] == "metrics":
        metrics(sys.argv[2:])
    elif len(sys.argv) >= 3 and sys.argv[1] == "limiters":
        limiters(sys.argv[2:])
    elif len(sys.argv) >= 3 and sys.argv[1] == "die":
        die(sys.argv[2:])
    else:
        raise SystemExit(__doc__)
