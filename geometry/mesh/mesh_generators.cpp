#include "geometry/mesh/mesh_generators.h"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace sa {

SimplicialMesh grid_triangles(int nx, int ny) {
    SimplicialMesh mesh;
    mesh.vertices.resize((nx + 1) * (ny + 1), 2);
    for (int j = 0; j <= ny; ++j) {
        for (int i = 0; i <= nx; ++i)
            mesh.vertices.row(j * (nx + 1) + i) << double(i) / nx, double(j) / ny;
    }
    mesh.simplices.resize(2 * nx * ny, 3);
    int t = 0;
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            const int v = j * (nx + 1) + i;
            mesh.simplices.row(t++) << v, v + 1, v + nx + 2;
            mesh.simplices.row(t++) << v, v + nx + 2, v + nx + 1;
        }
    }
    return mesh;
}

SimplicialMesh grid_tetrahedra(int nx, int ny, int nz) {
    SimplicialMesh mesh;
    const double h = 1.0 / std::max({nx, ny, nz});
    auto index = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
    mesh.vertices.resize((nx + 1) * (ny + 1) * (nz + 1), 3);
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) mesh.vertices.row(index(i, j, k)) << i * h, j * h, k * h;
    // Kuhn: the six paths from corner 000 to 111 through the cube's axes.
    const std::array<std::array<int, 3>, 6> orders = {
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    mesh.simplices.resize(6 * nx * ny * nz, 4);
    int t = 0;
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
                for (const auto& order : orders) {
                    std::array<int, 3> c = {i, j, k};
                    std::array<int, 4> tet;
                    tet[0] = index(c[0], c[1], c[2]);
                    for (int step = 0; step < 3; ++step) {
                        ++c[order[step]];
                        tet[step + 1] = index(c[0], c[1], c[2]);
                    }
                    Eigen::Matrix3d e;
                    for (int a = 0; a < 3; ++a)
                        e.col(a) =
                            (mesh.vertices.row(tet[a + 1]) - mesh.vertices.row(tet[0])).transpose();
                    if (e.determinant() < 0) std::swap(tet[1], tet[2]);
                    mesh.simplices.row(t++) << tet[0], tet[1], tet[2], tet[3];
                }
    return mesh;
}

SimplicialMesh torus_triangles(int nu, int nv, double R, double r) {
    SimplicialMesh mesh;
    mesh.vertices.resize(nu * nv, 3);
    auto index = [&](int i, int j) { return (j % nv) * nu + (i % nu); };
    for (int j = 0; j < nv; ++j) {
        for (int i = 0; i < nu; ++i) {
            const double u = 2.0 * M_PI * i / nu, v = 2.0 * M_PI * j / nv;
            mesh.vertices.row(index(i, j)) << (R + r * std::cos(v)) * std::cos(u),
                (R + r * std::cos(v)) * std::sin(u), r * std::sin(v);
        }
    }
    mesh.simplices.resize(2 * nu * nv, 3);
    int t = 0;
    for (int j = 0; j < nv; ++j) {
        for (int i = 0; i < nu; ++i) {
            mesh.simplices.row(t++) << index(i, j), index(i + 1, j), index(i + 1, j + 1);
            mesh.simplices.row(t++) << index(i, j), index(i + 1, j + 1), index(i, j + 1);
        }
    }
    return mesh;
}

SimplicialMesh sphere_triangles(int n) {
    // Each octant's face x + y + z = 1 (signs flipped) sampled at (a, b, n - a - b) / n; vertices
    // shared between octants are merged by their integer coordinates.
    std::map<std::array<int, 3>, Index> id;
    std::vector<Eigen::Vector3d> points;
    auto vertex = [&](const std::array<int, 3>& c) {
        const auto [it, inserted] = id.try_emplace(c, Index(points.size()));
        if (inserted) points.push_back(Eigen::Vector3d(c[0], c[1], c[2]).normalized());
        return it->second;
    };
    std::vector<std::array<Index, 3>> faces;
    for (int octant = 0; octant < 8; ++octant) {
        const int sx = octant & 1 ? -1 : 1, sy = octant & 2 ? -1 : 1, sz = octant & 4 ? -1 : 1;
        auto at = [&](int a, int b) { return vertex({sx * a, sy * b, sz * (n - a - b)}); };
        const bool flip = sx * sy * sz < 0;  // keep the normals outward
        auto add = [&](Index p, Index q, Index w) {
            faces.push_back(flip ? std::array<Index, 3>{p, w, q} : std::array<Index, 3>{p, q, w});
        };
        for (int a = 0; a < n; ++a) {
            for (int b = 0; a + b < n; ++b) {
                add(at(a, b), at(a + 1, b), at(a, b + 1));
                if (a + b + 1 < n) add(at(a + 1, b), at(a + 1, b + 1), at(a, b + 1));
            }
        }
    }
    SimplicialMesh mesh;
    mesh.vertices.resize(points.size(), 3);
    for (std::size_t v = 0; v < points.size(); ++v) mesh.vertices.row(v) = points[v].transpose();
    mesh.simplices.resize(faces.size(), 3);
    for (std::size_t f = 0; f < faces.size(); ++f)
        mesh.simplices.row(f) << faces[f][0], faces[f][1], faces[f][2];
    return mesh;
}

}  // namespace sa
