#!/usr/bin/env python3
"""Runs `sa polycube` (computed labels) on rotated copies of the robustPolycube meshes of
../shared/data/polycube: each copy is the mesh turned by a given angle about an axis drawn from a
seeded generator, so the closest-axis labels, the clean-up, the charts and the cube-cover start all
change while the shape does not. Each output is also checked by ../shared/tools/check_map.py
(OUT.rest.mesh against OUT.mesh). Prints one line per copy and a summary (verified / failed,
the failures' turning chart boundaries).

  python3 bench/polycube_variations.py [--meshes B0,NY_2,pente,M1_tet,S3] [--angles 15,30,45]
      [--seeds 1,2] [--max-time 150]
"""
import argparse
import json
import math
import os
import random
import subprocess
import sys
import tempfile

from bench_common import fmt, run_measured

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def rotation(seed, degrees):
    """The rotation by `degrees` about a unit axis drawn from random.Random(seed)."""
    rng = random.Random(seed)
    while True:
        axis = [rng.gauss(0.0, 1.0) for _ in range(3)]
        norm = math.sqrt(sum(x * x for x in axis))
        if norm > 1e-3:
            break
    x, y, z = (v / norm for v in axis)
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    t = 1.0 - c
    return [[c + x * x * t, x * y * t - z * s, x * z * t + y * s],
            [y * x * t + z * s, c + y * y * t, y * z * t - x * s],
            [z * x * t - y * s, z * y * t + x * s, c + z * z * t]]


def write_rotated(source, target, matrix):
    """Copies a .mesh file with the rows of its Vertices section turned by `matrix` (the
    references and every other line kept)."""
    lines = open(source).read().split('\n')
    at = [line.strip() for line in lines].index('Vertices')
    count = int(lines[at + 1])
    for i in range(at + 2, at + 2 + count):
        words = lines[i].split()
        p = [float(w) for w in words[:3]]
        lines[i] = ' '.join(['%.17g' % sum(matrix[r][k] * p[k] for k in range(3))
                             for r in range(3)] + words[3:])
    with open(target, 'w') as f:
        f.write('\n'.join(lines))


def run_copy(a, mesh, degrees, seed, work):
    name = '%s %g deg seed %d' % (mesh, degrees, seed)
    base = os.path.join(work, '%s-%g-%d' % (mesh, degrees, seed))
    write_rotated(os.path.join(a.data, 'polycube', 'robustPolycube', mesh + '.mesh'),
                  base + '.in.mesh', rotation(seed, degrees))
    command = [a.sa, 'polycube', '--mesh', base + '.in.mesh', '--out', base + '.mesh',
               '--report', base + '.json', '--max-time', str(a.max_time), '--no-png', '--quiet',
               '--force']
    print('running %s ...' % name, file=sys.stderr, flush=True)
    r = run_measured(command, a.max_time * 2 + 120)
    if r is None:
        return dict(name=name, status='killed')
    if r['code'] not in (0, 1) or not os.path.exists(base + '.json'):
        return dict(name=name, status='error: ' + (r['err'].strip().splitlines() or
                                                    ['exit %d' % r['code']])[-1])
    with open(base + '.json') as f:
        report = json.load(f)
    c = subprocess.run([sys.executable, a.checker, '--rest', base + '.rest.mesh', '--result',
                        base + '.mesh'], capture_output=True, text=True)
    try:
        check = json.loads(c.stdout)
    except json.JSONDecodeError:
        check = dict(error=(c.stdout + c.stderr).strip())
    labels = report['preparation']['labels']
    return dict(name=name, status='ok', success=report['success'], code=r['code'],
                wall=r['wall'], charts=labels['charts'],
                turning=len(labels.get('non_monotone_boundaries', [])),
                start=report['start']['quality']['inverted'],
                conformal=report['verification']['quality']['conformal'],
                inverted=check.get('inverted'), degenerate=check.get('degenerate'))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument('--sa', default=os.path.join(ROOT, 'build', 'bin', 'sa'))
    ap.add_argument('--data', default=os.path.join(ROOT, '..', 'shared', 'data'))
    ap.add_argument('--checker', default=os.path.join(ROOT, '..', 'shared', 'tools', 'check_map.py'))
    ap.add_argument('--meshes', default='B0,NY_2,pente,M1_tet,S3',
                    help='names of ../shared/data/polycube/robustPolycube/*.mesh')
    ap.add_argument('--angles', default='15,30,45', help='rotation angles in degrees')
    ap.add_argument('--seeds', default='1,2', help='seeds of the rotation axes')
    ap.add_argument('--max-time', type=float, default=150.0, help='--max-time of each solve')
    a = ap.parse_args()
    work = tempfile.mkdtemp(prefix='sa-polycube-variations-')
    print('| copy | charts (turning back) | flipped at start | δ_con max / mean | time (s) | '
          'verified (exit) | check_map.py: inverted / degenerate |')
    print('|---|---|---|---|---|---|---|')
    rows = []
    for mesh in a.meshes.split(','):
        for degrees in [float(x) for x in a.angles.split(',')]:
            for seed in [int(x) for x in a.seeds.split(',')]:
                r = run_copy(a, mesh, degrees, seed, work)
                rows.append(r)
                if r['status'] != 'ok':
                    print('| %s | %s |' % (r['name'], r['status']), flush=True)
                    continue
                print('| %s | %d (%d) | %d | %s / %s | %s | %s (%d) | %s / %s |' % (
                    r['name'], r['charts'], r['turning'], r['start'],
                    fmt(r['conformal']['max'], 4), fmt(r['conformal']['mean'], 4),
                    fmt(r['wall'], 3), 'yes' if r['success'] else 'no', r['code'],
                    fmt(r['inverted']), fmt(r['degenerate'])), flush=True)
    verified = [r for r in rows if r.get('success')]
    failed = [r for r in rows if not r.get('success')]
    print('\n%d of %d verified (outputs in %s)' % (len(verified), len(rows), work))
    for r in failed:
        print('failed: %s (%s turning chart boundaries)' % (r['name'], r.get('turning', '?')))
    return 0 if not failed else 1


if __name__ == '__main__':
    sys.exit(main())
