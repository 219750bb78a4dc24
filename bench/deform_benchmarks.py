#!/usr/bin/env python3
"""Runs `sa deform` on issue 22's cases and prints a markdown table: simplices, handles, the ARAP
start's inverted simplices and isometric max, the result's isometric / conformal / volumetric
distortion (δ, max / mean, from sa's report), the rounds and the bounds reached on d^c and d^vol
(the barriers' measures), iterations, time, peak memory, and the independent check of the output
by ../shared/tools/check_map.py (no inverted or degenerate tetrahedron, handles at their
targets).

Cases (as deform_start_benchmarks.py's):
  deform/<name>   the rest shape, <name>_handles.txt and the rows of <name>_init.node at the
                  handles, nothing else of the data's initial map
  knight          tet/decimated-knight.mesh posed by bench/knight_pose.py (libigl's ARAP tutorial)
  bar-<pose>      the Figure 16 bar (bench_bar_pose)

  python3 bench/deform_benchmarks.py [--only NAME] [--optimal-bound] [--timeout S]
                                     [--write docs/performance.md] [-- extra sa deform arguments]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

from bench_common import fmt, run_measured, write_section

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def cases(data, work, bin_dir):
    out = []
    for pose in ['bend', 'twist', 'translate']:
        prefix = os.path.join(work, 'bar-' + pose)
        subprocess.run([os.path.join(bin_dir, 'bench_bar_pose'), '--pose', pose, '--prefix',
                        prefix], check=True, capture_output=True)
        out.append(dict(name='bar-' + pose, rest=prefix + '.mesh',
                        args=['--targets', prefix + '_targets.txt'],
                        check=['--handles', prefix + '_handles.txt', '--targets',
                               prefix + '_posed_handles.mesh']))
    knight = os.path.join(work, 'knight_targets.txt')
    subprocess.run([sys.executable, os.path.join(HERE, 'knight_pose.py'), '--data', data,
                    '--out', knight], check=True)
    # (check_map.py reads no `index x y z` rows: the knight's handles are checked by sa only.)
    out.append(dict(name='knight', rest=os.path.join(data, 'tet', 'decimated-knight.mesh'),
                    args=['--targets', knight], check=None))
    for name in ['untwist', 'stretch', 'botijo', 'rabbit', 'cat']:
        d = os.path.join(data, 'deform', name)
        handles = os.path.join(d, name + '_handles.txt')
        init = os.path.join(d, name + '_init.node')
        out.append(dict(name='deform/' + name, rest=os.path.join(d, name + '_rest.node'),
                        args=['--handles', handles, '--targets', init],
                        check=['--handles', handles, '--targets', init]))
    return out


def check(checker, rest, result, extra):
    command = [sys.executable, checker, '--rest', rest, '--result', result] + (extra or [])
    c = subprocess.run(command, capture_output=True, text=True)
    try:
        return json.loads(c.stdout)
    except json.JSONDecodeError:
        return dict(ok=False, error=(c.stdout + c.stderr).strip()[-300:])


def row(case, r, report, checked):
    if r is None:
        return '| %s | killed after the timeout |' % case
    if report is None:
        return '| %s | exit %d: %s |' % (case, r['code'], (r['err'].strip().splitlines() or [''])[-1])
    start = report['start']['quality']
    q = report['solve']['final_quality']
    rounds = report['rounds']
    last_ok = [x for x in rounds if x['success']] or rounds
    best = last_ok[-1]
    iterations = sum(x['iterations'] for x in rounds)
    if checked.get('ok'):
        verdict = 'verified'
    else:
        verdict = 'NOT verified: %s' % str(checked.get('error', checked))[:120]
    return ('| %s | %d | %d | %d / %s | %s / %s | %s / %s | %s / %s | %d: %s, %s | %d | %s | %s | %s | %s |' % (
        case, start['simplices'], report['solve']['input']['handles'], start['inverted'],
        fmt(start['isometric']['max'], 4),
        fmt(q['isometric']['max'], 4), fmt(q['isometric']['mean'], 4),
        fmt(q['conformal']['max'], 4), fmt(q['conformal']['mean'], 4),
        fmt(q['volumetric']['max'], 4), fmt(q['volumetric']['mean'], 4),
        len(rounds), fmt(best['conformal_max'], 4), fmt(best['volumetric_max'], 4), iterations,
        fmt(report['start']['seconds'], 3), fmt(r['wall'], 3), fmt(r['peak_kb'] / 1048576.0, 2),
        verdict))


HEADER = ('| case | tets | handles | start: inverted / δ_iso max | δ_iso max / mean | '
          'δ_con max / mean | δ_vol max / mean | rounds: d^c, d^vol reached | iterations | '
          'start (s) | total (s) | peak (GB) | check_map.py |\n'
          '|---|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---|\n')


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--bin', default=os.path.join(ROOT, 'build', 'bin'))
    ap.add_argument('--data', default=os.path.join(ROOT, '..', 'shared', 'data'))
    ap.add_argument('--checker', default=os.path.join(ROOT, '..', 'shared', 'tools', 'check_map.py'))
    ap.add_argument('--only', help='run only the cases whose name contains this text')
    ap.add_argument('--optimal-bound', action='store_true', help='sa deform --optimal-bound')
    ap.add_argument('--timeout', type=float, default=600.0, help='seconds per run')
    ap.add_argument('--write', help='markdown file whose deform section gets the table')
    ap.add_argument('extra', nargs='*', help='arguments for every run (after --)')
    a = ap.parse_args()

    work = tempfile.mkdtemp(prefix='sa-deform-')
    todo = [c for c in cases(a.data, work, a.bin) if not a.only or a.only in c['name']]
    lines = []
    for c in todo:
        print('%s ...' % c['name'], file=sys.stderr, flush=True)
        out = os.path.join(work, c['name'].replace('/', '-') + '.vtk')
        report_path = out[:-4] + '.json'
        command = ([os.path.join(a.bin, 'sa'), 'deform', '--rest', c['rest']] + c['args'] +
                   ['--out', out, '--report', report_path, '--no-png', '--force', '--quiet'] +
                   (['--optimal-bound'] if a.optimal_bound else []) + a.extra)
        r = run_measured(command, a.timeout)
        report = None
        if r is not None and os.path.exists(report_path) and r['code'] in (0, 1):
            with open(report_path) as f:
                report = json.load(f)
        checked = check(a.checker, c['rest'], out, c['check']) if report else {}
        lines.append(row(c['name'], r, report, checked))
    mode = '--optimal-bound' if a.optimal_bound else 'default options (no bound)'
    output = ('`sa deform` with %s:\n\n' % mode) + HEADER + '\n'.join(lines) + '\n'
    print(output)
    if a.write:
        marker = 'deform-optimal' if a.optimal_bound else 'deform'
        write_section(a.write, marker, 'python3 bench/deform_benchmarks.py ' +
                      ' '.join(sys.argv[1:]), output)
    return 0


if __name__ == '__main__':
    sys.exit(main())
