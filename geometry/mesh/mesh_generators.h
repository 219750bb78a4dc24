#pragma once
// Generated meshes, for tests, demos and benchmarks.

#include "geometry/mesh/simplicial_mesh.h"

namespace sa {

/// The unit square [0, 1]^2 cut into nx x ny cells of two triangles each (2D vertices,
/// counter-clockwise triangles). Vertex (i, j) has index j * (nx + 1) + i.
SimplicialMesh grid_triangles(int nx, int ny);

/// The box [0, nx/n] x [0, ny/n] x [0, nz/n], n = max(nx, ny, nz), cut into nx x ny x nz cubes
/// of six positively oriented tetrahedra each (Kuhn subdivision, conforming across cubes).
/// Vertex (i, j, k) has index (k * (ny + 1) + j) * (nx + 1) + i.
SimplicialMesh grid_tetrahedra(int nx, int ny, int nz);

/// A torus in space (major radius R, minor radius r): the periodic nu x nv grid of its angles,
/// two triangles per cell, outward normals. Closed, genus 1.
SimplicialMesh torus_triangles(int nu, int nv, double R = 1.0, double r = 0.4);

/// The unit sphere: an octahedron whose faces are each cut into n^2 triangles, vertices pushed
/// onto the sphere. Closed, genus 0, outward normals.
SimplicialMesh sphere_triangles(int n);

}  // namespace sa
