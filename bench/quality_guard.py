#!/usr/bin/env python3
"""The quality guard: a fast subset of the shared-data cases, every command, run and checked
against the committed table of expected verdicts and distortions (bench/quality_expected.tsv).

  python3 bench/quality_guard.py [--sa build/bin/sa] [--data ../shared/data] [--jobs 2]
  python3 bench/quality_guard.py --update     # rewrite the table from this run

It needs the Release sa and, beside it, bench_bar_pose (bash scripts/build.sh sa bench_bar_pose).

Each case runs the sa command, then the independent checker (../shared/tools/check_map.py) on
what it wrote. Its verdict is `verified` (exit 0 and the checker agrees), `unverified` (exit 1,
a map written that does not pass), `infeasible` (no solution, named before the solve) or
`exit N`. A run fails the guard when its verdict differs from the table's, when sa and the
checker disagree, or when the maximum or the mean of the case's distortion measure (the
checker's sigma-ratios: conformal sigma_max/sigma_min, isometric max(sigma, 1/sigma)) exceeds
the table's by more than --tolerance (10%). Better results pass and are listed; the table
changes only in a commit that says why (--update). Exit status 0 when every case passes (or
the shared data is absent: nothing to guard), 1 otherwise.
"""
import argparse
import concurrent.futures
import csv
import json
import os
import subprocess
import sys
import tempfile

from bench_common import fmt, run_measured

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
EXPECTED = os.path.join(HERE, 'quality_expected.tsv')
FIELDS = ['case', 'verdict', 'measure', 'max', 'mean']


def cases(data, work, bin_dir):
    """(name, sa arguments, output file, checker arguments, measure) of every guarded case."""
    def out(name, ext):
        return os.path.join(work, name.replace('/', '-') + ext)

    tlc = lambda name: os.path.join(data, 'tlc', name, 'input')
    deform = lambda name, f: os.path.join(data, 'deform', name, name + f)
    result = []
    for name, ext, measure in [('stgc-2d', '.obj', 'conformal'), ('sea-2d', '.obj', 'conformal'),
                               ('param2d', '.obj', 'conformal'), ('cube', '.node', 'isometric'),
                               ('stgc-3d', '.node', 'isometric'),
                               ('armadillo-598', '.node', 'isometric'),
                               ('infeasible-star', '.node', 'isometric')]:
        o = out('map-' + name, ext)
        result.append(dict(name='map tlc/' + name, sa=['map', '--rest', tlc(name), '--out', o],
                           out=o, check=['--rest', tlc(name)], measure=measure))
    for name, start in [('stretch', '--targets'), ('untwist', '--init')]:
        rest, init = deform(name, '_rest.node'), deform(name, '_init.node')
        handles = deform(name, '_handles.txt')
        o = out('map-' + name, '.node')
        result.append(dict(name='map deform/%s %s' % (name, start), out=o, measure='isometric',
                           sa=['map', '--rest', rest, '--handles', handles, start, init,
                               '--distortion', 'isometric', '--out', o],
                           check=['--rest', rest, '--handles', handles, '--targets', init]))
    for name, extra in [('camelhead.off', ['--optimal-bound']),
                        ('camelhead.off', ['--free-boundary-injective']), ('golf.obj', [])]:
        mesh = os.path.join(data, 'param', name)
        o = out('param-' + name, '.obj')
        result.append(dict(name=' '.join(['param', name] + extra), out=o,
                           sa=['param', '--mesh', mesh, '--out', o] + extra,
                           check=['--rest', mesh, '--uv'], measure='conformal'))
    ff = os.path.join(data, 'frame-fields')
    for name, mesh, extra in [
            ('3holes.off', os.path.join(data, 'surfaces', '3holes.off'), []),
            ('lilium.crossfield', os.path.join(ff, 'lilium.obj'),
             ['--field', os.path.join(ff, 'lilium.crossfield')]),
            ('torus_twosings', os.path.join(ff, 'torus.obj'),
             ['--field', os.path.join(ff, 'torus_twosings.rawfield')])]:
        o = out('seamless-' + name, '.obj')
        result.append(dict(name='seamless ' + name, out=o, measure='conformal',
                           sa=['seamless', '--mesh', mesh, '--no-vtu', '--out', o] + extra,
                           check=['--rest', mesh, '--uv']))
    s1 = os.path.join(data, 'polycube', 'polycube_withHexEx', 'S1')
    for name, mesh, extra in [
            ('B0', os.path.join(data, 'polycube', 'robustPolycube', 'B0.mesh'), []),
            ('S1.flags --bound 5', s1 + '.mesh', ['--labels', s1 + '.flags', '--bound', '5'])]:
        o = out('polycube-' + name.split()[0], '.mesh')
        result.append(dict(name='polycube ' + name, sa=['polycube', '--mesh', mesh, '--out', o] + extra,
                           out=o, check=['--rest', o[:-len('.mesh')] + '.rest.mesh'],
                           measure='conformal'))
    for pose in ['bend', 'twist']:  # the paper's Figure 16 bar
        prefix = os.path.join(work, 'bar-' + pose)
        subprocess.run([os.path.join(bin_dir, 'bench_bar_pose'), '--pose', pose, '--prefix',
                        prefix], check=True, capture_output=True)
        o = prefix + '-posed.vtk'  # legacy VTK: the checker reads it
        result.append(dict(name='deform bar-' + pose, out=o, measure='isometric',
                           sa=['deform', '--rest', prefix + '.mesh', '--targets',
                               prefix + '_targets.txt', '--out', o],
                           check=['--rest', prefix + '.mesh', '--handles', prefix + '_handles.txt',
                                  '--targets', prefix + '_posed_handles.mesh']))
    rest, init = deform('stretch', '_rest.node'), deform('stretch', '_init.node')
    handles = deform('stretch', '_handles.txt')
    o = out('deform-stretch', '.vtk')
    result.append(dict(name='deform deform/stretch', out=o, measure='isometric',
                       sa=['deform', '--rest', rest, '--handles', handles, '--targets', init,
                           '--out', o],
                       check=['--rest', rest, '--handles', handles, '--targets', init]))
    # The knight's ARAP start folds tetrahedra that the solve repairs. Its targets are
    # `index x y z` rows, which the checker does not read: sa checks the handles.
    knight = os.path.join(work, 'knight_targets.txt')
    subprocess.run([sys.executable, os.path.join(HERE, 'knight_pose.py'), '--data', data,
                    '--out', knight], check=True, capture_output=True)
    mesh = os.path.join(data, 'tet', 'decimated-knight.mesh')
    o = out('deform-knight', '.vtk')
    result.append(dict(name='deform knight', out=o, measure='isometric',
                       sa=['deform', '--rest', mesh, '--targets', knight, '--out', o],
                       check=['--rest', mesh]))
    return result


def run_case(a, case):
    report = case['out'] + '.json'
    r = run_measured([a.sa] + case['sa'] + ['--report', report, '--no-png', '--force', '--quiet',
                                            '--max-time', repr(a.timeout)], 2 * a.timeout)
    row = dict(case=case['name'], measure=case['measure'])
    if r is None:
        row['verdict'] = 'killed'
        return row
    row['wall'] = r['wall']
    rep = json.load(open(report)) if os.path.exists(report) else {}
    if 'infeasible' in rep or 'no PolyCube' in r['err'] or 'polycube: bound' in r['err']:
        row['verdict'] = 'infeasible'
        return row
    if r['code'] not in (0, 1) or not os.path.exists(case['out']):
        row['verdict'] = 'exit %d' % r['code']
        row['note'] = (r['err'].strip().splitlines() or [''])[-1]
        return row
    c = subprocess.run([sys.executable, a.checker] + case['check'] + ['--result', case['out']],
                       capture_output=True, text=True)
    try:
        chk = json.loads(c.stdout)
    except json.JSONDecodeError:
        chk = dict(ok=False, error=(c.stdout + c.stderr).strip()[-300:])
    row['verdict'] = 'verified' if r['code'] == 0 else 'unverified'
    if bool(chk.get('ok')) != (r['code'] == 0):
        row['disagreement'] = 'sa exit %d, the checker says ok = %s' % (r['code'], chk.get('ok'))
    if case['measure'] in chk:
        row['max'], row['mean'] = chk[case['measure']]
    return row


def compare(row, expected, tolerance, table):
    """The reasons this row fails against the expected one (none: it passes)."""
    if expected is None:
        return ['not in %s (run --update)' % table]
    reasons = []
    if row['verdict'] != expected['verdict']:
        reasons.append('verdict %s, expected %s' % (row['verdict'], expected['verdict']))
    if 'disagreement' in row:
        reasons.append(row['disagreement'])
    elif 'note' in row and row['verdict'] != expected['verdict']:
        reasons.append(row['note'])
    for key in ('max', 'mean'):
        if expected[key] in ('', '-') or row['verdict'] != expected['verdict']:
            continue
        if key not in row:
            reasons.append('no %s measured' % key)
        elif row[key] > float(expected[key]) * (1.0 + tolerance):
            reasons.append('%s %s %s, expected at most %s' % (
                row['measure'], key, fmt(row[key], 6), fmt(float(expected[key]) * (1 + tolerance), 6)))
    return reasons


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--sa', default=os.path.join(ROOT, 'build', 'bin', 'sa'))
    ap.add_argument('--data', default=os.path.join(ROOT, '..', 'shared', 'data'))
    ap.add_argument('--checker', default=os.path.join(ROOT, '..', 'shared', 'tools', 'check_map.py'))
    ap.add_argument('--jobs', type=int, default=os.cpu_count())
    ap.add_argument('--timeout', type=float, default=120.0, help='--max-time of every run, s')
    ap.add_argument('--tolerance', type=float, default=0.10,
                    help='relative worsening of a distortion that fails (default 0.10)')
    ap.add_argument('--expected', default=EXPECTED, help='the table (default %(default)s)')
    ap.add_argument('--update', action='store_true', help='rewrite the expected table')
    a = ap.parse_args()
    if not os.path.isdir(a.data) or not os.path.exists(a.checker):
        print('quality guard: skipped, no %s' % a.data)
        return 0
    with tempfile.TemporaryDirectory(prefix='sa-quality-') as work:
        todo = cases(a.data, work, os.path.dirname(a.sa))
        # One sa thread per job: the jobs fill the cores and results do not depend on threads.
        for case in todo:
            case['sa'] += ['--threads', '1']
        with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
            rows = list(pool.map(lambda c: run_case(a, c), todo))
    if a.update:
        with open(a.expected, 'w', newline='') as f:
            w = csv.writer(f, delimiter='\t', lineterminator='\n')
            w.writerow(FIELDS)
            for r in rows:
                w.writerow([r['case'], r['verdict'], r['measure'],
                            repr(r['max']) if 'max' in r else '-',
                            repr(r['mean']) if 'mean' in r else '-'])
        print('quality guard: wrote %s (%d cases)' % (a.expected, len(rows)))
        return 0
    with open(a.expected) as f:
        expected = {e['case']: e for e in csv.DictReader(f, delimiter='\t')}
    failures = 0
    print('| case | verdict | %s max / mean | expected | time (s) | |' % 'distortion')
    print('|---|---|---|---|---:|---|')
    for r in rows:
        e = expected.get(r['case'])
        reasons = compare(r, e, a.tolerance, a.expected)
        failures += bool(reasons)
        shown = lambda d: '%s %s / %s' % (d.get('verdict'), fmt(_number(d.get('max')), 4),
                                          fmt(_number(d.get('mean')), 4))
        print('| %s | %s | %s %s / %s | %s | %s | %s |' % (
            r['case'], r['verdict'], r['measure'], fmt(r.get('max'), 4), fmt(r.get('mean'), 4),
            shown(e) if e else '-', fmt(r.get('wall')), 'FAIL: ' + '; '.join(reasons) if reasons else 'ok'))
    missing = sorted(set(expected) - {r['case'] for r in rows})
    for name in missing:
        print('| %s | not run | | | | FAIL: in the table, not among the cases |' % name)
    failures += len(missing)
    print('quality guard: %d of %d cases pass' % (len(rows) - failures + len(missing), len(rows)))
    return 1 if failures else 0


def _number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


if __name__ == '__main__':
    sys.exit(main())
