#!/usr/bin/python3
"""Writes a CalculiX (ccx 2.20) input deck of tubeform's `squaring` scene.

Independent reference model (tools/calculix/README.md): the quarter tube
(x >= 0, y >= 0, outer radius Ro, wall t, centre at the origin) in plane
strain, symmetry u_x = 0 on x = 0 and u_y = 0 on y = 0; the upper V-die as a
band of elements whose every node is prescribed (a rigid tool moving down by
the stroke U); face-to-face penalty contact with Coulomb friction between the
tube's outer surface (slave) and the die's working face (master); the
isotropic J2 large-strain plasticity of ccx (*PLASTIC, NLGEOM) with the
Ludwik flow curve sigma_y = sy + K ep^n tabulated. Step time = stroke (mm)
while loading, so increments are in mm of stroke.

Die (docs/dies.md; tubeform src/tool/tool.cpp BuildVDie): flank
x + y = Ro sqrt(2) from the apex fillet's end to x = reach Ro; the apex
fillet, radius r_apex, centre (0, Ro sqrt(2) - r_apex sqrt(2)), from 45 to
90 degrees (continued a little past x = 0 so the tube's node on the
symmetry line never reaches the face's edge).

    /usr/bin/python3 tools/calculix/deck.py --nt 4 --ntheta 90 --out case.inp
"""
import argparse
import math
import sys

MATERIALS = {  # Huang 2008, Table 1 (as tubeform's src/io/options.cpp)
    'aluminum': dict(e=75000.0, nu=0.34, sy=165.3, k=673.5, n=0.927),
    'copper': dict(e=112000.0, nu=0.34, sy=445.0, k=3628.6, n=0.987),
}
ELEMENTS = ('CPE8R', 'CPE8', 'CPE4', 'CPE4R')
DIE_NODE0 = 100000  # die node and element numbers start above this


def parser():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    a = p.add_argument
    a('--tube_ro', type=float, default=17.5, help='outer radius Ro (mm)')
    a('--tube_t', type=float, default=1.5, help='wall thickness t (mm)')
    a('--material', choices=('aluminum', 'copper', 'custom'), default='aluminum')
    for k in ('e', 'nu', 'sy', 'k', 'n'):
        a('--material_' + k, type=float, default=None, help='override of the preset (custom: required)')
    a('--friction_mu', type=float, default=0.05, help='Coulomb coefficient')
    a('--die_r_apex', type=float, default=3.0, help='apex fillet radius (mm)')
    a('--die_reach', type=float, default=1.3, help='the flank runs to x = reach * Ro')
    a('--stroke', type=float, default=4.2, help='final stroke U (mm)')
    a('--unload', choices=('withdraw', 'none'), default='withdraw', help='withdraw: the die goes back to U = 0')
    a('--report', default='1,2,3', help='strokes (mm) where a step ends (exact values there); the final stroke is added')
    a('--nt', type=int, default=4, help='elements through the wall')
    a('--ntheta', type=int, default=90, help='elements around the quarter')
    a('--element', choices=ELEMENTS, default='CPE8R')
    a('--dumax', type=float, default=0.05, help='largest increment (mm of stroke)')
    a('--du0', type=float, default=None, help='first increment (default dumax / 4)')
    a('--direct', action='store_true', help='fixed increments of dumax (no automatic incrementation)')
    a('--unload_dumax', type=float, default=None, help='largest increment while withdrawing (default dumax)')
    a('--unload_cutbacks', type=int, default=12, help='cut-backs allowed per increment while withdrawing')
    a('--penalty', type=float, default=1e6, help='normal contact stiffness (MPa/mm, pressure per overclosure)')
    a('--stick_slope', type=float, default=None, help='friction stick slope (MPa/mm; default penalty / 10)')
    a('--field_tol', type=float, default=None,
      help='ccx residual criterion R_n (largest residual / average force; ccx default 0.005)')
    a('--table_tol', type=float, default=0.02, help='flow curve table: largest interpolation error (MPa)')
    a('--table_epmax', type=float, default=1.0, help='flow curve table: last plastic strain (flat beyond)')
    a('--die_narc', type=int, default=48, help='die faces along the apex fillet (45 degrees)')
    a('--die_hface', type=float, default=None, help='die face length along the flank (mm; default outer element size / 2)')
    a('--frd', action='store_true', help='also write U, S, PEEQ to the .frd at every increment (ParaView, cgx)')
    a('--out', default='-', help='output .inp (- for stdout)')
    return p


def material(args):
    m = dict(MATERIALS.get(args.material, {}))
    for k in ('e', 'nu', 'sy', 'k', 'n'):
        v = getattr(args, 'material_' + k)
        if v is not None:
            m[k] = v
        if k not in m:
            sys.exit(f'deck.py: --material custom needs --material_{k}')
    return m


def flow_table(m, tol, epmax):
    """(sigma_y, ep) pairs of the Ludwik curve, piecewise linear within tol (MPa) of it up to epmax (flat beyond).

    The points are placed so that the chord of every interval stays within tol of the concave curve: the first
    at e1 with K e1^n c(n) = tol (c(n) = max_x x^n - x, the chord error of x^n on [0, 1]), then steps
    sqrt(8 tol / |f''(a)|) (f'' = K n (n - 1) ep^(n - 2) shrinks with ep, so each interval is within tol).
    The first point is not below ep = 1e-10 (for n = 0.3 the chord misses by up to 0.2 MPa on [0, 1e-10])."""
    k, n = m['k'], m['n']
    pts = [(m['sy'], 0.0)]
    if k <= 0 or n <= 0 or n >= 1:  # linear or no hardening (or convex): the two ends suffice for n in {0, 1}
        steps = 1 if n in (0.0, 1.0) or k <= 0 else 400
        return pts + [(m['sy'] + k * (epmax * j / steps) ** n, epmax * j / steps) for j in range(1, steps + 1)]
    c = n ** (n / (1 - n)) - n ** (1 / (1 - n))
    ep = max((tol / (k * c)) ** (1 / n), 1e-10)  # below 1e-10 of plastic strain nothing depends on the curve
    while ep < epmax:
        pts.append((m['sy'] + k * ep ** n, ep))
        ep += math.sqrt(8 * tol / (k * n * (1 - n) * ep ** (n - 2)))
    pts.append((m['sy'] + k * epmax ** n, epmax))
    return pts


def table_error(m, table):
    """Largest |linear interpolation - Ludwik| (MPa) sampled inside the table's intervals."""
    err = 0.0
    for (s0, e0), (s1, e1) in zip(table, table[1:]):
        for f in (0.1, 0.25, 0.4, 0.5, 0.6, 0.75, 0.9):
            e = e0 + f * (e1 - e0)
            err = max(err, abs(s0 + f * (s1 - s0) - (m['sy'] + m['k'] * e ** m['n'])))
    return err


def tube_mesh(ro, t, nt, nth, quadratic):
    """Structured quarter annulus. Returns nodes {id: (x, y)}, elements [(id, [nodes])], node sets."""
    ri = ro - t
    nr, na = (2 * nt + 1, 2 * nth + 1) if quadratic else (nt + 1, nth + 1)
    step = 2 if quadratic else 1
    ids, nodes = {}, {}
    for j in range(na):
        th = 0.5 * math.pi * j / (na - 1)
        c, s = (1.0, 0.0) if j == 0 else (0.0, 1.0) if j == na - 1 else (math.cos(th), math.sin(th))
        for i in range(nr):
            if quadratic and i % 2 == 1 and j % 2 == 1:
                continue  # centre of a serendipity element
            r = ri + t * i / (nr - 1)
            n = len(nodes) + 1
            ids[i, j] = n
            nodes[n] = (r * c, r * s)
    elements = []
    for b in range(nth):
        for a in range(nt):
            i, j = step * a, step * b
            # counter-clockwise: (r, th) -> (r+, th) -> (r+, th+) -> (r, th+); face S2 = outer arc
            con = [ids[i, j], ids[i + step, j], ids[i + step, j + step], ids[i, j + step]]
            if quadratic:
                con += [ids[i + 1, j], ids[i + 2, j + 1], ids[i + 1, j + 2], ids[i, j + 1]]
            elements.append((len(elements) + 1, con))
    sets = {
        'NOUT': [ids[nr - 1, j] for j in range(na)],  # from the x axis to the y axis
        'NINN': [ids[0, j] for j in range(na)],
        'NY0': [ids[i, 0] for i in range(nr)],
        'NX0': [ids[i, na - 1] for i in range(nr)],
    }
    outer_elems = [e for e, _ in elements[nt - 1::nt]]
    return nodes, elements, sets, outer_elems


def die_profile(ro, r_apex, reach, narc, hface):
    """Points along the die's working face from x < 0 (apex) to the flank's end, with unit normals into the die."""
    s2 = math.sqrt(2.0)
    h = ro * s2
    pts = []
    if r_apex > 0:
        cy = h - r_apex * s2
        dth = 0.25 * math.pi / narc
        for k in range(narc + 2, 0, -1):  # two faces past x = 0, then 90 -> 45 degrees
            th = 0.25 * math.pi + k * dth
            pts.append(((r_apex * math.cos(th), cy + r_apex * math.sin(th)), (math.cos(th), math.sin(th))))
        a = (r_apex / s2, cy + r_apex / s2)
    else:
        a = (-hface / s2, h + hface / s2)  # sharp apex: the flank from just past x = 0
    b = (reach * ro, h - reach * ro)
    length = math.hypot(b[0] - a[0], b[1] - a[1])
    nfl = max(2, int(math.ceil(length / hface)))
    for k in range(nfl + 1):
        f = k / nfl
        pts.append(((a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])), (1 / s2, 1 / s2)))
    return pts


def fmt_set(name, items, kind='NSET'):
    out = [f'*{kind}, {kind}={name}']
    for k in range(0, len(items), 12):
        out.append(', '.join(str(v) for v in items[k:k + 12]))
    return out


def strokes(args):
    marks = sorted({float(v) for v in args.report.split(',') if v.strip() and 0 < float(v) < args.stroke - 1e-9})
    return marks + [args.stroke]


def build(args):
    m = material(args)
    quadratic = args.element.startswith('CPE8')
    nodes, elements, sets, outer_elems = tube_mesh(args.tube_ro, args.tube_t, args.nt, args.ntheta, quadratic)
    hout = 0.5 * math.pi * args.tube_ro / args.ntheta
    hface = args.die_hface or 0.5 * hout
    prof = die_profile(args.tube_ro, args.die_r_apex, args.die_reach, args.die_narc, hface)
    table = flow_table(m, args.table_tol, args.table_epmax)
    if len(table) > 200:  # ccx (plcopy.f) resamples longer curves on 200 equal steps of ep: far too coarse near 0
        sys.exit(f'deck.py: the flow curve needs {len(table)} points for --table_tol {args.table_tol}; '
                 'ccx takes at most 200 (raise --table_tol or lower --table_epmax)')
    stick = args.stick_slope if args.stick_slope is not None else 0.1 * args.penalty
    L = ['** tubeform squaring scene, CalculiX reference deck written by tools/calculix/deck.py',
         '** ' + ' '.join(sys.argv[1:]),
         f'** material E={m["e"]} nu={m["nu"]} sy={m["sy"]} K={m["k"]} n={m["n"]}; flow table {len(table)} points, '
         f'largest interpolation error {table_error(m, table):.3g} MPa',
         '*HEADING', 'tubeform squaring reference (quarter tube, upper V-die)', '*NODE, NSET=NTUBE']
    L += [f'{n}, {x:.12g}, {y:.12g}' for n, (x, y) in nodes.items()]
    # Die: a band of 4-node elements one millimetre deep behind the working face.
    depth = 1.0
    L.append('*NODE, NSET=NDIE')
    nprof = len(prof)
    for k, ((x, y), (mx, my)) in enumerate(prof):
        L.append(f'{DIE_NODE0 + 1 + k}, {x:.12g}, {y:.12g}')
        L.append(f'{DIE_NODE0 + 1 + nprof + k}, {x + depth * mx:.12g}, {y + depth * my:.12g}')
    L.append(f'*ELEMENT, TYPE={args.element}, ELSET=TUBE')
    L += [f'{e}, ' + ', '.join(str(v) for v in con) for e, con in elements]
    L.append('*ELEMENT, TYPE=CPE4, ELSET=DIE')
    for k in range(nprof - 1):
        a, b = DIE_NODE0 + 1 + k, DIE_NODE0 + 2 + k
        L.append(f'{DIE_NODE0 + 1 + k}, {a}, {b}, {b + nprof}, {a + nprof}')  # S1 = working face
    for name, items in sets.items():
        L += fmt_set(name, items)
    L += fmt_set('NDREF', [DIE_NODE0 + 1])
    L += ['*SURFACE, NAME=SOUT, TYPE=ELEMENT'] + [f'{e}, S2' for e in outer_elems]
    L += ['*SURFACE, NAME=SDIE, TYPE=ELEMENT'] + [f'{DIE_NODE0 + 1 + k}, S1' for k in range(nprof - 1)]
    L += ['*MATERIAL, NAME=TUBE', '*ELASTIC', f'{m["e"]}, {m["nu"]}', '*PLASTIC']
    L += [f'{s:.10g}, {e:.10g}' for s, e in table]
    L += ['*MATERIAL, NAME=DIE', '*ELASTIC', f'{10 * m["e"]}, 0.3',
          '*SOLID SECTION, ELSET=TUBE, MATERIAL=TUBE', '1.', '*SOLID SECTION, ELSET=DIE, MATERIAL=DIE', '1.',
          '*SURFACE INTERACTION, NAME=CI', '*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR', f'{args.penalty:g}']
    if args.friction_mu > 0:
        L += ['*FRICTION', f'{args.friction_mu:g}, {stick:g}']
    L += ['*CONTACT PAIR, INTERACTION=CI, TYPE=SURFACE TO SURFACE', 'SOUT, SDIE',
          '*BOUNDARY', 'NX0, 1, 1, 0.', 'NY0, 2, 2, 0.', 'NDIE, 1, 1, 0.']
    du0 = args.du0 or 0.25 * args.dumax
    u_prev = 0.0
    targets = [(u, 0) for u in strokes(args)]
    if args.unload == 'withdraw':
        targets.append((0.0, 1))
    for u, stage in targets:
        span = abs(u - u_prev)
        dmax = args.dumax if stage == 0 else (args.unload_dumax or args.dumax)
        dmax = min(dmax, span)
        first = dmax if args.direct else min(du0, dmax)
        L += [f'** stage {stage}: die to U = {u:g} mm', '*STEP, NLGEOM, INC=100000',
              '*STATIC' + (', DIRECT' if args.direct else ''), f'{first:.8g}, {span:.8g}, {1e-6 * span:.8g}, {dmax:.8g}']
        if args.field_tol:
            L += ['*CONTROLS, PARAMETERS=FIELD', f'{args.field_tol:g}, {2 * args.field_tol:g}']
        if stage == 1 and args.unload_cutbacks != 5:
            # releasing the die with friction makes the contact set chatter: allow more cut-backs (ccx default 5)
            L += ['*CONTROLS, PARAMETERS=TIME INCREMENTATION', f'4, 8, 9, 16, 10, 4, 0, {args.unload_cutbacks}']
        L += ['*BOUNDARY', f'NDIE, 2, 2, {-u:.10g}',
              '*NODE PRINT, NSET=NDIE, TOTALS=ONLY, FREQUENCY=1', 'RF',
              '*NODE PRINT, NSET=NDREF', 'U', '*NODE PRINT, NSET=NOUT', 'U']
        if args.frd:  # one FREQUENCY governs every output request of a step: print and file alike
            L += ['*NODE FILE', 'U', '*EL FILE', 'S, PEEQ']
        L.append('*END STEP')
        u_prev = u
    return '\n'.join(L) + '\n'


def main(argv=None):
    args = parser().parse_args(argv)
    if args.nt < 1 or args.ntheta < 2:
        sys.exit('deck.py: --nt >= 1 and --ntheta >= 2')
    text = build(args)
    if args.out == '-':
        sys.stdout.write(text)
    else:
        with open(args.out, 'w') as f:
            f.write(text)


if __name__ == '__main__':
    main()
