#!/usr/bin/env python3
"""Writes handle targets for the knight of ../shared/data (tet/decimated-knight.mesh, handles
from deform/knight/decimated-knight-selection.dmat) as rows `index x y z`.

The selection is libigl's tutorial 405 (As-Rigid-As-Possible): -1 = free, 0, 1, 2 = three
handle groups, on the vertices of deform/knight/decimated-knight.off, which are the first 502
vertices of the tet mesh (checked). The groups move as that tutorial animates them, taken at
anim_t = 1 with mid the centre of the surface's bounding box:
  group 0: x += r0 sin(pi t),          y -= r0 + r0 cos(pi + pi t),          r0 = 0.25 mid_x
  group 1: y += r1 + r1 cos(pi + 0.3 pi t), z -= r1 sin(0.3 pi t),           r1 = 0.15 mid_y
  group 2: z += r1 + r1 cos(pi + 0.7 pi t), x += r1 sin(0.7 pi t)

  python3 bench/knight_pose.py --data ../shared/data --out knight_targets.txt [--t 1]
"""
import argparse
import math
import os
import sys


def read_medit_vertices(path):
    with open(path) as f:
        tokens = f.read().split()
    i = tokens.index('Vertices')
    n = int(tokens[i + 1])
    return [tuple(float(x) for x in tokens[i + 2 + 4 * k:i + 5 + 4 * k]) for k in range(n)]


def read_off_vertices(path):
    with open(path) as f:
        tokens = [t for line in f for t in line.split('#')[0].split()]
    n = int(tokens[1])
    return [tuple(float(x) for x in tokens[4 + 3 * k:7 + 3 * k]) for k in range(n)]


def read_dmat_column(path):
    with open(path) as f:
        tokens = f.read().split()
    cols, rows = int(tokens[0]), int(tokens[1])
    assert cols == 1
    return [int(float(x)) for x in tokens[2:2 + rows]]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--data', default=os.path.join(os.path.dirname(__file__), '..', '..', 'shared', 'data'))
    ap.add_argument('--out', required=True)
    ap.add_argument('--t', type=float, default=1.0, help="the tutorial's anim_t")
    a = ap.parse_args()
    tets = read_medit_vertices(os.path.join(a.data, 'tet', 'decimated-knight.mesh'))
    surface = read_off_vertices(os.path.join(a.data, 'deform', 'knight', 'decimated-knight.off'))
    groups = read_dmat_column(os.path.join(a.data, 'deform', 'knight', 'decimated-knight-selection.dmat'))
    assert len(groups) == len(surface)
    # The tet mesh starts with the surface's vertices (written with 6 digits).
    worst = max(abs(p - q) for u, v in zip(tets, surface) for p, q in zip(u, v))
    if worst > 1e-6:
        sys.exit('the tet mesh does not start with the surface vertices (%g apart)' % worst)
    mid = [0.5 * (min(v[k] for v in surface) + max(v[k] for v in surface)) for k in range(3)]
    r0, r1, t = 0.25 * mid[0], 0.15 * mid[1], a.t
    rows = 0
    with open(a.out, 'w') as out:
        out.write('# decimated-knight.mesh: libigl tutorial 405 pose at anim_t = %g\n' % t)
        for v, g in enumerate(groups):
            if g < 0:
                continue
            x, y, z = tets[v]
            if g == 0:
                x += r0 * math.sin(0.5 * t * 2 * math.pi)
                y -= r0 + r0 * math.cos(math.pi + 0.5 * t * 2 * math.pi)
            elif g == 1:
                y += r1 + r1 * math.cos(math.pi + 0.15 * t * 2 * math.pi)
                z -= r1 * math.sin(0.15 * t * 2 * math.pi)
            elif g == 2:
                z += r1 + r1 * math.cos(math.pi + 0.35 * t * 2 * math.pi)
                x += r1 * math.sin(0.35 * t * 2 * math.pi)
            out.write('%d %.17g %.17g %.17g\n' % (v, x, y, z))
            rows += 1
    print('wrote %d handle targets to %s' % (rows, a.out), file=sys.stderr)
    return 0


if __name__ == '__main__':
    sys.exit(main())
