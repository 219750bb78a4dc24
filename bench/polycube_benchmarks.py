#!/usr/bin/env python3
"""Runs the pieces of `sa polycube` that exist before the solve (bench_polycube_pieces) on every
mesh of issue 21's table in ../shared/data/polycube: labels (read, transferred, or computed and
cleaned), charts, squashed elements and splits, and the cube-cover start, which the independent
checker ../shared/tools/check_map.py also measures (OUT.rest.mesh against OUT.mesh). Prints a
markdown table; times are wall seconds of each stage, peak memory of the whole run.

  python3 bench/polycube_benchmarks.py [--only NAME] [--timeout 600] [--write BENCHMARKS.md]

With --write, the table replaces the section between <!-- polycube-pieces:begin --> and
<!-- polycube-pieces:end --> of that file.
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

# (name, mesh, label arguments) relative to ../shared/data/polycube.
CASES = [
    ('B0', 'robustPolycube/B0.mesh', []),
    ('NY_2', 'robustPolycube/NY_2.mesh', []),
    ('S3', 'robustPolycube/S3.mesh', []),
    ('pente', 'robustPolycube/pente.mesh', []),
    ('M1_tet', 'robustPolycube/M1_tet.mesh', []),
    ('cup', 'robustPolycube/cup.mesh', []),
    ('S1 (S1.flags)', 'polycube_withHexEx/S1.mesh', ['--flags', 'polycube_withHexEx/S1.flags']),
    ('S1 (fastbndpolycube labeling.txt)', 'polycube_withHexEx/S1.mesh',
     ['--labels', 'fastbndpolycube/labeling.txt', '--surface', 'fastbndpolycube/boundary.obj']),
]


def run_case(a, name, mesh, labels, work):
    folder = os.path.join(a.data, 'polycube')
    out = os.path.join(work, name.split()[0] + '.mesh')
    args = [os.path.join(folder, x) if x.endswith(('.flags', '.txt', '.obj')) else x for x in labels]
    command = [a.tool, '--mesh', os.path.join(folder, mesh)] + args + ['--out', out]
    print('running %s ...' % name, file=sys.stderr, flush=True)
    r = run_measured(command, a.timeout)
    row = dict(name=name)
    if r is None:
        row['status'] = 'killed after %g s' % a.timeout
        return row
    if r['code'] != 0:
        row['status'] = 'error: ' + (r['err'].strip().splitlines() or ['exit %d' % r['code']])[-1]
        return row
    row.update(json.loads(r['out']))
    row['wall'], row['peak'] = r['wall'], r['peak_kb'] / 1024.0 / 1024.0
    c = subprocess.run([sys.executable, a.checker, '--rest', out.replace('.mesh', '.rest.mesh'),
                        '--result', out], capture_output=True, text=True)
    try:
        row['check'] = json.loads(c.stdout)
    except json.JSONDecodeError:
        row['check'] = dict(ok=False, error=(c.stdout + c.stderr).strip())
    row['status'] = 'ok'
    return row


def table(rows):
    lines = ['| mesh | tets | labels | charts (clean-up) | squashed tets / int. edges / bnd. edges / '
             'bnd. triangles | splits (edge, face) -> tets | cube cover: inverted / degenerate '
             '(check_map.py) | δ_con max / mean | verified start | time (s): labels, splits, '
             'cube cover, verify | peak memory (GB) |',
             '|---|---|---|---|---|---|---|---|---|---|---|']
    for r in rows:
        if r.get('status') != 'ok':
            lines.append('| %s | %s |' % (r['name'], r.get('status')))
            continue
        c = r.get('cleanup')
        charts = ('%d -> %d, %d triangles relabelled' % (c['charts_before'], c['charts_after'],
                                                          c['triangles_changed'])
                  if c else str(r['charts']))
        labels = 'computed' if r['labels'] == 'computed' else os.path.basename(r['labels'])
        if 'convention' in r:
            labels += ' (%s)' % ('inward' if 'inward normal' in r['convention']
                                 and 'mixed' not in r['convention'] else r['convention'])
        s, sp, cc, chk, t = r['squashed'], r['splits'], r['cube_cover'], r['check'], r['seconds']
        lines.append('| %s | %d | %s | %s | %d / %d / %d / %d | %d, %d -> %d | %d / %d (%s / %s) | '
                     '%s / %s | %s | %s, %s, %s, %s | %s |' % (
                         r['name'], r['tets'], labels, charts, s['tets'], s['interior_edges'],
                         s['boundary_edges'], s['boundary_triangles'], sp['edge'], sp['face'],
                         sp['tets_after'], cc['inverted'], cc['degenerate'],
                         fmt(chk.get('inverted')), fmt(chk.get('degenerate')),
                         fmt(cc['delta_con_max'], 4), fmt(cc['delta_con_mean'], 4),
                         'yes' if cc['verified'] else 'no', fmt(t['labels'], 2),
                         fmt(t['splits'], 2), fmt(t['cube_cover'], 2), fmt(t['verify'], 2),
                         fmt(r['peak'], 2)))
    return '\n'.join(lines) + '\n'


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--tool', default=os.path.join(ROOT, 'build', 'bin', 'bench_polycube_pieces'))
    ap.add_argument('--data', default=os.path.join(ROOT, '..', 'shared', 'data'))
    ap.add_argument('--checker', default=os.path.join(ROOT, '..', 'shared', 'tools', 'check_map.py'))
    ap.add_argument('--only', help='run only the cases whose name contains this text')
    ap.add_argument('--timeout', type=float, default=600.0, help='seconds per run')
    ap.add_argument('--write', help='markdown file whose polycube-pieces section gets the table')
    a = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix='sa-polycube-bench-') as work:
        rows = [run_case(a, name, mesh, labels, work) for name, mesh, labels in CASES
                if not a.only or a.only in name]
    output = table(rows)
    print(output)
    if a.write:
        write_section(a.write, 'polycube-pieces',
                      'python3 bench/polycube_benchmarks.py ' + ' '.join(sys.argv[1:]), output)
    return 0


if __name__ == '__main__':
    sys.exit(main())
