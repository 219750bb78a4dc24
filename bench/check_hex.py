#!/usr/bin/env python3
"""Independent checker for an all-hex mesh made from a tetrahedral mesh (the output of `sa hex`).

It reads the hex mesh and the tet mesh it was made from (both Medit .mesh) and reports, as one
JSON object on stdout:
  hexes, vertices, inverted (hexes with a corner Jacobian determinant <= 0 at any of their 8
  corners), scaled_jacobian_min / scaled_jacobian_mean (per hex, the smallest over its 8 corners
  of the determinant of the corner's three unit edge vectors; min and mean over the hexes),
  boundary_closed (boundary quads are hex faces used by exactly one hex, keyed by their sorted
  vertex ids; the boundary is closed when every edge of a boundary quad is in exactly two boundary
  quads and no face is in more than two hexes; open_boundary_edges and overused_faces count the
  offenders), volume_ratio (hex volume, each hex split into the 6 tets (0,1,2,6), (0,2,3,6),
  (0,3,7,6), (0,7,4,6), (0,4,5,6), (0,5,1,6), over the volume of the tet mesh),
  hausdorff (two-sided distance between the hex boundary surface, its quads split into two
  triangles, and the tet boundary surface, the tet faces used by one tet, measured at the
  vertices of each surface to the other surface's triangles, as a fraction of the diagonal of
  the tet mesh's bounding box; hausdorff_hex_to_tets and hausdorff_tets_to_hex are the two
  sides), and ok.
Exit status: 0 when ok (at least one hex, no inverted hex, closed boundary), 1 otherwise, 2 on
unreadable input (a one-line error naming the file and line, on stderr and as the JSON's error).

Hex corner order is VTK_HEXAHEDRON's: bottom face 0 1 2 3, top face 4 5 6 7, corner 4 above
corner 0. The edges of corner c go, in positive order, to 0:(1,3,4) 1:(2,0,5) 2:(3,1,6)
3:(0,2,7) 4:(7,5,0) 5:(4,6,1) 6:(5,7,2) 7:(6,4,3); the unit cube has all 8 determinants 1.

Formats read: Medit ASCII .mesh, 'Vertices' (x y z ref), 'Hexahedra' (8 1-based indices + ref)
and 'Tetrahedra' (4 + ref); the other sections (Edges, Triangles, Corners, ...) are skipped by
their row sizes, sections unknown to this script up to the next keyword; '#' starts a comment.

The distances use a uniform spatial hash of the triangles' bounding boxes, searched in growing
shells of cells around each point until the shell's lower bound exceeds the best distance, and
the exact point-triangle distance (Ericson's closest-point regions).

Usage:
  check_hex.py --hex OUT.mesh --tets INPUT.mesh
"""
import argparse, bisect, json, math, sys, time

# Values per row of the Medit sections, in 3D, that this script knows how to skip.
ROW_SIZES = {
    'Vertices': 4, 'Edges': 3, 'Triangles': 4, 'Quadrilaterals': 5, 'Tetrahedra': 5, 'Prisms': 7,
    'Pyramids': 6, 'Hexahedra': 9, 'Corners': 1, 'Ridges': 1, 'RequiredVertices': 1,
    'RequiredEdges': 1, 'RequiredTriangles': 1, 'RequiredQuadrilaterals': 1, 'Normals': 3,
    'Tangents': 3, 'NormalAtVertices': 2, 'TangentAtVertices': 2, 'NormalAtTriangleVertices': 3,
    'NormalAtQuadrilateralVertices': 3, 'TangentAtEdges': 3, 'Edges2': 4, 'Triangles2': 7,
    'Tetrahedra2': 11, 'Hexahedra2': 28,
}

# Corner c and its three neighbours, in positive order.
CORNERS = ((0, 1, 3, 4), (1, 2, 0, 5), (2, 3, 1, 6), (3, 0, 2, 7),
           (4, 7, 5, 0), (5, 4, 6, 1), (6, 5, 7, 2), (7, 6, 4, 3))
# The six faces, oriented outwards for a positive hex.
HEX_FACES = ((0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7))
# The six tets of the volume, as the pairs (a, b) of the tets (0, a, b, 6).
VOLUME_PAIRS = ((1, 2), (2, 3), (3, 7), (7, 4), (4, 5), (5, 1))


class InputError(ValueError):
    pass


def read_medit(path):
    """dict(V=[(x, y, z)], T=[4-tuples], H=[8-tuples]) with 0-based indices, or InputError
    naming the file and line."""
    toks, starts = [], []
    with open(path) as f:
        try:
            for line in f:
                starts.append(len(toks))
                if '#' in line:
                    line = line[:line.index('#')]
                toks.extend(line.split())
        except UnicodeDecodeError as e:
            raise InputError('%s:%d: not a text file (%s)' % (path, len(starts) + 1, e.reason))

    def where(i):
        return '%s:%d' % (path, bisect.bisect_right(starts, min(i, len(toks) - 1)) if toks else 1)

    def fail(i, message):
        raise InputError('%s: %s' % (where(i), message))

    def convert(fn, what, lo, hi, step, k):
        try:
            return list(map(fn, toks[lo:hi:step]))
        except ValueError:
            for i in range(lo, hi, step):
                try:
                    fn(toks[i])
                except ValueError:
                    fail(i, 'expected %s, got %r' % (what, toks[i]))
            raise

    def count_at(i, name):
        if i >= len(toks):
            fail(i, 'end of file after %s' % name)
        try:
            n = int(toks[i])
        except ValueError:
            fail(i, 'expected the number of %s, got %r' % (name, toks[i]))
        if n < 0:
            fail(i, 'negative count %d of %s' % (n, name))
        return n

    dim, V, T, H, elements = 3, None, [], [], []
    p, n = 0, len(toks)
    while p < n:
        key = toks[p]
        if not key[0].isalpha():
            fail(p, 'expected a section keyword, got %r' % key)
        if key == 'End':
            break
        if key == 'MeshVersionFormatted':
            count_at(p + 1, key); p += 2; continue
        if key == 'Dimension':
            dim = count_at(p + 1, key)
            if dim != 3:
                fail(p + 1, 'only Dimension 3 is supported, got %d' % dim)
            p += 2; continue
        if key not in ROW_SIZES:
            p += 1
            while p < n and not toks[p][0].isalpha():
                p += 1
            continue
        m, k = count_at(p + 1, key), ROW_SIZES[key]
        lo, hi = p + 2, p + 2 + m * k
        if hi > n:
            fail(n, '%s announces %d rows of %d values, the file ends first' % (key, m, k))
        if key == 'Vertices':
            cols = [convert(float, 'a coordinate', lo + j, hi, k, k) for j in range(3)]
            V = list(zip(*cols))
        elif key in ('Tetrahedra', 'Hexahedra'):
            ids = convert(int, 'a vertex index', lo, hi, 1, k)
            rows = [tuple(x - 1 for x in ids[r * k:r * k + k - 1]) for r in range(m)]
            (T if key == 'Tetrahedra' else H).extend(rows)
            elements.append((key, lo, k, rows))
        p = hi
    if V is None:
        raise InputError('%s: no Vertices section' % path)
    nv = len(V)
    for key, lo, k, rows in elements:
        if rows and (min(min(r) for r in rows) < 0 or max(max(r) for r in rows) >= nv):
            r, j = next((r, j) for r, row in enumerate(rows) for j, x in enumerate(row)
                        if x < 0 or x >= nv)
            fail(lo + r * k + j, '%s row %d: vertex index %d not in 1..%d'
                 % (key, r + 1, rows[r][j] + 1, nv))
    return dict(V=V, T=T, H=H)


def det3(ux, uy, uz, vx, vy, vz, wx, wy, wz):
    return ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx)


def hex_quality(V, H):
    """inverted, per-hex minimum scaled Jacobians, total signed volume."""
    inverted, sj, volume = 0, [], 0.0
    for h in H:
        P = [V[i] for i in h]
        worst, bad = float('inf'), False
        for c, a, b, d in CORNERS:
            px, py, pz = P[c]
            ax, ay, az = P[a][0] - px, P[a][1] - py, P[a][2] - pz
            bx, by, bz = P[b][0] - px, P[b][1] - py, P[b][2] - pz
            dx, dy, dz = P[d][0] - px, P[d][1] - py, P[d][2] - pz
            j = det3(ax, ay, az, bx, by, bz, dx, dy, dz)
            if j <= 0:
                bad = True
            ln = math.sqrt((ax * ax + ay * ay + az * az) * (bx * bx + by * by + bz * bz)
                           * (dx * dx + dy * dy + dz * dz))
            s = j / ln if ln > 0 else 0.0
            if s < worst:
                worst = s
        inverted += bad
        sj.append(worst)
        ox, oy, oz = P[0]
        sx, sy, sz = P[6][0] - ox, P[6][1] - oy, P[6][2] - oz
        for a, b in VOLUME_PAIRS:
            volume += det3(P[a][0] - ox, P[a][1] - oy, P[a][2] - oz,
                           P[b][0] - ox, P[b][1] - oy, P[b][2] - oz, sx, sy, sz) / 6.0
    return inverted, sj, volume


def hex_boundary(H):
    """Boundary quads (in their hex's order), faces in more than two hexes, open boundary edges."""
    faces = {}
    for h in H:
        for f in HEX_FACES:
            q = (h[f[0]], h[f[1]], h[f[2]], h[f[3]])
            key = tuple(sorted(q))
            e = faces.get(key)
            if e is None:
                faces[key] = [1, q]
            else:
                e[0] += 1
    quads = [e[1] for e in faces.values() if e[0] == 1]
    overused = sum(1 for e in faces.values() if e[0] > 2)
    edges = {}
    for q in quads:
        for j in range(4):
            a, b = q[j], q[(j + 1) % 4]
            key = (a, b) if a < b else (b, a)
            edges[key] = edges.get(key, 0) + 1
    open_edges = sum(1 for c in edges.values() if c != 2)
    return quads, overused, open_edges


def tet_boundary(V, T):
    """Boundary triangles (faces used by one tet) and the total unsigned volume."""
    faces, volume = {}, 0.0
    for t in T:
        a, b, c, d = t
        pa = V[a]
        volume += abs(det3(V[b][0] - pa[0], V[b][1] - pa[1], V[b][2] - pa[2],
                           V[c][0] - pa[0], V[c][1] - pa[1], V[c][2] - pa[2],
                           V[d][0] - pa[0], V[d][1] - pa[1], V[d][2] - pa[2])) / 6.0
        for f in ((b, c, d), (a, c, d), (a, b, d), (a, b, c)):
            key = tuple(sorted(f))
            e = faces.get(key)
            if e is None:
                faces[key] = [1, f]
            else:
                e[0] += 1
    return [e[1] for e in faces.values() if e[0] == 1], volume


def point_triangle_d2(px, py, pz, t):
    """Squared distance from p to the triangle t = (ax..cz, bbox), Ericson's closest-point regions."""
    ax, ay, az, bx, by, bz, cx, cy, cz = t[0], t[1], t[2], t[3], t[4], t[5], t[6], t[7], t[8]
    abx, aby, abz = bx - ax, by - ay, bz - az
    acx, acy, acz = cx - ax, cy - ay, cz - az
    apx, apy, apz = px - ax, py - ay, pz - az
    d1 = abx * apx + aby * apy + abz * apz
    d2 = acx * apx + acy * apy + acz * apz
    if d1 <= 0 and d2 <= 0:
        return apx * apx + apy * apy + apz * apz
    bpx, bpy, bpz = px - bx, py - by, pz - bz
    d3 = abx * bpx + aby * bpy + abz * bpz
    d4 = acx * bpx + acy * bpy + acz * bpz
    if d3 >= 0 and d4 <= d3:
        return bpx * bpx + bpy * bpy + bpz * bpz
    vc = d1 * d4 - d3 * d2
    if vc <= 0 and d1 >= 0 and d3 <= 0:
        v = d1 / (d1 - d3)
        qx, qy, qz = apx - v * abx, apy - v * aby, apz - v * abz
        return qx * qx + qy * qy + qz * qz
    cpx, cpy, cpz = px - cx, py - cy, pz - cz
    d5 = abx * cpx + aby * cpy + abz * cpz
    d6 = acx * cpx + acy * cpy + acz * cpz
    if d6 >= 0 and d5 <= d6:
        return cpx * cpx + cpy * cpy + cpz * cpz
    vb = d5 * d2 - d1 * d6
    if vb <= 0 and d2 >= 0 and d6 <= 0:
        w = d2 / (d2 - d6)
        qx, qy, qz = apx - w * acx, apy - w * acy, apz - w * acz
        return qx * qx + qy * qy + qz * qz
    va = d3 * d6 - d5 * d4
    if va <= 0 and d4 - d3 >= 0 and d5 - d6 >= 0:
        w = (d4 - d3) / ((d4 - d3) + (d5 - d6))
        qx, qy, qz = bpx - w * (cx - bx), bpy - w * (cy - by), bpz - w * (cz - bz)
        return qx * qx + qy * qy + qz * qz
    s = va + vb + vc
    if s <= 0:
        # Degenerate (zero-area) triangle that no region claimed: the nearest of its three sides.
        return min(segment_d2(px, py, pz, ax, ay, az, bx, by, bz),
                   segment_d2(px, py, pz, bx, by, bz, cx, cy, cz),
                   segment_d2(px, py, pz, cx, cy, cz, ax, ay, az))
    v, w = vb / s, vc / s
    qx, qy, qz = apx - abx * v - acx * w, apy - aby * v - acy * w, apz - abz * v - acz * w
    return qx * qx + qy * qy + qz * qz


def segment_d2(px, py, pz, ax, ay, az, bx, by, bz):
    ex, ey, ez = bx - ax, by - ay, bz - az
    ee = ex * ex + ey * ey + ez * ez
    t = ((px - ax) * ex + (py - ay) * ey + (pz - az) * ez) / ee if ee > 0 else 0.0
    t = 0.0 if t < 0 else 1.0 if t > 1 else t
    qx, qy, qz = px - ax - t * ex, py - ay - t * ey, pz - az - t * ez
    return qx * qx + qy * qy + qz * qz


class TriangleHash:
    """A uniform grid of cells (a dict of the occupied ones), each listing the triangles whose
    bounding box meets it."""

    def __init__(self, V, tris):
        self.T = []
        ext = 0.0
        lo = [float('inf')] * 3
        hi = [float('-inf')] * 3
        for f in tris:
            a, b, c = V[f[0]], V[f[1]], V[f[2]]
            box = [min(a[0], b[0], c[0]), min(a[1], b[1], c[1]), min(a[2], b[2], c[2]),
                   max(a[0], b[0], c[0]), max(a[1], b[1], c[1]), max(a[2], b[2], c[2])]
            self.T.append(tuple(a) + tuple(b) + tuple(c) + tuple(box))
            ext += max(box[3] - box[0], box[4] - box[1], box[5] - box[2])
            for j in range(3):
                lo[j] = min(lo[j], box[j]); hi[j] = max(hi[j], box[3 + j])
        diag = math.sqrt(sum((hi[j] - lo[j]) ** 2 for j in range(3))) if self.T else 0.0
        # Cells about as large as the average triangle, but not so small that a large triangle
        # would fill millions of them.
        self.h = max(ext / max(len(self.T), 1), diag / 400.0, 1e-300)
        self.o = lo
        self.n = [int((hi[j] - lo[j]) / self.h) + 1 for j in range(3)] if self.T else [0, 0, 0]
        self.cells = {}
        nx, ny = self.n[0], self.n[1]
        for t, e in enumerate(self.T):
            i0, j0, k0 = self.index(e[9], e[10], e[11])
            i1, j1, k1 = self.index(e[12], e[13], e[14])
            for k in range(k0, k1 + 1):
                for j in range(j0, j1 + 1):
                    base = nx * (j + ny * k)
                    for i in range(i0, i1 + 1):
                        self.cells.setdefault(base + i, []).append(t)
        self.stamp = [-1] * len(self.T)
        self.queries = 0

    def index(self, x, y, z):
        h, o, n = self.h, self.o, self.n
        return (min(max(int((x - o[0]) // h), 0), n[0] - 1), min(max(int((y - o[1]) // h), 0), n[1] - 1),
                min(max(int((z - o[2]) // h), 0), n[2] - 1))

    def distance(self, p):
        """Distance from p to the nearest triangle (inf when there is none)."""
        if not self.T:
            return float('inf')
        px, py, pz = p
        h, o, (nx, ny, nz) = self.h, self.o, self.n
        fx, fy, fz = (px - o[0]) / h, (py - o[1]) / h, (pz - o[2]) / h
        ix, iy, iz = math.floor(fx), math.floor(fy), math.floor(fz)
        # Distance from p to the walls of its own (possibly virtual) cell.
        m = h * min(fx - ix, ix + 1 - fx, fy - iy, iy + 1 - fy, fz - iz, iz + 1 - fz)
        # Rings nearer than r0 do not meet the grid; none beyond rmax does.
        r0 = max(0, -ix, ix - nx + 1, -iy, iy - ny + 1, -iz, iz - nz + 1)
        rmax = max(ix, nx - 1 - ix, iy, ny - 1 - iy, iz, nz - 1 - iz)
        self.queries += 1
        q, stamp, T, cells = self.queries, self.stamp, self.T, self.cells
        best = float('inf')
        for r in range(r0, rmax + 1):
            if r >= 1:
                bound = (r - 1) * h + m
                if bound > 0 and bound * bound >= best:
                    break
            xs = range(max(ix - r, 0), min(ix + r, nx - 1) + 1)
            ys = range(max(iy - r, 0), min(iy + r, ny - 1) + 1)
            for k in range(max(iz - r, 0), min(iz + r, nz - 1) + 1):
                kface = abs(k - iz) == r
                for j in ys:
                    base = nx * (j + ny * k)
                    if kface or abs(j - iy) == r:
                        row = xs
                    else:
                        row = [i for i in (ix - r, ix + r) if 0 <= i < nx]
                    for i in row:
                        c = cells.get(base + i)
                        if c is None:
                            continue
                        for t in c:
                            if stamp[t] == q:
                                continue
                            stamp[t] = q
                            e = T[t]
                            dx = e[9] - px if px < e[9] else px - e[12] if px > e[12] else 0.0
                            dy = e[10] - py if py < e[10] else py - e[13] if py > e[13] else 0.0
                            dz = e[11] - pz if pz < e[11] else pz - e[14] if pz > e[14] else 0.0
                            if dx * dx + dy * dy + dz * dz >= best:
                                continue
                            d2 = point_triangle_d2(px, py, pz, e)
                            if d2 < best:
                                best = d2
        return math.sqrt(best)


def one_sided(V_from, points, V_to, tris):
    """Largest distance from the points to the triangles."""
    grid = TriangleHash(V_to, tris)
    worst = 0.0
    for i in points:
        d = grid.distance(V_from[i])
        if d > worst:
            worst = d
    return worst


def check(hexm, tetm):
    V, H = hexm['V'], hexm['H']
    TV, T = tetm['V'], tetm['T']
    if not T:
        raise InputError('the tet mesh has no Tetrahedra')
    times = {}
    t0 = time.time()
    inverted, sj, hex_volume = hex_quality(V, H)
    quads, overused, open_edges = hex_boundary(H)
    closed = overused == 0 and open_edges == 0 and len(quads) > 0
    times['hexes'] = time.time() - t0
    t0 = time.time()
    tris, tet_volume = tet_boundary(TV, T)
    used = sorted({i for t in T for i in t})
    lo = [min(TV[i][j] for i in used) for j in range(3)]
    hi = [max(TV[i][j] for i in used) for j in range(3)]
    diag = math.sqrt(sum((hi[j] - lo[j]) ** 2 for j in range(3)))
    qtris = [(q[0], q[1], q[2]) for q in quads] + [(q[0], q[2], q[3]) for q in quads]
    hex_points = sorted({i for q in quads for i in q})
    tet_points = sorted({i for f in tris for i in f})
    if quads:
        to_tets = one_sided(V, hex_points, TV, tris)
        to_hex = one_sided(TV, tet_points, V, qtris)
    else:
        to_tets = to_hex = float('inf')
    times['distance'] = time.time() - t0
    unit = diag if diag > 0 else 1.0
    n = len(H)
    ok = n > 0 and inverted == 0 and closed
    def num(x):
        return x if math.isfinite(x) else 'inf'
    return dict(
        hexes=n, vertices=len(V), inverted=inverted,
        scaled_jacobian_min=min(sj) if sj else None,
        scaled_jacobian_mean=sum(sj) / n if n else None,
        boundary_closed=closed, boundary_quads=len(quads), open_boundary_edges=open_edges,
        overused_faces=overused,
        hex_volume=hex_volume, tet_volume=tet_volume,
        volume_ratio=hex_volume / tet_volume if tet_volume > 0 else None,
        hausdorff=num(max(to_tets, to_hex) / unit), hausdorff_hex_to_tets=num(to_tets / unit),
        hausdorff_tets_to_hex=num(to_hex / unit), diagonal=diag,
        tets=len(T), tet_boundary_triangles=len(tris),
        seconds={k: round(v, 3) for k, v in times.items()}, ok=ok)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--hex', required=True, help='the hex mesh (Medit .mesh with Hexahedra)')
    ap.add_argument('--tets', required=True, help='the tet mesh it was made from')
    a = ap.parse_args()
    try:
        hexm = read_medit(a.hex)
        tetm = read_medit(a.tets)
        if not tetm['T']:
            raise InputError('%s: no Tetrahedra section (or an empty one)' % a.tets)
        report = check(hexm, tetm)
    except (OSError, InputError) as e:
        message = str(e).replace('\n', ' ')
        print(json.dumps(dict(ok=False, error=message)))
        print('check_hex.py: ' + message, file=sys.stderr)
        return 2
    print(json.dumps(report))
    return 0 if report['ok'] else 1


if __name__ == '__main__':
    sys.exit(main())
