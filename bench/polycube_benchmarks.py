#!/usr/bin/env python3
"""Runs the pieces of `sa polycube` that exist before the solve (bench_polycube_pieces) on every
mesh of issue 21's table in ../shared/data/polycube: labels (read, transferred, or computed and
cleaned), charts, squashed elements and splits, and the cube-cover start, which the independent
checker ../shared/tools/check_map.py also measures (OUT.rest.mesh against OUT.mesh). Prints a
markdown table; times are wall seconds of each stage, peak memory of the whole run.

  python3 bench/polycube_benchmarks.py [--only NAME] [--timeout 600] [--write docs/performance.md]

With --write, the table replaces the section between <!-- polycube-pieces:begin --> and
<!-- polycube-pieces:end --> of that file.

With --solve, runs the whole of `sa polycube` instead (the solve of issue 21, with --optimal-bound
unless --bound K is given, --max-time per run), on the cases of SOLVE_CASES (S1 with S1.flags
last), each output also checked by check_map.py, into the section polycube-solve:

  python3 bench/polycube_benchmarks.py --solve [--max-time 300] [--only NAME] [--write FILE]
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

# The solve's cases: issue 21's table, S1 last (the largest).
SOLVE_CASES = [
    ('B0', 'robustPolycube/B0.mesh', []),
    ('NY_2', 'robustPolycube/NY_2.mesh', []),
    ('pente', 'robustPolycube/pente.mesh', []),
    ('S3', 'robustPolycube/S3.mesh', []),
    ('M1_tet', 'robustPolycube/M1_tet.mesh', []),
    ('cup', 'robustPolycube/cup.mesh', []),
    ('S1 (S1.flags)', 'polycube_withHexEx/S1.mesh', ['--labels', 'polycube_withHexEx/S1.flags']),
]


def run_solve(a, name, mesh, labels, work):
    folder = os.path.join(a.data, 'polycube')
    base = os.path.join(work, name.split()[0])
    out, report = base + '.mesh', base + '.json'
    args = [os.path.join(folder, x) if x.endswith(('.flags', '.txt', '.obj')) else x for x in labels]
    bound = ['--bound', a.bound] if a.bound else ['--optimal-bound']
    command = ([a.sa, 'polycube', '--mesh', os.path.join(folder, mesh)] + args + bound +
               ['--out', out, '--report', report, '--max-time', str(a.max_time), '--no-png',
                '--quiet', '--force'])
    print('running %s ...' % name, file=sys.stderr, flush=True)
    r = run_measured(command, a.max_time * 2 + 120)
    row = dict(name=name)
    if r is None:
        row['status'] = 'killed'
        return row
    if r['code'] not in (0, 1) or not os.path.exists(report):
        row['status'] = 'error: ' + (r['err'].strip().splitlines() or ['exit %d' % r['code']])[-1]
        return row
    with open(report) as f:
        row['report'] = json.load(f)
    row['code'], row['wall'], row['peak'] = r['code'], r['wall'], r['peak_kb'] / 1024.0 / 1024.0
    c = subprocess.run([sys.executable, a.checker, '--rest', base + '.rest.mesh', '--result', out],
                       capture_output=True, text=True)
    try:
        row['check'] = json.loads(c.stdout)
    except json.JSONDecodeError:
        row['check'] = dict(ok=False, error=(c.stdout + c.stderr).strip())
    row['status'] = 'ok'
    return row


def solve_table(rows):
    lines = ['| mesh | tets (after splits) | flipped at start | charts (turning back) | '
             'δ_con max / mean (floor the labels force) | '
             'δ_iso max / mean | reached bound | rounds | assembly + vertex-stage iterations | '
             'time (s) | peak memory (GB) | verified (exit) | check_map.py: inverted / degenerate |',
             '|---|---|---|---|---|---|---|---|---|---|---|---|---|']
    for r in rows:
        if r.get('status') != 'ok':
            lines.append('| %s | %s |' % (r['name'], r.get('status')))
            continue
        rep, chk = r['report'], r['check']
        prep, q = rep['preparation'], rep['verification']['quality']
        start = rep['start']['quality']
        rounds = rep['rounds']
        iterations = '%d + %d' % (rep['solve']['assembly_iterations'],
                                  rep['solve']['vertex_stage_iterations'])
        floor = prep['labels'].get('distortion_lower_bound', {}).get('bound')
        lines.append('| %s | %s | %s | %s | %s / %s (%s) | %s / %s | %s | %s | %s | %s | %s | %s (%d) | '
                     '%s / %s |' % (
                         r['name'], prep['splits']['tets'],
                         start['inverted'], '%d (%d)' % (
                             prep['labels']['charts'],
                             len(prep['labels'].get('non_monotone_boundaries', []))),
                         fmt(q['conformal']['max'], 4), fmt(q['conformal']['mean'], 4),
                         fmt(floor, 4) if isinstance(floor, (int, float)) else (floor or '-'),
                         fmt(q['isometric']['max'], 4), fmt(q['isometric']['mean'], 4),
                         fmt(rep['reached_bound'], 4) if rep['reached_bound'] != 'inf' else 'inf',
                         len(rounds) if rounds else '-', iterations, fmt(r['wall'], 3),
                         fmt(r['peak'], 2), 'yes' if rep['success'] else 'no', r['code'],
                         fmt(chk.get('inverted')), fmt(chk.get('degenerate'))))
    return '\n'.join(lines) + '\n'


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
    lines = ['| mesh | tets | labels | charts (clean-up; turning back) | squashed tets / int. edges / '
             'bnd. edges / bnd. triangles | splits (edge, face) -> tets | cube cover: inverted / degenerate '
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
        charts += '; %s' % r.get('non_monotone_boundaries', '-')
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
    ap.add_argument('--solve', action='store_true', help='run `sa polycube` (the whole solve)')
    ap.add_argument('--sa', default=os.path.join(ROOT, 'build', 'bin', 'sa'))
    ap.add_argument('--max-time', type=float, default=300.0, help='--max-time of each solve')
    ap.add_argument('--bound', help='--bound K instead of --optimal-bound')
    ap.add_argument('--skip', help='skip the cases whose name contains this text')
    a = ap.parse_args()
    if a.solve:
        with tempfile.TemporaryDirectory(prefix='sa-polycube-solve-') as work:
            rows = [run_solve(a, name, mesh, labels, work) for name, mesh, labels in SOLVE_CASES
                    if (not a.only or a.only in name) and not (a.skip and a.skip in name)]
        output = solve_table(rows)
        print(output)
        if a.write:
            write_section(a.write, 'polycube-solve',
                          'python3 bench/polycube_benchmarks.py ' + ' '.join(sys.argv[1:]), output)
        return 0
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
