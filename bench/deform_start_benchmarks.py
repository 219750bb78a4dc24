#!/usr/bin/env python3
"""Measures the start of deformation posing alone (issue 22, before the solve): the ARAP
deformation with the handles at their targets (bench_deform_start), on the cases of issue 22,
and prints a markdown table: simplices, handles, the start's inverted simplices (and how many of
them have a boundary facet, i.e. show on the surface), its isometric, conformal and volumetric
distortion (max / volume-weighted mean over the simplices neither inverted nor degenerate),
iterations, why they stopped, and the time of the start (median of --runs runs, the cases
alternating; reading the files not included).

Cases:
  deform/<name>   the rest shape, <name>_handles.txt and the rows of <name>_init.node at the
                  handles (untwist's handles do not move: its start is the rest shape)
  knight          tet/decimated-knight.mesh, the handles of deform/knight's selection at the pose
                  of bench/knight_pose.py (libigl's ARAP tutorial at anim_t = 1), as `index x y z`
  bar-<pose>      the generated bar of Figure 16 (tests/fixtures/bar_deformation.h)

  python3 bench/deform_start_benchmarks.py [--runs 3] [--only NAME] [--write docs/performance.md]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

from bench_common import fmt, run_measured, write_section

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def cases(data, work):
    out = []
    for name in ['untwist', 'stretch', 'botijo', 'rabbit']:
        d = os.path.join(data, 'deform', name)
        out.append(dict(name='deform/' + name,
                        args=['--rest', os.path.join(d, name + '_rest.node'),
                              '--handles', os.path.join(d, name + '_handles.txt'),
                              '--targets', os.path.join(d, name + '_init.node')]))
    knight = os.path.join(work, 'knight_targets.txt')
    subprocess.run([sys.executable, os.path.join(HERE, 'knight_pose.py'), '--data', data,
                    '--out', knight], check=True)
    out.append(dict(name='knight', args=['--rest', os.path.join(data, 'tet', 'decimated-knight.mesh'),
                                         '--targets', knight]))
    for pose in ['bend', 'twist', 'translate']:
        out.append(dict(name='bar-' + pose, args=['--bar', pose]))
    return out


def table(rows):
    header = ('| case | simplices | handles | inverted (on the surface) | degenerate | '
              'δ_iso max / mean | δ_con max / mean | δ_vol max / mean | iterations | stop | '
              'start time (s) |\n'
              '|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|\n')
    lines = []
    for r in rows:
        if 'error' in r:
            lines.append('| %s | %s |' % (r['case'], r['error']))
            continue
        lines.append('| %s | %d | %d | %d (%d) | %d | %s / %s | %s / %s | %s / %s | %d | %s | %s |' % (
            r['case'], r['simplices'], r['handles'], r['inverted'], r['inverted_on_boundary'],
            r['degenerate'], fmt(r['isometric'][0], 4), fmt(r['isometric'][1], 4),
            fmt(r['conformal'][0], 4), fmt(r['conformal'][1], 4), fmt(r['volumetric'][0], 4),
            fmt(r['volumetric'][1], 4), r['iterations'], r['stop'],
            '%.3f (%s)' % (statistics.median(r['times']),
                           ', '.join('%.3f' % t for t in r['times']))))
    return header + '\n'.join(lines) + '\n'


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--bench', default=os.path.join(ROOT, 'build', 'bin', 'bench_deform_start'))
    ap.add_argument('--data', default=os.path.join(ROOT, '..', 'shared', 'data'))
    ap.add_argument('--runs', type=int, default=3)
    ap.add_argument('--only', help='run only the cases whose name contains this text')
    ap.add_argument('--timeout', type=float, default=600.0, help='seconds per run')
    ap.add_argument('--write', help='markdown file whose deform-start section gets the table')
    ap.add_argument('extra', nargs='*', help='arguments for every run (after --)')
    a = ap.parse_args()

    work = tempfile.mkdtemp(prefix='sa-deform-start-')
    todo = [c for c in cases(a.data, work) if not a.only or a.only in c['name']]
    rows = {c['name']: dict(case=c['name'], times=[]) for c in todo}
    for run in range(a.runs):
        for c in todo:  # alternating cases, so that a noisy moment does not hit one case only
            print('run %d: %s ...' % (run + 1, c['name']), file=sys.stderr, flush=True)
            r = run_measured([a.bench] + c['args'] + a.extra, a.timeout)
            row = rows[c['name']]
            if r is None or r['code'] != 0:
                row['error'] = 'killed' if r is None else r['err'].strip().splitlines()[-1]
                continue
            result = json.loads(r['out'])
            times = row['times'] + [result['start_seconds']]
            row.update(result)
            row['case'], row['times'] = c['name'], times
    output = table([rows[c['name']] for c in todo])
    print(output)
    if a.write:
        write_section(a.write, 'deform-start', 'python3 bench/deform_start_benchmarks.py ' +
                      ' '.join(sys.argv[1:]), output)
    return 0


if __name__ == '__main__':
    sys.exit(main())
