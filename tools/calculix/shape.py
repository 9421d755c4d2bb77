#!/usr/bin/python3
"""Shape metrics of a pressed tube exactly as tubeform measures them.

A transcription of tubeform's rules (src/scenes/press.cpp PressScene::Shape,
src/metrics/shape.cpp, src/tool/tool.cpp Tool::Project, BuildVDie), written
again in Python so the CalculiX reference can be measured the same way:

- x_max, y_max: largest x and y of the outer-surface nodes (C1 across the
  press, C2 along it); deviation ratio C1 / C2 = x_max / y_max (the history's
  deviation_ratio; the paper's, min(C1, C2) / max(C1, C2), follows from the two).
- C/t while loading: the outer nodes sorted by angle; a node touches the die
  when its gap to the die is <= ctol (tubeform: its contact flag); its segment
  is the die segment nearest to it (smallest |gap|; the apex fillet is segment
  0, the flank 1). The side runs between the outermost nodes touching the
  flank (coordinate s along the flank line, s = 0 at the flank's apex end,
  s < 0 towards the corner); when any node touches the fillet the side reaches
  s = 0 (its end node: the node nearest to s = 0). C = the largest gap to the
  flank line over the nodes with s in the side's range, 0 if none is positive.
- C/t after unloading: the largest gap between the chord through the side's
  two end nodes (remembered at the last loading state) and the nodes between
  them, measured towards the origin (0 for a straight or outward-bowed side).

    /usr/bin/python3 tools/calculix/shape.py --validate RESULT.h5   (against tubeform's own c_over_t)
"""
import argparse
import math
import sys

S2 = math.sqrt(2.0)
ON_SEGMENT = 1e-12


class VDie:
    """tubeform's V-die (no parting face) at stroke U: segments [fillet (if r_apex > 0), flank]."""

    def __init__(self, ro, r_apex, reach=1.3):
        h = ro * S2
        self.segments = []
        start = (0.0, h)
        if r_apex > 0:
            c = (0.0, h - r_apex * S2)
            self.segments.append(('arc', c, r_apex, math.pi / 4, math.pi / 2))
            start = (r_apex / S2, c[1] + r_apex / S2)
        self.segments.append(('line', start, (reach * ro, h - reach * ro), (-1 / S2, -1 / S2)))
        self.flank = len(self.segments) - 1
        self.apex = 0 if r_apex > 0 else -1

    def project(self, x, y, stroke):
        """(gap, segment) of tubeform's Tool::Project: the segment with the smallest |gap|."""
        best = (1e300, -1)
        for k, seg in enumerate(self.segments):
            if seg[0] == 'line':
                _, a, b, n = seg
                ax, ay, bx, by = a[0], a[1] - stroke, b[0], b[1] - stroke
                abx, aby = bx - ax, by - ay
                t = ((x - ax) * abx + (y - ay) * aby) / (abx * abx + aby * aby)
                if t < -ON_SEGMENT or t > 1 + ON_SEGMENT:
                    continue
                t = min(1.0, max(0.0, t))
                px, py = ax + t * abx, ay + t * aby
                gap = (x - px) * n[0] + (y - py) * n[1]
            else:
                _, c, r, t0, t1 = seg
                dx, dy = x - c[0], y - (c[1] - stroke)
                d = math.hypot(dx, dy)
                if d == 0:
                    continue
                ang = math.atan2(dy, dx)
                while ang < t0:
                    ang += 2 * math.pi
                while ang >= t0 + 2 * math.pi:
                    ang -= 2 * math.pi
                if ang > t1 + ON_SEGMENT:
                    continue
                gap = r - d  # concave: normal -e, gap = (x - c - r e) . (-e)
            if abs(gap) < abs(best[0]):
                best = (gap, k)
        return best

    def flank_line(self, stroke):
        """(a, n, l) of the flank line at stroke U: a its apex end, n into the tube, l = n turned by -90 deg."""
        _, a, _, n = self.segments[self.flank]
        return (a[0], a[1] - stroke), n, (n[1], -n[0])


def along(p, line):
    a, _, l = line
    return (p[0] - a[0]) * l[0] + (p[1] - a[1]) * l[1]


def gap_to(p, line):
    a, n, _ = line
    return (p[0] - a[0]) * n[0] + (p[1] - a[1]) * n[1]


def sort_by_angle(points):
    """points: list of (x, y, id); sorted from the x axis to the y axis."""
    return sorted(points, key=lambda p: math.atan2(p[1], p[0]))


def extents(points):
    """x_max (C1), y_max (C2) and the deviation ratio C1 / C2 (tubeform's OuterExtents: 1 for a point at the centre)."""
    xm = max(p[0] for p in points)
    ym = max(p[1] for p in points)
    return xm, ym, (xm / ym if ym > 0 else 1.0)


def loaded_gap(points, die, stroke, contact=None, ctol=0.0):
    """C (mm) while the die acts, and the ids of the side's end nodes (None if no flank contact).

    points sorted by angle; contact: per point 0/1 (tubeform's flag) or None to take gap <= ctol."""
    seg, touch = [], []
    for k, p in enumerate(points):
        g, s = die.project(p[0], p[1], stroke)
        seg.append(s)
        touch.append(contact[k] if contact is not None else int(g <= ctol))
    line = die.flank_line(stroke)
    smin, smax, ends, apex = 1e300, -1e300, [0, 0], False
    for k, p in enumerate(points):
        if not touch[k]:
            continue
        apex = apex or seg[k] == die.apex
        if seg[k] != die.flank:
            continue
        s = along(p, line)
        if s < smin:
            smin, ends[0] = s, k
        if s > smax:
            smax, ends[1] = s, k
    if smax < smin:
        return 0.0, None, touch, seg
    if apex:
        nearest = min(range(len(points)), key=lambda k: abs(along(points[k], line)))
        if 0.0 < smin:
            smin, ends[0] = 0.0, nearest
        if 0.0 > smax:
            smax, ends[1] = 0.0, nearest
    gmax = max((gap_to(p, line) for p in points if smin <= along(p, line) <= smax), default=-1e300)
    return max(gmax, 0.0), (points[ends[0]][2], points[ends[1]][2]), touch, seg


def chord_gap(points, end_ids):
    """C (mm) after unloading: the largest gap towards the origin from the chord through the two end nodes."""
    idx = {p[2]: k for k, p in enumerate(points)}
    if end_ids is None or end_ids[0] not in idx or end_ids[1] not in idx:
        return 0.0
    first, last = sorted((idx[end_ids[0]], idx[end_ids[1]]))
    a, b = points[first], points[last]
    lx, ly = b[0] - a[0], b[1] - a[1]
    length = math.hypot(lx, ly)
    if last - first < 2 or not length > 0:
        return 0.0
    n = (-ly / length, lx / length)
    if n[0] * -a[0] + n[1] * -a[1] < 0:
        n = (-n[0], -n[1])
    c = 0.0
    for k in range(first + 1, last):
        c = max(c, (points[k][0] - a[0]) * n[0] + (points[k][1] - a[1]) * n[1])
    return c


def validate(path, tol=1e-9, ctol=None):
    """Recompute C/t, x_max, y_max, C1/C2 of a tubeform result at its output steps from the HDF5 fields and compare.

    ctol None: tubeform's contact flags; a number: contact taken as gap <= ctol (the rule used on CalculiX)."""
    import h5py
    import numpy as np
    with h5py.File(path, 'r') as f:
        opts = f.attrs['options']
        opts = opts.decode() if isinstance(opts, bytes) else str(opts)
        words = opts.split()
        val = lambda k, d: float(words[words.index(k) + 1]) if k in words else d
        ro, t, r_apex = val('-tube_ro', 17.5), val('-tube_t', 1.5), val('-die_r_apex', 3.0)
        x0 = f['/geometry/vertices'][:]
        u = f['/vertex_fields/displacement_u'][:]
        cs = f['/vertex_fields/contact_state'][:]
        lam = f['/time'][:].ravel()
        hist = {k: f['/history/' + k][:] for k in ('stroke', 'stage', 'c_over_t', 'x_max', 'y_max', 'deviation_ratio')}
    outer = np.where(np.abs(np.hypot(x0[:, 0], x0[:, 1]) - ro) < 1e-6 * ro)[0]
    die = VDie(ro, r_apex)
    worst, ends, rows = 0.0, None, []
    for k in range(len(lam)):
        pos = x0 + u[k]
        pts = sort_by_angle([(pos[i, 0], pos[i, 1], int(i)) for i in outer])
        order = {p[2]: j for j, p in enumerate(pts)}
        contact = [0] * len(pts)
        for i in outer:
            contact[order[int(i)]] = int(round(cs[k, i]))
        stage = 0 if lam[k] <= 1 + 1e-12 else 1
        # the history row written with this output step: the same stage and stroke (loading: U = lambda U_final;
        # withdraw: U = (2 - lambda) U_final); the paper's reverse unloading keeps U: only its last state is matched
        cand = [j for j in range(len(hist['stroke'])) if hist['stage'][j] == stage]
        uf = max(hist['stroke'])
        if stage == 1 and max(hist['stroke'][cand]) - min(hist['stroke'][cand]) < 1e-12:
            if k != len(lam) - 1:
                continue
            j = cand[-1]
        else:
            j = min(cand, key=lambda j: abs(hist['stroke'][j] - (lam[k] if stage == 0 else 2 - lam[k]) * uf))
        U = hist['stroke'][j]
        if stage == 0:
            c, ends, _, _ = loaded_gap(pts, die, U, contact=None if ctol is not None else contact, ctol=ctol or 0.0)
        else:
            c = chord_gap(pts, ends)
        xm, ym, dev = extents(pts)
        d = max(abs(c / t - hist['c_over_t'][j]), abs(xm - hist['x_max'][j]), abs(ym - hist['y_max'][j]),
                abs(dev - hist['deviation_ratio'][j]))
        worst = max(worst, d)
        rows.append((lam[k], U, stage, c / t, hist['c_over_t'][j], xm, hist['x_max'][j], d))
    print(f'{"lambda":>8} {"stroke":>8} st {"C/t py":>10} {"C/t tf":>10} {"x_max py":>10} {"x_max tf":>10} {"diff":>9}')
    for r in rows:
        print(f'{r[0]:8.4f} {r[1]:8.4f} {r[2]:2d} {r[3]:10.6f} {r[4]:10.6f} {r[5]:10.5f} {r[6]:10.5f} {r[7]:9.2e}')
    print(f'largest difference {worst:.3g} over {len(rows)} output steps: ' + ('ok' if worst <= tol else 'MISMATCH'))
    return worst <= tol


if __name__ == '__main__':
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('--validate', metavar='H5', required=True, help='tubeform result file (squaring scene)')
    p.add_argument('--tol', type=float, default=1e-9, help='largest difference accepted')
    p.add_argument('--ctol', type=float, default=None, help='take contact as gap <= CTOL (mm) instead of the flags')
    a = p.parse_args()
    sys.exit(0 if validate(a.validate, a.tol, a.ctol) else 1)
