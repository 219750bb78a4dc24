#!/usr/bin/env python3
"""Runs `sa param` on every mesh of ../shared/data/param, checks every UV map with the independent
checker ../shared/tools/check_map.py --uv, and prints a markdown table: faces, foldovers of the
initial map and after, delta_con max / mean (from the checker), the bound reached by
--optimal-bound, wall time and peak memory.

With --large, also the million-face case of issue 5: camelhead.off Loop-subdivided 3 times
(`sa subdivide`, 1.45M faces), parameterized from LSCM with E_m = LSCM and K^conf = 1.45
(delta_con <= 2.5) as in the paper's Figure 11, with the time of each stage.

  python3 bench/param_benchmarks.py [--large] [--only NAME] [--timeout 600] [--write BENCHMARKS.md]

With --write, the tables replace the section between <!-- param-benchmarks:begin --> and
<!-- param-benchmarks:end --> of that file. Extra arguments after -- go to every `sa param` run.
"""
import argparse
import json
import os
import sys
import tempfile

from bench_common import check_uv, fmt, run_measured, write_section

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def run_param(a, mesh, args, work, name):
    out = os.path.join(work, name + '.obj')
    report = out + '.json'
    command = [a.sa, 'param', '--mesh', mesh] + args + ['--out', out, '--report', report, '--force',
                                                        '--quiet'] + a.extra
    print('running %s %s ...' % (name, ' '.join(args)), file=sys.stderr, flush=True)
    r = run_measured(command, a.timeout)
    row = dict(name=name)
    if r is None:
        row['status'] = 'killed after %g s' % a.timeout
        return row, None
    row['wall'], row['peak'] = r['wall'], r['peak_kb'] / 1024.0 / 1024.0
    if not os.path.exists(report) or not os.path.exists(out):
        row['status'] = 'error: ' + (r['err'].strip().splitlines() or ['exit %d' % r['code']])[-1]
        return row, None
    rep = json.load(open(report))
    par = rep['parameterization']
    row['faces'] = rep['input']['simplices']
    row['before'] = par['initial_quality']['inverted']
    row['reached'] = par['reached_bound']
    row['rounds'] = len(par['bound_rounds'])
    row['mode'] = rep.get('mode', '-')
    chk = check_uv(a.checker, mesh, out)
    row['check'] = chk
    row['status'] = 'verified' if chk.get('ok') else 'NOT verified'
    if chk.get('ok') != par['success']:
        row['status'] += ' (sa says %s)' % ('success' if par['success'] else 'failure')
    print('  ', row['status'], fmt(row['wall']), 's', file=sys.stderr, flush=True)
    return row, rep


def table(rows):
    lines = ['| mesh | faces | foldovers initial (LSCM) | foldovers after | δ_con max | δ_con mean | '
             'reached K^conf (rounds) | mode | time (s) | peak memory (GB) | check_map.py |',
             '|---|---|---|---|---|---|---|---|---|---|---|']
    for r in rows:
        chk = r.get('check', {})
        con = chk.get('conformal', [None, None])
        lines.append('| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |' % (
            r['name'], fmt(r.get('faces')), fmt(r.get('before')), fmt(chk.get('inverted')),
            fmt(con[0], 4), fmt(con[1], 4),
            '%s (%s)' % (fmt(r['reached'], 4), r['rounds']) if 'reached' in r else '-',
            r.get('mode', '-'), fmt(r.get('wall')), fmt(r.get('peak'), 2), r['status']))
    return '\n'.join(lines) + '\n'


def large_case(a, work):
    mesh = os.path.join(work, 'camelhead-x64.obj')
    source = os.path.join(a.data, 'param', 'camelhead.off')
    s = run_measured([a.sa, 'subdivide', '--mesh', source, '--levels', '3', '--out', mesh, '--force'],
                     a.timeout)
    if s is None or s['code'] != 0:
        return 'subdivision failed: %s\n' % (s and s['err'])
    args = ['--energy', 'lscm', '--bound', '1.45']
    row, rep = run_param(a, mesh, args, work, 'camelhead, Loop-subdivided 3 times')
    text = ('`sa subdivide --mesh camelhead.off --levels 3` (%.1f s), then `sa param %s`:\n\n%s\n' %
            (s['wall'], ' '.join(args), table([row])))
    if rep is not None:
        t, pt, m = rep['times'], rep['parameterization']['times'], rep.get('submesh', {})
        mt = m.get('times', {})
        text += ('Stages (s): read %.2f, initial map (LSCM) %.2f, disassembly %.2f, other setup %.2f, '
                 'submesh start %.2f, submesh regions %.2f (%d bad simplices at the start, %d solves), '
                 'recovery %.2f, vertex stage %.2f, verification %.2f, output %.2f; total %.2f. '
                 'Peak memory (sa\'s own report) %.2f GB.\n' % (
                     pt['read'], pt['initial_map'], t['disassembly'], t['setup'] - t['disassembly'],
                     mt.get('start', 0.0), mt.get('solves', 0.0) + mt.get('regions', 0.0),
                     m.get('start_bad', 0), m.get('solves', 0), t['recovery'], t['vertex_stage'],
                     t['verification'], pt['output'], pt['total'], rep['parameterization']['peak_memory_gb']))
    return text


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--sa', default=os.path.join(ROOT, 'build', 'bin', 'sa'))
    ap.add_argument('--data', default=os.path.join(ROOT, '..', 'shared', 'data'))
    ap.add_argument('--checker', default=os.path.join(ROOT, '..', 'shared', 'tools', 'check_map.py'))
    ap.add_argument('--only', help='run only the meshes whose name contains this text')
    ap.add_argument('--large', action='store_true', help='add the 1.45M-face case')
    ap.add_argument('--timeout', type=float, default=600.0, help='seconds per run')
    ap.add_argument('--write', help='markdown file whose param-benchmarks section gets the tables')
    ap.add_argument('extra', nargs='*', help='arguments for every sa param run (after --)')
    a = ap.parse_args()

    work = tempfile.mkdtemp(prefix='sa-param-bench-')
    folder = os.path.join(a.data, 'param')
    rows = []
    for name in sorted(os.listdir(folder)):
        if a.only and a.only not in name:
            continue
        rows.append(run_param(a, os.path.join(folder, name), ['--optimal-bound'], work, name)[0])
    output = ('`sa param --mesh M --optimal-bound` (LSCM start, E_m = area-weighted |A - A0|^2, '
              'rounds of K = the largest distortion until it stops improving):\n\n' + table(rows))
    if a.large:
        output += '\n' + large_case(a, work)
    print(output)
    if a.write:
        write_section(a.write, 'param-benchmarks', 'python3 bench/param_benchmarks.py ' + ' '.join(sys.argv[1:]),
                      output)
    return 0


if __name__ == '__main__':
    sys.exit(main())
