#!/usr/bin/env python3
"""Runs the default `sa map` on many generated problems of the fixed-boundary hard class
(tests/fixtures/generated_problems.h through build/bin/bench_generate_problem: every boundary vertex a
handle at a twisted or bent, optionally flattened position, the interior tangled by a Tutte solve
and seeded noise) and checks every result with ../shared/tools/check_map.py.

Variations: meshes (generated boxes, planar rectangles and the tetrahedral meshes of
../shared/data/tet), deformation (twist, bend; planar: bend only), amount, flattening and noise
seed, drawn from a seeded generator so that a run is reproducible. Prints one line per problem and a summary (verified / failed,
median and largest wall time).

  python3 bench/hard_class_variations.py [--count 30] [--seed 7] [--timeout 60] [--meshes ...]
"""
import argparse
import json
import os
import random
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument('--sa', default=os.path.join(ROOT, 'build', 'bin', 'sa'))
    ap.add_argument('--generator', default=os.path.join(ROOT, 'build', 'bin', 'bench_generate_problem'))
    ap.add_argument('--data', default=os.path.join(ROOT, '..', 'shared', 'data'))
    ap.add_argument('--checker', default=os.path.join(ROOT, '..', 'shared', 'tools', 'check_map.py'))
    ap.add_argument('--count', type=int, default=30)
    ap.add_argument('--seed', type=int, default=7)
    ap.add_argument('--timeout', type=float, default=60.0, help='seconds per sa run (--max-time)')
    ap.add_argument('--meshes', default='grid,octopus-low,decimated-knight,hand',
                    help='grid (a box of tets), grid2d (a rectangle of triangles) and/or names of '
                    '../shared/data/tet/*.mesh')
    a = ap.parse_args()
    rng = random.Random(a.seed)
    meshes = a.meshes.split(',')
    work = tempfile.mkdtemp(prefix='sa-hard-class-')
    rows = []
    for i in range(a.count):
        mesh = rng.choice(meshes)
        deformation = rng.choice(['twist', 'bend']) if mesh != 'grid2d' else 'bend'
        amount = round(rng.uniform(0.5, 2.0), 3)
        flatten = rng.choice([1.0, 1.0, 0.2, 0.05, 0.02])
        noise = round(rng.uniform(0.3, 1.5), 3)
        seed = rng.randrange(1, 10**6)
        if mesh == 'grid':
            dims = [rng.randint(3, 8), rng.randint(3, 8), rng.randint(6, 20)]
            source = ['--grid'] + [str(d) for d in dims]
            label = 'grid-%dx%dx%d' % tuple(dims)
        elif mesh == 'grid2d':
            dims = [rng.randint(10, 120), rng.randint(40, 300)]
            source = ['--grid'] + [str(d) for d in dims]
            label = 'grid2d-%dx%d' % tuple(dims)
        else:
            source = ['--mesh', os.path.join(a.data, 'tet', mesh + '.mesh')]
            label = mesh
        name = '%s %s %.3g flat %.3g noise %.3g seed %d' % (label, deformation, amount, flatten,
                                                            noise, seed)
        path = os.path.join(work, 'p%d.txt' % i)
        g = subprocess.run([a.generator] + source +
                           ['--deformation', deformation, '--amount', repr(amount), '--noise',
                            repr(noise), '--seed', str(seed), '--flatten', repr(flatten),
                            '--out', path], capture_output=True, text=True)
        if g.returncode != 0:
            print('%-60s generator refused: %s' % (name, g.stderr.strip()[-120:]), flush=True)
            continue
        out, report = path + ('.obj' if mesh == 'grid2d' else '.node'), path + '.json'
        t = time.time()
        r = subprocess.run([a.sa, 'map', '--rest', path, '--out', out, '--report', report,
                            '--no-png', '--force', '--quiet', '--max-time', repr(a.timeout)],
                           capture_output=True, text=True)
        wall = time.time() - t
        try:
            rep = json.load(open(report))
        except (OSError, json.JSONDecodeError):
            rep = {}
        before = rep.get('initial_quality', {}).get('inverted')
        status = 'sa exit %d' % r.returncode
        if r.returncode == 0:
            c = subprocess.run([sys.executable, a.checker, '--rest', path, '--result', out],
                               capture_output=True, text=True)
            try:
                ok = json.loads(c.stdout).get('ok')
            except json.JSONDecodeError:
                ok = False
            status = 'verified' if ok else 'NOT verified by check_map.py (sa said success)'
        rows.append((name, status, wall))
        extra = ''
        if any(s['stage'] == 'fallback' for s in rep.get('stages', [])):
            extra = ' fallback'
        print('%-60s %6s simplices %6s inverted  %-12s %6.2f s  %s%s' % (
            name, rep.get('input', {}).get('simplices'), before, rep.get('mode', '-'), wall, status,
            extra), flush=True)
    verified = [r for r in rows if r[1] == 'verified']
    walls = sorted(r[2] for r in rows)
    print('\n%d problems: %d verified, %d not; wall median %.2f s, max %.2f s' % (
        len(rows), len(verified), len(rows) - len(verified),
        walls[len(walls) // 2] if walls else 0.0, walls[-1] if walls else 0.0))
    return 0 if len(verified) == len(rows) else 1


if __name__ == '__main__':
    sys.exit(main())
