"""Measures shared by the checks of a die on a path of its own (tests/check_die_path.py, check_die_turn.py): the
full model under the rotation hold, the lower die fixed."""
import numpy as np


def balance(t, ro, pivot=(0.0, 0.0)):
    """The tube's equilibrium at every loading row against both dies and the hold (tests/check_hold.py B): the net
    force on the hold (tool_fx + lower_fx) and the dies' moment about the centre less the hold's couple, each as a
    fraction of its bound n_contact (residual + fn_mismatch) (times ro for the moment). The upper die's moment is
    about its pivot, now at pivot + (die_x, -2 U); the lower die's about the centre. Returns (force, moment, the
    hold's largest couple)."""
    p, U = t["stage"] == 0, t["stroke"]
    bound = (t["n_contact"] * (t["residual"] + t["fn_mismatch"]))[p]
    force = np.abs(t["tool_fx"] + t["lower_fx"])[p]
    px, py = pivot[0] + t["die_x"], pivot[1] - 2 * U
    dies = t["tool_moment"] + px * t["tool_fy"] - py * t["tool_fx"] + t["lower_moment"]
    moment = np.abs(dies - t["hold_moment"])[p]
    f, mo = np.max(force / np.maximum(bound, 1e-300)), np.max(moment / np.maximum(ro * bound, 1e-300))
    return f, mo, np.abs(t["hold_moment"][p]).max()


def at_rows(a, b, rows_a, rows_b, sign, ro, columns=("tool_fx", "lower_fx", "hold_moment")):
    """The largest difference of two presses at matching rows, relative to the load (the load times ro for a moment,
    ro for an extent, the largest w_int for it), `columns` compared with `sign` (-1: a mirror image), the load, the
    extents and w_int as they are. Returns (difference, its column)."""
    load = np.abs(a["load"]).max()
    scales = {"load": (1, load), "x_max": (1, ro), "y_max": (1, ro), "w_int": (1, np.abs(a["w_int"]).max())}
    for c in columns:
        scales[c] = (sign, load * ro if "moment" in c else load)
    d = {c: max(abs(a[c][i] - s * b[c][j]) / v for i, j in zip(rows_a, rows_b)) for c, (s, v) in scales.items()}
    c = max(d, key=d.get)
    return d[c], c
