#!/usr/bin/env python3
"""Runs `sa seamless` on every surface of ../shared/data/surfaces (smoothest cross field) and every
frame field of ../shared/data/frame-fields, checks every result with the independent checker
../shared/tools/check_map.py --uv (per-corner UVs), measures seams and cone points again here from
the written OBJ, and prints a markdown table: faces, singularities, edge curl before and after,
foldovers of the plain Poisson map of the input field and of ours, seam mismatch, time, memory.

It also measures libigl's published MIQ result for 3holes (frame-fields/3holes-miq-UV.dmat and
-FUV.dmat, on surfaces/3holes.off) with the same checks, beside ours on the same mesh.

  python3 bench/seamless_benchmarks.py [--only NAME] [--timeout 600] [--write docs/performance.md]

Seam mismatch (measured here, independently of sa): for every interior edge of the surface, the
two images of the edge in (u, v) seen from its two faces, d_f and d_g; the mismatch is
min over quarter turns R of |d_g - R d_f|, over the mean edge length in (u, v); the table shows
the largest. Cone points: interior vertices whose (u, v) angle sum is not 2 pi, with index
1 - sum / 2 pi.
"""
import argparse
import json
import math
import os
import sys
import tempfile

from bench_common import check_uv, fmt, run_measured, write_section

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def read_obj(path):
    V, VT, F, FT = [], [], [], []
    for line in open(path):
        p = line.split()
        if not p:
            continue
        if p[0] == 'v':
            V.append([float(x) for x in p[1:4]])
        elif p[0] == 'vt':
            VT.append([float(x) for x in p[1:3]])
        elif p[0] == 'f':
            F.append([int(c.split('/')[0]) - 1 for c in p[1:4]])
            FT.append([int(c.split('/')[1]) - 1 for c in p[1:4]])
    return V, VT, F, FT


def read_dmat(path):
    tok = open(path).read().split()
    cols, rows = int(tok[0]), int(tok[1])
    vals = [float(x) for x in tok[2:2 + cols * rows]]
    return [[vals[c * rows + r] for c in range(cols)] for r in range(rows)]


def read_off(path):
    tok = [t for line in open(path) for t in line.split('#')[0].split()]
    assert tok[0] == 'OFF'
    nv, nf = int(tok[1]), int(tok[2])
    V = [[float(x) for x in tok[4 + 3 * i:7 + 3 * i]] for i in range(nv)]
    p = 4 + 3 * nv
    F = []
    for _ in range(nf):
        k = int(tok[p])
        F.append([int(x) for x in tok[p + 1:p + 1 + k]])
        p += 1 + k
    return V, F


def write_obj(path, V, F, VT, FT):
    with open(path, 'w') as f:
        for v in V:
            f.write('v %r %r %r\n' % tuple(v))
        for t in VT:
            f.write('vt %r %r\n' % tuple(t))
        for a, b in zip(F, FT):
            f.write('f %d/%d %d/%d %d/%d\n' % (a[0] + 1, b[0] + 1, a[1] + 1, b[1] + 1, a[2] + 1, b[2] + 1))


def seams_and_cones(F, VT, FT):
    """Largest relative seam mismatch and the cone points {vertex: index} of a per-corner map."""
    edge_faces = {}
    for f, tri in enumerate(F):
        for k in range(3):
            a, b = tri[k], tri[(k + 1) % 3]
            edge_faces.setdefault((min(a, b), max(a, b)), []).append((f, k))
    mean_edge = sum(math.dist(VT[FT[f][k]], VT[FT[f][(k + 1) % 3]])
                    for f in range(len(F)) for k in range(3)) / (3 * len(F))

    def image(f, a, b):
        ta = FT[f][F[f].index(a)]
        tb = FT[f][F[f].index(b)]
        return (VT[tb][0] - VT[ta][0], VT[tb][1] - VT[ta][1])

    worst = 0.0
    boundary = set()
    for (a, b), faces in edge_faces.items():
        if len(faces) != 2:
            boundary.update((a, b))
            continue
        df, dg = image(faces[0][0], a, b), image(faces[1][0], a, b)
        best = min(math.hypot(dg[0] - rx, dg[1] - ry)
                   for rx, ry in [(df[0], df[1]), (-df[1], df[0]), (-df[0], -df[1]), (df[1], -df[0])])
        worst = max(worst, best / mean_edge)
    angle = {}
    for f, tri in enumerate(F):
        for k in range(3):
            p, q, r = VT[FT[f][k]], VT[FT[f][(k + 1) % 3]], VT[FT[f][(k + 2) % 3]]
            ax, ay, bx, by = q[0] - p[0], q[1] - p[1], r[0] - p[0], r[1] - p[1]
            angle[tri[k]] = angle.get(tri[k], 0.0) + math.atan2(ax * by - ay * bx, ax * bx + ay * by)
    cones = {}
    for v, s in angle.items():
        if v in boundary:
            continue
        index = 1.0 - s / (2.0 * math.pi)
        if abs(index) > 1e-6:
            cones[v] = index
    return worst, cones


def run_case(a, work, name, mesh, args):
    stem = name.replace('/', '-')
    out = os.path.join(work, stem + '.obj')
    report = os.path.join(work, stem + '.json')
    command = [a.sa, 'seamless', '--mesh', mesh] + args + ['--out', out, '--report', report,
                                                           '--no-png', '--no-vtu', '--force', '--quiet']
    print('running %s ...' % name, file=sys.stderr, flush=True)
    r = run_measured(command, a.timeout)
    row = dict(name=name)
    if r is None:
        row['status'] = 'killed after %g s' % a.timeout
        return row
    row['wall'], row['peak'] = r['wall'], r['peak_kb'] / 1024.0 / 1024.0
    if not os.path.exists(report):
        row['status'] = 'error: ' + (r['err'].strip().splitlines() or ['exit %d' % r['code']])[-1]
        return row
    rep = json.load(open(report))
    if 'infeasible' in rep:  # a cone configuration no seamless map has (cone_obstruction.h)
        row.update(faces=rep['faces'], singular=len(rep['singularities_before']),
                   source=rep['field_source'],
                   status='diagnosed infeasible (exit %d): a +1/4, -1/4 pair alone on a torus' % r['code'])
        print('  ', row['status'], fmt(row['wall']), 's', file=sys.stderr, flush=True)
        return row
    row.update(faces=rep['faces'], singular=len(rep['singularities_before']),
               curl_before=rep['curl_before']['max'], curl_after=rep['curl_after']['max'],
               plain=rep['plain_poisson']['quality']['inverted'], source=rep['field_source'],
               iterations=len(rep['integrable']['iterations']) - 1 if rep['integrable']['iterations'] else 0)
    chk = check_uv(a.checker, mesh, out)
    _, VT, F, FT = read_obj(out)
    mismatch, cones = seams_and_cones(F, VT, FT)
    expected = {s['vertex']: s['index'] for s in rep['singularities_before']}
    same = set(cones) == set(expected) and all(abs(cones[v] - expected[v]) < 1e-6 for v in cones)
    row.update(ours=chk.get('inverted'), mismatch=mismatch, cones=len(cones), same_cones=same)
    ok = chk.get('ok') and mismatch < 1e-6 and same
    row['status'] = 'verified' if ok else 'NOT verified'
    if bool(ok) != rep['success']:
        row['status'] += ' (sa says %s)' % ('success' if rep['success'] else 'failure')
    print('  ', row['status'], fmt(row['wall']), 's', file=sys.stderr, flush=True)
    return row


def miq_row(a, work):
    """libigl's published MIQ result for 3holes, measured as ours."""
    V, F = read_off(os.path.join(a.data, 'surfaces', '3holes.off'))
    folder = os.path.join(a.data, 'frame-fields')
    UV = read_dmat(os.path.join(folder, '3holes-miq-UV.dmat'))
    FUV = [[int(x) for x in row] for row in read_dmat(os.path.join(folder, '3holes-miq-FUV.dmat'))]
    out = os.path.join(work, '3holes-miq.obj')
    write_obj(out, V, F, UV, FUV)
    chk = check_uv(a.checker, os.path.join(a.data, 'surfaces', '3holes.off'), out)
    mismatch, cones = seams_and_cones(F, UV, FUV)
    return dict(name='3holes: libigl MIQ (published UV)', faces=len(F), ours=chk.get('inverted'),
                mismatch=mismatch, cones=len(cones), status='checked' if 'inverted' in chk else
                'error: %s' % chk.get('error'))


def table(rows):
    lines = ['| case | field | faces | singularities | edge curl max before → after | '
             'foldovers: Poisson of the input field | foldovers: ours | cone points in (u, v) (= singularities?) | '
             'seam mismatch | SA iterations | time (s) | peak memory (GB) | check |',
             '|---|---|---|---|---|---|---|---|---|---|---|---|---|']
    for r in rows:
        curl = ('%s → %s' % (fmt(r['curl_before']), fmt(r['curl_after']))) if 'curl_before' in r else '-'
        cones = '-' if 'cones' not in r else '%d%s' % (
            r['cones'], '' if 'same_cones' not in r else (' (yes)' if r['same_cones'] else ' (NO)'))
        lines.append('| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |' % (
            r['name'], r.get('source', '-'), fmt(r.get('faces')), fmt(r.get('singular')), curl,
            fmt(r.get('plain')), fmt(r.get('ours')), cones, fmt(r.get('mismatch'), 2),
            fmt(r.get('iterations')), fmt(r.get('wall')), fmt(r.get('peak'), 2), r['status']))
    return '\n'.join(lines) + '\n'


def cases(data):
    s, ff = os.path.join(data, 'surfaces'), os.path.join(data, 'frame-fields')
    out = [(os.path.splitext(n)[0], os.path.join(s, n), []) for n in sorted(os.listdir(s))]
    out += [
        ('inspired_mesh.dmat', os.path.join(ff, 'inspired_mesh.obj'), ['--field', os.path.join(ff, 'inspired_mesh.dmat')]),
        ('inspired_mesh_b/_bc', os.path.join(ff, 'inspired_mesh.obj'),
         ['--constraints', os.path.join(ff, 'inspired_mesh_b.dmat'), os.path.join(ff, 'inspired_mesh_bc.dmat')]),
        ('lilium.crossfield', os.path.join(ff, 'lilium.obj'), ['--field', os.path.join(ff, 'lilium.crossfield')]),
        ('lilium_b/_bc', os.path.join(ff, 'lilium.obj'),
         ['--constraints', os.path.join(ff, 'lilium_b.dmat'), os.path.join(ff, 'lilium_bc.dmat')]),
        ('bumpy-cube.dmat', os.path.join(ff, 'bumpy-cube.obj'), ['--field', os.path.join(ff, 'bumpy-cube.dmat')]),
        ('torus_twosings.rawfield', os.path.join(ff, 'torus.obj'),
         ['--field', os.path.join(ff, 'torus_twosings.rawfield')]),
    ]
    out += [('%s.dmat' % n, os.path.join(ff, 'snail.obj'), ['--field', os.path.join(ff, n + '.dmat')])
            for n in ('snail1', 'snail2', 'snail3', 'snail4')]
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--sa', default=os.path.join(ROOT, 'build', 'bin', 'sa'))
    ap.add_argument('--data', default=os.path.join(ROOT, '..', 'shared', 'data'))
    ap.add_argument('--checker', default=os.path.join(ROOT, '..', 'shared', 'tools', 'check_map.py'))
    ap.add_argument('--only', help='run only the cases whose name contains this text')
    ap.add_argument('--timeout', type=float, default=600.0, help='seconds per run')
    ap.add_argument('--write', help='markdown file whose seamless-benchmarks section gets the table')
    a = ap.parse_args()
    work = tempfile.mkdtemp(prefix='sa-seamless-bench-')
    rows = [run_case(a, work, name, mesh, args) for name, mesh, args in cases(a.data)
            if not a.only or a.only in name]
    if not a.only or a.only in '3holes':
        rows.append(miq_row(a, work))
    output = ('`sa seamless --mesh M [--field F | --constraints B BC] --out M.obj --report M.json` '
              '(without a field: the smoothest cross field; with a field that leaves faces free: '
              'the smoothest cross field through the given faces). "check": check_map.py --uv finds '
              'no inverted or degenerate face, the seam mismatch measured here is below 1e-6, and '
              'the cone points measured here are the singularities sa reported for the input field.\n\n'
              + table(rows))
    print(output)
    if a.write:
        write_section(a.write, 'seamless-benchmarks',
                      'python3 bench/seamless_benchmarks.py ' + ' '.join(sys.argv[1:]), output)
    return 0


if __name__ == '__main__':
    sys.exit(main())
