#!/usr/bin/env python3
"""Runs `sa param` on every mesh of ../shared/data/param, checks every UV map with the independent
checker ../shared/tools/check_map.py --uv, and prints a markdown table: faces, foldovers of the
initial map and after, delta_con max / mean (from the checker), the bound reached by
--optimal-bound, wall time and peak memory.

With --large, also the subdivided cases of issue 24 (LARGE_CASES: camel_b.obj Loop-subdivided 4
and 5 times, 0.92M and 3.7M faces, from LSCM with E_m = LSCM and K^conf = 1.45 (delta_con <= 2.5)
as in the paper's Figure 11; camelhead.off and face.obj subdivided 3 times with --optimal-bound),
each mesh built by `sa subdivide` and deleted after its run, with a table of the time of each
stage, peak memory and bytes per face. --large-only skips the table of the shared meshes.

With --robustness, instead: golf.obj (OptCuts) and generated disks of its class (flat closed
surfaces with a one-vertex hole and sliver triangles), from LSCM and from Tutte, with and without
the fallback to a Tutte start (frontends/param/start_fallback.h); --write puts that table between
<!-- param-robustness:begin --> and <!-- param-robustness:end -->.

  python3 bench/param_benchmarks.py [--large] [--large-only] [--robustness] [--compare-full] [--only NAME] [--timeout 600] [--write docs/performance.md]

With --compare-full, every shared mesh also runs with the optimal bound's previous default, its
rounds in the full mode (FULL_ROUNDS).

With --write, the tables replace the section between <!-- param-benchmarks:begin --> and
<!-- param-benchmarks:end --> of that file (<!-- param-large:... --> with --large-only). Extra arguments after -- go to every `sa param` run.
"""
import argparse
import math
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
    command = [a.sa, 'param', '--mesh', mesh] + args + ['--out', out, '--report', report, '--no-png',
                                                        '--force', '--quiet'] + a.extra
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


# The cases of --large (issue 24): (name, mesh in ../shared/data/param, Loop levels, sa param
# arguments). camel_b's LSCM map folds (9 triangles at the base, more after subdivision), so its
# submesh runs have regions to repair; camelhead's and face's test the optimal bound at scale.
# --compare-full: the optimal bound as it was before its rounds ran in the submesh mode.
FULL_ROUNDS = ['--mode', 'full', '--optimal-bound-rounds', '10', '--optimal-bound-tolerance', '1e-3']

LARGE_CASES = [
    ('camel_b x256', 'camel_b.obj', 4, ['--energy', 'lscm', '--bound', '1.45']),
    ('camel_b x1024', 'camel_b.obj', 5, ['--energy', 'lscm', '--bound', '1.45']),
    ('camelhead x64', 'camelhead.off', 3, ['--optimal-bound']),
    ('face x64', 'face.obj', 3, ['--optimal-bound']),
]


def stage_row(name, row, rep, subdivide_wall):
    """One line of the stage table: seconds per stage from sa's report, peak memory, bytes per
    face. Stages of an --optimal-bound run are those of its last round (rounds' total in 'solve')."""
    if rep is None:
        return '| %s | %s |' % (name, row['status']) + ' |' * 16
    t, pt, m = rep['times'], rep['parameterization']['times'], rep.get('submesh', {})
    mt = m.get('times', {})
    peak = rep['parameterization']['peak_memory_gb']
    cells = [pt['read'], pt['initial_map'], t['disassembly'], t['setup'] - t['disassembly'],
             mt.get('start', 0.0), mt.get('solves', 0.0) + mt.get('regions', 0.0), t['recovery'],
             t['vertex_stage'], t['verification'], pt['solve'], pt['output'], pt['total']]
    return '| %s | %s | %s | %s | %s | %.2f | %.0f |' % (
        name, fmt(subdivide_wall, 3), ' | '.join('%.2f' % c for c in cells),
        '%s / %s' % (m.get('start_bad', '-'), m.get('solves', '-')),
        '%s' % row['status'], peak, peak * 2**30 / max(1, row.get('faces', 1)))


def large_case(a, work):
    rows, stages = [], []
    for name, source, levels, args in LARGE_CASES:
        if a.only and a.only not in name:
            continue
        mesh = os.path.join(work, '%s-L%d.obj' % (os.path.splitext(source)[0], levels))
        s = run_measured([a.sa, 'subdivide', '--mesh', os.path.join(a.data, 'param', source),
                          '--levels', str(levels), '--out', mesh, '--force'], a.timeout)
        if s is None or s['code'] != 0:
            rows.append(dict(name=name, status='subdivision failed: %s' % (s and s['err'])))
            continue
        row, rep = run_param(a, mesh, args, work, name)
        row['name'] = '%s (`%s`)' % (name, ' '.join(args))
        rows.append(row)
        stages.append(stage_row(name, row, rep, s['wall']))
        os.remove(mesh)
    text = ('`sa subdivide --mesh M --levels L` (Loop), then `sa param` with the arguments shown:\n\n'
            + table(rows) + '\n')
    text += ('Stages (s, from sa\'s report; for --optimal-bound, of the last round, and "solve" is '
             'every round\'s): subdivide, read, initial map (LSCM), disassembly, other setup, submesh '
             'start, submesh regions, recovery, vertex stage, verification, solve (all of Simplex '
             'Assembly), output, total of sa param; bad simplices at the start / region solves; '
             'status; peak memory (sa\'s own report) and bytes per face:\n\n'
             '| case | subdivide | read | LSCM | disassembly | other setup | submesh start | '
             'regions | recovery | vertex stage | verification | solve | output | total | bad / '
             'solves | status | peak (GB) | bytes/face |\n' + '|---' * 18 + '|\n' +
             '\n'.join(stages) + '\n')
    return text


def flat_ball_with_slivers(n, toward, step, pull, path):
    """The class of OptCuts' golf.obj, as tests/frontends/param_test.cpp builds it: the octahedral
    sphere of n^2 triangles per face (geometry/mesh/mesh_generators.h), the star of the vertex nearest
    `toward` removed (a one-vertex hole), bent, squashed to 3% of its height, and every `step`-th
    triangle made a sliver by moving a vertex `pull` of the way to its opposite edge's middle."""
    ids, points, faces = {}, [], []

    def vertex(c):
        if c not in ids:
            ids[c] = len(points)
            norm = math.sqrt(sum(x * x for x in c))
            points.append([x / norm for x in c])
        return ids[c]
    for octant in range(8):
        sx, sy, sz = (-1 if octant & 1 else 1), (-1 if octant & 2 else 1), (-1 if octant & 4 else 1)
        flip = sx * sy * sz < 0

        def at(a, b):
            return vertex((sx * a, sy * b, sz * (n - a - b)))

        def add(p, q, w):
            faces.append([p, w, q] if flip else [p, q, w])
        for a in range(n):
            for b in range(n - a):
                add(at(a, b), at(a + 1, b), at(a, b + 1))
                if a + b + 1 < n:
                    add(at(a + 1, b), at(a + 1, b + 1), at(a, b + 1))
    norm = math.sqrt(sum(x * x for x in toward))
    toward = [x / norm for x in toward]
    hole = max(range(len(points)), key=lambda v: sum(points[v][k] * toward[k] for k in range(3)))
    faces = [f for f in faces if hole not in f]
    last = len(points) - 1
    points[hole] = points[last]
    points.pop()
    faces = [[hole if v == last else v for v in f] for f in faces]
    for p in points:
        p[1] = 1.3 * p[1] + 0.5 * math.sin(2.0 * p[0])
        p[2] *= 0.03
    moved = [False] * len(points)
    for s in range(0, len(faces), step):
        a, b, c = faces[s]
        if moved[a] or moved[b] or moved[c]:
            continue
        moved[a] = True
        middle = [0.5 * (points[b][k] + points[c][k]) for k in range(3)]
        points[a] = [(1 - pull) * points[a][k] + pull * middle[k] for k in range(3)]
    with open(path, 'w') as out:
        for p in points:
            out.write('v %.17g %.17g %.17g\n' % tuple(p))
        for f in faces:
            out.write('f %d %d %d\n' % (f[0] + 1, f[1] + 1, f[2] + 1))
    return path


def robustness_case(a, work):
    """golf.obj and generated disks of its class, with and without the Tutte fallback."""
    golf = os.path.join(a.data, 'param', 'golf.obj')
    meshes = [('golf.obj', golf)]
    for n, toward, step, pull in [(8, (-0.3, 0.9, 0.2), 5, 0.95), (10, (-0.3, 0.9, 0.2), 7, 0.95),
                                  (10, (-0.3, 0.9, 0.2), 4, 0.9), (20, (1, 0.1, 0.2), 8, 0.9)]:
        name = 'flat ball n=%d, slivers every %d' % (n, step)
        meshes.append((name, flat_ball_with_slivers(n, toward, step, pull, os.path.join(
            work, 'flat-ball-%d-%d.obj' % (n, step)))))
    rows = []
    for name, mesh in meshes:
        if a.only and a.only not in name:
            continue
        for init in ('lscm', 'tutte'):
            for fallback in (False, True):
                args = ['--init', init] + ([] if fallback else ['--no-fallback'])
                label = '%s, --init %s%s' % (name, init, '' if fallback else ', --no-fallback')
                row, rep = run_param(a, mesh, args, work, label.replace(' ', '_').replace(',', ''))
                row['name'] = label
                if rep is not None:
                    f = rep['parameterization']['fallback']
                    row['fallback'] = f.get('start') or ('none verified' if f['used'] else '-')
                rows.append(row)
    lines = ['| case | faces | foldovers initial | foldovers after | δ_con max | δ_con mean | '
             'fallback start | time (s) | check_map.py |', '|---|---|---|---|---|---|---|---|---|']
    for r in rows:
        chk = r.get('check', {})
        con = chk.get('conformal', [None, None])
        lines.append('| %s | %s | %s | %s | %s | %s | %s | %s | %s |' % (
            r['name'], fmt(r.get('faces')), fmt(r.get('before')), fmt(chk.get('inverted')),
            fmt(con[0], 4), fmt(con[1], 4), r.get('fallback', '-'), fmt(r.get('wall')), r['status']))
    return ('`sa param --mesh M --init I [--no-fallback]` (default options otherwise; the generated '
            'disks as tests/frontends/param_test.cpp builds them):\n\n' + '\n'.join(lines) + '\n')


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--sa', default=os.path.join(ROOT, 'build', 'bin', 'sa'))
    ap.add_argument('--data', default=os.path.join(ROOT, '..', 'shared', 'data'))
    ap.add_argument('--checker', default=os.path.join(ROOT, '..', 'shared', 'tools', 'check_map.py'))
    ap.add_argument('--only', help='run only the meshes whose name contains this text')
    ap.add_argument('--large', action='store_true', help='add the subdivided cases (LARGE_CASES)')
    ap.add_argument('--large-only', action='store_true', help='only the subdivided cases')
    ap.add_argument('--robustness', action='store_true',
                    help='only golf.obj and generated disks of its class, with and without the '
                         'Tutte fallback')
    ap.add_argument('--compare-full', action='store_true',
                    help='also run every mesh with the previous default: the full mode\'s rounds '
                         '(--mode full --optimal-bound-rounds 10 --optimal-bound-tolerance 1e-3)')
    ap.add_argument('--timeout', type=float, default=600.0, help='seconds per run')
    ap.add_argument('--write', help='markdown file whose param-benchmarks section gets the tables')
    ap.add_argument('extra', nargs='*', help='arguments for every sa param run (after --)')
    a = ap.parse_args()

    work = tempfile.mkdtemp(prefix='sa-param-bench-')
    if a.robustness:
        output = robustness_case(a, work)
        print(output)
        if a.write:
            write_section(a.write, 'param-robustness',
                          'python3 bench/param_benchmarks.py ' + ' '.join(sys.argv[1:]), output)
        return 0
    folder = os.path.join(a.data, 'param')
    rows = []
    for name in sorted(os.listdir(folder)) if not a.large_only else []:
        if a.only and a.only not in name:
            continue
        rows.append(run_param(a, os.path.join(folder, name), ['--optimal-bound'], work, name)[0])
        if a.compare_full:
            rows.append(run_param(a, os.path.join(folder, name), ['--optimal-bound'] + FULL_ROUNDS,
                                  work, name)[0])
            rows[-1]['name'] = name + ' (full mode)'
    output = '' if a.large_only else ('`sa param --mesh M --optimal-bound` (LSCM start, E_m = area-weighted |A - A0|^2, '
              'rounds of K = the largest distortion until it stops improving; "full mode": with `%s`):\n\n'
              % ' '.join(FULL_ROUNDS) + table(rows))
    if a.large or a.large_only:
        output += '\n' + large_case(a, work)
    print(output)
    if a.write:
        write_section(a.write, 'param-large' if a.large_only else 'param-benchmarks',
                      'python3 bench/param_benchmarks.py ' + ' '.join(sys.argv[1:]), output)
    return 0


if __name__ == '__main__':
    sys.exit(main())
