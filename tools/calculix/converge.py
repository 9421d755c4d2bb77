#!/usr/bin/python3
"""Convergence study of the CalculiX reference: mesh, step size, contact penalty (and the flow table, the
equilibrium tolerance) for the three reference cases, one ccx run at a time.

    /usr/bin/python3 tools/calculix/converge.py --case default --study mesh      (runs what is missing)
    /usr/bin/python3 tools/calculix/converge.py --case default --study all --table   (only prints the tables)
    /usr/bin/python3 tools/calculix/converge.py --case default --save NAME      (NAME's CSV -> tests/reference/calculix/default.csv)

Each run is tools/calculix/run.py under results/ccx/<case>_<label>/; a run whose JSON says it completed is
not run again. A study varies one parameter around the base (middle mesh, base step, base penalty) and
prints, per level, the loads at the reported strokes, C/t, springback and wall time, then the change
between successive levels: the largest relative load change over the loading curve (sampled every 0.1 mm
from U = 0.5 mm, interpolated between increments) and at the reported strokes, and the C/t change.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
# The helper package python/tubeform_py (python/README.md); deck and run are this folder's own modules (the folder of
# the running script is on the path; tools/validate puts it there when it imports this file).
sys.path.insert(0, os.path.join(ROOT, "python"))
import deck  # noqa: E402
import run  # noqa: E402
from tubeform_py import validation as v  # noqa: E402

CASES = {
    'default': dict(args=['--material', 'aluminum', '--tube_ro', '17.5', '--tube_t', '1.5', '--friction_mu', '0.05',
                          '--die_r_apex', '3', '--stroke', '4.2', '--report', '1,2,3'],
                    meshes=[(2, 45), (4, 90), (8, 180)], base_mesh=(4, 90)),
    'thin': dict(args=['--material', 'aluminum', '--tube_ro', '18.5', '--tube_t', '0.5', '--friction_mu', '0.05',
                       '--die_r_apex', '3', '--stroke', '4.2', '--report', '1,2,3'],
                 meshes=[(2, 60), (4, 120), (8, 240)], base_mesh=(4, 120),
                 # with K = 1e6 the static contact iterations stall at U = 1.1-1.3 mm (2x60 and 4x120)
                 base_penalty=1e5),
    'steel': dict(args=['--material', 'custom', '--material_e', '210000', '--material_nu', '0.3', '--material_sy', '350',
                        '--material_k', '500', '--material_n', '0.3', '--tube_ro', '20', '--tube_t', '2',
                        '--friction_mu', '0.1', '--die_r_apex', '3', '--stroke', '5', '--report', '1,2,3,4.2'],
                  meshes=[(2, 45), (4, 90), (8, 180)], base_mesh=(4, 90)),
}


def validation_cases():
    """The tubes of tools/validate (the validation set of docs/accuracy.md) as cases named val_<tube>: three meshes of
    CPE8R, the middle one with 18 elements per bending length sqrt(Ro t) around the quarter (the default
    case's 4 x 90 has 17.5) and at least 90; penalty 1e6 MPa/mm, 1e5 for walls thinner than 1 mm (the
    thin case's stall at 1e6)."""
    import math
    out = {}
    for name, (mat, ro, t, mu, stroke) in v.CASES.items():
        args = ['--tube_ro', f'{ro:g}', '--tube_t', f'{t:g}', '--friction_mu', f'{mu:g}', '--die_r_apex', '3',
                '--stroke', f'{stroke:g}', '--report', ','.join(f'{u:g}' for u in v.reported(name)[:-1])]
        if v.MATERIALS[mat] is None:
            args = ['--material', mat] + args
        else:
            e, nu, sy, k, n = v.MATERIALS[mat]
            args = ['--material', 'custom', '--material_e', f'{e:g}', '--material_nu', f'{nu:g}', '--material_sy',
                    f'{sy:g}', '--material_k', f'{k:g}', '--material_n', f'{n:g}'] + args
        arc = 0.5 * math.pi * (ro - 0.5 * t)
        nth = max(90, 2 * round(9 * arc / math.sqrt(ro * t)))
        out['val_' + name] = dict(args=args, meshes=[(2, nth // 2), (4, nth), (8, 2 * nth)], base_mesh=(4, nth),
                                  base_penalty=1e6 if t >= 1 else 1e5)
    return out


CASES.update(validation_cases())
BASE_STEP = 0.05
STEPS = [0.1, 0.05, 0.025]
PENALTY_FACTORS = [0.1, 1, 10]  # of the case's base penalty


def label(nt, nth, du, k, extra=()):
    s = f'{nt}x{nth}_d{du:g}_k{k:.0e}'.replace('e+0', 'e')
    pairs = zip(extra[0::2], extra[1::2])
    return s + ''.join('_' + (v if o == '--element' else o.lstrip('-').replace('_', '') + v) for o, v in pairs)


def levels(case, study):
    c = CASES[case]
    nt, nth = c['base_mesh']
    BASE_PENALTY = c.get('base_penalty', 1e6)
    if study == 'mesh':
        return [(m[0], m[1], BASE_STEP, BASE_PENALTY, ()) for m in c['meshes']]
    if study == 'step':
        return [(nt, nth, du, BASE_PENALTY, ()) for du in STEPS]
    if study == 'penalty':
        return [(nt, nth, BASE_STEP, f * BASE_PENALTY, ()) for f in PENALTY_FACTORS]
    if study == 'table':  # the flow curve's tabulation (largest interpolation error, MPa; the base: 0.02)
        out = [(nt, nth, BASE_STEP, BASE_PENALTY, ('--table_tol', '0.1')), (nt, nth, BASE_STEP, BASE_PENALTY, ())]
        if len(deck.flow_table(deck.material(deck.parser().parse_args(c['args'])), 0.005, 1.0)) <= 200:
            out.append((nt, nth, BASE_STEP, BASE_PENALTY, ('--table_tol', '0.005')))
        return out
    if study == 'tolerance':  # ccx's equilibrium criterion (largest residual / average force; default 0.005)
        return [(nt, nth, BASE_STEP, BASE_PENALTY, ()), (nt, nth, BASE_STEP, BASE_PENALTY, ('--field_tol', '0.0005'))]
    if study == 'element':
        return [(nt, nth, BASE_STEP, BASE_PENALTY, ()), (nt, nth, BASE_STEP, BASE_PENALTY, ('--element', 'CPE8'))]
    raise SystemExit(f'converge.py: unknown study {study}')


def name_of(case, lev):
    nt, nth, du, k, extra = lev
    return f'{case}_' + label(nt, nth, du, k, extra)


def repost(case, lev):
    """Post-process a finished run again (run.py --post with the same options)."""
    nt, nth, du, k, extra = lev
    name = name_of(case, lev)
    if not os.path.exists(os.path.join(ROOT, 'results', 'ccx', name, name + '.dat')):
        return
    cmd = [sys.executable, os.path.join(HERE, 'run.py'), '--name', name, '--post'] + CASES[case]['args'] + [
        '--nt', str(nt), '--ntheta', str(nth), '--dumax', str(du), '--penalty', f'{k:g}'] + list(extra)
    subprocess.run(cmd, cwd=ROOT, stdout=subprocess.DEVNULL)


def ensure(case, lev, dry=False):
    nt, nth, du, k, extra = lev
    name = name_of(case, lev)
    js = os.path.join(ROOT, 'results', 'ccx', name, name + '.json')
    if os.path.exists(js) and json.load(open(js)).get('complete'):
        return name
    if dry:
        return name
    cmd = [sys.executable, os.path.join(HERE, 'run.py'), '--name', name] + CASES[case]['args'] + [
        '--nt', str(nt), '--ntheta', str(nth), '--dumax', str(du), '--penalty', f'{k:g}'] + list(extra)
    print('converge.py: running ' + ' '.join(cmd[1:]), flush=True)
    subprocess.run(cmd, cwd=ROOT)
    return name


def load_rows(name):
    path = os.path.join(ROOT, 'results', 'ccx', name, name + '.csv')
    if not os.path.exists(path):
        return None, None
    rows = []
    with open(path) as f:
        lines = [line for line in f if not line.startswith('#')]
    keys = lines[0].strip().split(',')
    for line in lines[1:]:
        v = line.strip().split(',')
        rows.append({k: float(x) for k, x in zip(keys, v)})
    js = os.path.join(ROOT, 'results', 'ccx', name, name + '.json')
    return rows, (json.load(open(js)) if os.path.exists(js) else {})


def curve_change(a, b, u_end):
    """Largest |P_b - P_a| / P_b over U = 0.5, 0.6, ... u_end (loading)."""
    worst, at = 0.0, None
    u = 0.5
    while u <= u_end + 1e-9:
        pa, pb = run.at_stroke(a, u), run.at_stroke(b, u)
        if pa == pa and pb == pb and pb != 0:
            d = abs(pb - pa) / abs(pb)
            if d > worst:
                worst, at = d, u
        u = round(u + 0.1, 10)
    return worst, at


def table(case, study):
    c = CASES[case]
    stroke = float(c['args'][c['args'].index('--stroke') + 1])
    marks = [float(v) for v in c['args'][c['args'].index('--report') + 1].split(',')] + [stroke]
    out = [f'### {case}: {study}', '']
    head = '| run | ' + ' | '.join(f'P({u:g})' for u in marks) + \
        ' | C/t(2) | C/t(3) | C/t final | C/t sprung | C1/C2 final | C1/C2 sprung | incr. | wall (s) |'
    out += [head, '|' + '---|' * (head.count('|') - 1)]
    prev, changes = None, []
    for lev in levels(case, study):
        name = name_of(case, lev)
        rows, s = load_rows(name)
        if not rows:
            out.append(f'| {name} | (not run) |')
            prev = None
            continue
        ok = s.get('complete')
        cells = [f'{run.at_stroke(rows, u):.2f}' for u in marks]
        sprung = [r for r in rows if r['stage'] == 1]
        if sprung and abs(sprung[-1]['stroke']) > 1e-9:
            sprung = []  # the withdrawal did not finish
        fin = [r for r in rows if r['stage'] == 0][-1]
        sp = f'{sprung[-1]["c_over_t"]:.4f}' if sprung else '-'
        # C1/C2 from the half-extents: a CSV's deviation_ratio column was min/max before run.py wrote C1/C2
        spd = f'{sprung[-1]["x_max"] / sprung[-1]["y_max"]:.4f}' if sprung else '-'
        out.append(f'| {name}{"" if ok else " (INCOMPLETE)"} | ' + ' | '.join(cells) +
                   f' | {run.at_stroke(rows, 2.0, "c_over_t"):.4f} | {run.at_stroke(rows, 3.0, "c_over_t"):.4f}'
                   f' | {fin["c_over_t"]:.4f} | {sp} | {fin["x_max"] / fin["y_max"]:.4f} | {spd} | {len(rows)}'
                   f' | {s.get("wall_s") or 0:.0f} |')
        if prev is not None:
            pr, pname = prev
            worst, at = curve_change(pr, rows, min(stroke, fin['stroke']))
            at_marks = max(abs(run.at_stroke(rows, u) - run.at_stroke(pr, u)) / run.at_stroke(rows, u) for u in marks)
            dct = max(abs(run.at_stroke(rows, u, 'c_over_t') - run.at_stroke(pr, u, 'c_over_t')) for u in marks)
            psp = [r for r in pr if r['stage'] == 1]
            dsp = abs(sprung[-1]['c_over_t'] - psp[-1]['c_over_t']) if sprung and psp and abs(psp[-1]['stroke']) < 1e-9 \
                else float('nan')
            changes.append(f'- {pname} -> {name}: load {100 * at_marks:.3f} % at the reported strokes, '
                           f'{100 * worst:.3f} % over the curve (largest at U = {at}); C/t {dct:.4f} at the reported '
                           f'strokes, ' + (f'{dsp:.4f} sprung back' if dsp == dsp else 'no sprung-back pair'))
        prev = (rows, name)
    return '\n'.join(out + [''] + changes + [''])


def save(case, name, note=None):
    src = os.path.join(ROOT, 'results', 'ccx', name, name + '.csv')
    dst_dir = os.path.join(ROOT, 'tests', 'reference', 'calculix')
    os.makedirs(dst_dir, exist_ok=True)
    lines = run.c1_over_c2_lines(open(src).read().splitlines(True))
    head = [k for k, line in enumerate(lines) if line.startswith('#')]
    if note:
        lines.insert(head[-1] + 1, f'# note: {note}\n')
    with open(os.path.join(dst_dir, case + '.csv'), 'w') as f:
        f.writelines(lines)
    print(f'converge.py: {src} -> tests/reference/calculix/{case}.csv')


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('--case', choices=sorted(CASES), required=True)
    p.add_argument('--study', default='all', help='mesh, step, penalty, table, tolerance, element or all '
                   '(comma separated)')
    p.add_argument('--table', action='store_true', help='print the tables only (run nothing)')
    p.add_argument('--note', help='with --save: a comment line added to the header')
    p.add_argument('--repost', action='store_true', help='post-process the finished runs again (run nothing)')
    p.add_argument('--save', metavar='NAME', help="copy run NAME's CSV to tests/reference/calculix/CASE.csv")
    a = p.parse_args()
    if a.save:
        save(a.case, a.save, a.note)
        return
    studies = ['mesh', 'step', 'penalty'] if a.study == 'all' else a.study.split(',')
    for st in studies:
        for lev in levels(a.case, st):
            if a.repost:
                repost(a.case, lev)
            else:
                ensure(a.case, lev, dry=a.table)
    for st in studies:
        print(table(a.case, st))


if __name__ == '__main__':
    main()
