#!/usr/bin/python3
"""Generates, runs and post-processes one CalculiX case of the squaring scene.

    /usr/bin/python3 tools/calculix/run.py --name al_4x90 [deck.py options]
    /usr/bin/python3 tools/calculix/run.py --name al_4x90 --post      (parse an existing run again)

Writes under --dir (default results/ccx/NAME/): NAME.inp (deck.py), the ccx
output (NAME.dat, NAME.log, ...), NAME.csv (one row per converged increment:
stroke, load, c_over_t, x_max, y_max, deviation_ratio (C1/C2 = x_max / y_max,
as tubeform's history), stage, ...) and
NAME.json (the summary: loads at the step-end strokes, C/t, springback, wall
time). ccx runs on one core (OMP_NUM_THREADS=1 and ccx's CCX_NPROC_*) under
`nice -n 5`.

From the .dat file per increment: the die's total reaction (*NODE PRINT,
TOTALS=ONLY on all die nodes), the die's displacement (stroke), the outer
surface nodes' displacements. Load = punch load on the full tube per unit
length = -2 x the quarter's vertical die reaction / plane-strain thickness
(1 in the deck). Shape metrics: shape.py (tubeform's rules); a node touches
the die when its gap is <= --ctol (default 1e-3 t; see README.md).
"""
import json
import math
import os
import re
import subprocess
import sys
import time

import deck  # this folder's own modules (the folder of the running script, or put on the path by its importer)
import shape

COLUMNS = ('stroke', 'load', 'c_over_t', 'x_max', 'y_max', 'deviation_ratio', 'stage', 'time',
           'n_contact', 'n_contact_apex', 'fx')
HEADER_RE = re.compile(r'^\s*(total force|displacements)\s*\(.*\) for set (\S+) and time\s+(\S+)')


def ccx_version():
    try:
        out = subprocess.run(['dpkg-query', '-W', '-f=${Version}', 'calculix-ccx'], capture_output=True, text=True)
        return 'ccx ' + (out.stdout.strip() or '?') + ' (Debian calculix-ccx)'
    except OSError:
        return 'ccx ?'


def read_inp(path):
    """Node coordinates and node sets of a deck (the plain format deck.py writes)."""
    nodes, sets, mode, name, thickness = {}, {}, None, None, 1.0
    with open(path) as f:
        lines = f.read().splitlines()
    for k, line in enumerate(lines):
        if line.startswith('**'):
            continue
        if line.startswith('*'):
            up = line.upper().replace(' ', '')
            mode = None
            if up.startswith('*NODE,') or up == '*NODE':
                mode = 'node'
            elif up.startswith('*NSET,'):
                mode, name = 'nset', re.search(r'NSET=([^,]+)', up).group(1)
                sets[name] = []
            elif up.startswith('*SOLIDSECTION') and 'ELSET=TUBE' in up:
                thickness = float(lines[k + 1].split(',')[0])
            continue
        if mode == 'node':
            v = line.split(',')
            nodes[int(v[0])] = (float(v[1]), float(v[2]))
        elif mode == 'nset':
            sets[name] += [int(v) for v in line.split(',') if v.strip()]
    return nodes, sets, thickness


def read_dat(path):
    """Records, one per printed increment: time, die force (fx, fy), die displacement, {node: (ux, uy)} of NOUT."""
    recs, cur, block = [], None, None
    with open(path) as f:
        for line in f:
            m = HEADER_RE.match(line)
            if m:
                kind, name, t = m.group(1), m.group(2).upper(), float(m.group(3))
                if kind == 'total force':
                    cur = {'time': t, 'out': {}}
                    recs.append(cur)
                block = (kind, name)
                continue
            v = line.split()
            if not v or cur is None or block is None:
                continue
            if block[0] == 'total force':
                cur['force'] = (float(v[0]), float(v[1]))
                block = None
            elif block[1] == 'NDREF':
                cur['die_u'] = (float(v[1]), float(v[2]))
            elif block[1] == 'NOUT':
                cur['out'][int(v[0])] = (float(v[1]), float(v[2]))
    return [r for r in recs if 'force' in r and 'die_u' in r and r['out']]


def post(inp, dat, ro, t, r_apex, reach, stroke_final, ctol=0.0):
    """Rows of COLUMNS from a finished ccx run."""
    nodes, sets, thick = read_inp(inp)
    outer = sets['NOUT']
    die = shape.VDie(ro, r_apex, reach)
    rows, ends = [], None
    for r in read_dat(dat):
        U = -r['die_u'][1]
        stage = 0 if r['time'] <= stroke_final * (1 + 1e-9) else 1
        pts = shape.sort_by_angle([(nodes[n][0] + r['out'][n][0], nodes[n][1] + r['out'][n][1], n) for n in outer])
        xm, ym, dev = shape.extents(pts)
        c, touch, seg = 0.0, [], []
        if stage == 0:
            c, ends, touch, seg = shape.loaded_gap(pts, die, U, ctol=ctol)
        else:
            c = shape.chord_gap(pts, ends)
            touch = [int(die.project(p[0], p[1], U)[0] <= ctol) for p in pts]
            seg = [die.project(p[0], p[1], U)[1] for p in pts]
        n_apex = sum(1 for a, s in zip(touch, seg) if a and s == die.apex)
        rows.append(dict(stroke=U, load=-2.0 * r['force'][1] / thick, c_over_t=c / t, x_max=xm, y_max=ym,
                         deviation_ratio=dev, stage=stage, time=r['time'], n_contact=sum(touch),
                         n_contact_apex=n_apex, fx=-2.0 * r['force'][0] / thick))
    return rows


def at_stroke(rows, u, key='load'):
    """Value at stroke u of the loading rows (exact when an increment ends there, else linear interpolation)."""
    load = [r for r in rows if r['stage'] == 0]
    for a, b in zip(load, load[1:]):
        if abs(b['stroke'] - u) < 1e-9:
            return b[key]
        if a['stroke'] < u < b['stroke']:
            f = (u - a['stroke']) / (b['stroke'] - a['stroke'])
            return a[key] + f * (b[key] - a[key])
    return math.nan


def summary(rows, args, wall):
    load = [r for r in rows if r['stage'] == 0]
    last = load[-1] if load else {}
    final = rows[-1] if rows else {}
    s = {'name': args.name, 'final_stroke': last.get('stroke'), 'final_load': last.get('load'),
         'wall_s': wall, 'increments': len(rows)}
    for u in [1.0, 2.0, 3.0, 4.2, 5.0]:
        if u <= args.stroke + 1e-9:
            s[f'load_{u:g}'] = at_stroke(rows, u)
    for u in [2.0, 3.0]:
        if u <= args.stroke + 1e-9:
            s[f'c_over_t_{u:g}'] = at_stroke(rows, u, 'c_over_t')
    for k in ('c_over_t', 'x_max', 'y_max', 'deviation_ratio'):
        s['loaded_' + k] = last.get(k)
        if args.unload != 'none':
            s['unloaded_' + k] = final.get(k)
    return s


def c1_over_c2_lines(lines):
    """The lines of a CSV of COLUMNS (comments, header, rows) with deviation_ratio recomputed from the row's own
    x_max and y_max as C1/C2 = x_max / y_max: a CSV written before this script wrote C1/C2 held the paper's
    min(C1, C2) / max(C1, C2) there (converge.py --save passes a run's CSV through this)."""
    out, keys = [], None
    for line in lines:
        if line.startswith('#') or not line.strip():
            out.append(line)
            continue
        v = line.rstrip('\n').split(',')
        if keys is None:
            keys = v
        else:
            x, y = float(v[keys.index('x_max')]), float(v[keys.index('y_max')])
            v[keys.index('deviation_ratio')] = f'{x / y:.8g}'
        out.append(','.join(v) + '\n')
    return out


def write_csv(path, rows, header_lines):
    with open(path, 'w') as f:
        for h in header_lines:
            f.write('# ' + h + '\n')
        f.write(','.join(COLUMNS) + '\n')
        for r in rows:
            f.write(','.join(str(r[c]) if c in ('stage', 'n_contact', 'n_contact_apex') else f'{r[c] + 0.0:.8g}'
                             for c in COLUMNS) + '\n')


def ccx_stats(log):
    """Increments, attempts (cut-backs) and Newton iterations in a ccx log; whether it finished."""
    try:
        text = open(log, errors='replace').read()
    except OSError:
        return {}
    return {'attempts': len(re.findall(r'^ increment \d+ attempt', text, re.M)),
            'cutbacks': len(re.findall(r'^ increment \d+ attempt [2-9]', text, re.M)),
            'iterations': len(re.findall(r'^ iteration \d+', text, re.M)),
            'finished': 'Job finished' in text}


def main(argv=None):
    p = deck.parser()
    p.description = __doc__
    p.add_argument('--name', required=True, help='case name (files NAME.*)')
    p.add_argument('--dir', default=None, help='run directory (default results/ccx/NAME)')
    p.add_argument('--post', action='store_true', help='only post-process an existing run')
    p.add_argument('--ctol', type=float, default=None,
                   help='a node touches the die when its gap is <= CTOL (mm; default 1e-3 t: the outer faces are curved, '
                        'so a face pressed by the penalty can leave its nodes up to ~1e-3 mm off the die)')
    p.add_argument('--csv', default=None, help='also copy the CSV here (with a header comment)')
    args = p.parse_args(argv)
    if args.ctol is None:
        args.ctol = 1e-3 * args.tube_t
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    d = args.dir or os.path.join(root, 'results', 'ccx', args.name)
    os.makedirs(d, exist_ok=True)
    inp, dat, log = (os.path.join(d, args.name + e) for e in ('.inp', '.dat', '.log'))
    wall = None
    deck_argv = [a for a in (argv if argv is not None else sys.argv[1:])]
    if not args.post:
        args.out = inp
        sys.argv = ['deck.py'] + deck_argv  # the deck's header records the command
        with open(inp, 'w') as f:
            f.write(deck.build(args))
        env = dict(os.environ, OMP_NUM_THREADS='1', CCX_NPROC_STIFFNESS='1', CCX_NPROC_RESULTS='1',
                   CCX_NPROC_EQUATION_SOLVER='1', NUMBER_OF_PROCESSORS='1')
        t0 = time.time()
        with open(log, 'w') as f:
            rc = subprocess.run(['nice', '-n', '5', 'ccx', '-i', args.name], cwd=d, env=env, stdout=f,
                                stderr=subprocess.STDOUT).returncode
        wall = time.time() - t0
        with open(os.path.join(d, 'wall_s'), 'w') as f:
            f.write(f'{wall:.1f}\n')
        if rc != 0:
            print(f'run.py: ccx exited with {rc}; see {log}', file=sys.stderr)
    elif os.path.exists(os.path.join(d, 'wall_s')):
        wall = float(open(os.path.join(d, 'wall_s')).read())
    stats = ccx_stats(log)
    rows = post(inp, dat, args.tube_ro, args.tube_t, args.die_r_apex, args.die_reach, args.stroke, args.ctol)
    s = summary(rows, args, wall)
    s.update(stats)
    complete = bool(rows) and stats.get('finished') and abs(s['final_stroke'] - args.stroke) < 1e-6
    s['complete'] = bool(complete)
    m = deck.material(args)
    stick = args.stick_slope if args.stick_slope is not None else 0.1 * args.penalty
    header = [f'CalculiX reference of the tubeform squaring scene: {ccx_version()}',
              f'case: Ro {args.tube_ro} t {args.tube_t} E {m["e"]} nu {m["nu"]} sy {m["sy"]} K {m["k"]} n {m["n"]} '
              f'mu {args.friction_mu} r_apex {args.die_r_apex} stroke {args.stroke} unload {args.unload}',
              f'mesh {args.nt} x {args.ntheta} {args.element}; increments <= {args.dumax} mm of stroke'
              + (' (fixed)' if args.direct else ' (automatic)') + f'; penalty {args.penalty:g} MPa/mm, '
              f'stick slope {stick:g} MPa/mm; flow table tol {args.table_tol} MPa; contact gap <= {args.ctol} mm',
              'command: /usr/bin/python3 tools/calculix/run.py ' + ' '.join(a for a in deck_argv if a != '--post'),
              f'wall time {wall if wall is None else round(wall, 1)} s on one core; {stats}',
              'load: punch load on the full tube (N/mm); stage 0 loading, 1 withdrawing (last row: sprung back)']
    write_csv(os.path.join(d, args.name + '.csv'), rows, header)
    if args.csv:
        write_csv(args.csv, rows, header)
    with open(os.path.join(d, args.name + '.json'), 'w') as f:
        json.dump(s, f, indent=1)
    print(json.dumps(s))
    return 0 if complete else 1


if __name__ == '__main__':
    sys.exit(main())
