#pragma once
// Generated tetrahedral meshes with PolyCube-like shapes, for the PolyCube tests.

#include <Eigen/Geometry>
#include <array>
#include <map>
#include <random>
#include <vector>

#include "geometry/polycube_labeling.h"
#include "geometry/simplicial_mesh.h"

namespace sa::testing {

using Cell = std::array<int, 3>;

/// The union of the unit cubes with lower corners `cells`, each cut into n^3 cubes of six
/// positively oriented Kuhn tetrahedra (conforming across cubes), sharing vertices.
inline SimplicialMesh voxel_tetrahedra(const std::vector<Cell>& cells, int n = 1) {
    std::map<Cell, Index> index;
    std::vector<Eigen::Vector3d> points;
    auto vertex = [&](const Cell& p) {
        const auto [it, inserted] = index.emplace(p, Index(points.size()));
        if (inserted) points.emplace_back(p[0] / double(n), p[1] / double(n), p[2] / double(n));
        return it->second;
    };
    const std::array<std::array<int, 3>, 6> orders = {
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    std::vector<std::array<Index, 4>> tets;
    for (const Cell& cell : cells) {
        for (int a = 0; a < n; ++a) {
            for (int b = 0; b < n; ++b) {
                for (int c = 0; c < n; ++c) {
                    for (const auto& order : orders) {
                        Cell p = {cell[0] * n + a, cell[1] * n + b, cell[2] * n + c};
                        std::array<Index, 4> tet{};
                        tet[0] = vertex(p);
                        for (int step = 0; step < 3; ++step) {
                            ++p[order[step]];
                            tet[step + 1] = vertex(p);
                        }
                        Eigen::Matrix3d e;
                        for (int k = 0; k < 3; ++k) e.col(k) = points[tet[k + 1]] - points[tet[0]];
                        if (e.determinant() < 0) std::swap(tet[1], tet[2]);
                        tets.push_back(tet);
                    }
                }
            }
        }
    }
    SimplicialMesh mesh;
    mesh.vertices.resize(Index(points.size()), 3);
    for (std::size_t v = 0; v < points.size(); ++v) mesh.vertices.row(Index(v)) = points[v];
    mesh.simplices.resize(Index(tets.size()), 4);
    for (std::size_t t = 0; t < tets.size(); ++t) {
        for (int k = 0; k < 4; ++k) mesh.simplices(Index(t), k) = tets[t][k];
    }
    return mesh;
}

/// An L-shaped block of three unit cubes.
inline std::vector<Cell> l_shape() {
    return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
}

/// A square ring of 3 x 3 unit cubes without the middle one, `layers` cubes high: a solid with
/// one handle.
inline std::vector<Cell> ring(int layers = 1) {
    std::vector<Cell> cells;
    for (int z = 0; z < layers; ++z)
        for (int x = 0; x < 3; ++x)
            for (int y = 0; y < 3; ++y)
                if (x != 1 || y != 1) cells.push_back({x, y, z});
    return cells;
}

/// A smooth deformation that keeps every face of a voxel shape closest to its own axis: each
/// coordinate bent by a small sine of the others.
inline SimplicialMesh bent(SimplicialMesh mesh, double amplitude) {
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        const Eigen::Vector3d p = mesh.vertices.row(v).transpose();
        mesh.vertices(v, 0) += amplitude * std::sin(1.3 * p.y() + 0.7 * p.z());
        mesh.vertices(v, 1) += amplitude * std::sin(0.9 * p.z() + 1.1 * p.x());
        mesh.vertices(v, 2) += amplitude * std::sin(1.2 * p.x() + 0.8 * p.y());
    }
    return mesh;
}

/// The box [-1, 1]^2 x [0, 1] as a fan of wedges about its vertical axis: each side of the top
/// and bottom squares divided into `per_side` edges, every wedge (the two centres, two
/// neighbouring points of the top square and the two below them) cut into three positively
/// oriented tetrahedra, one of them on the axis. The two centres are boundary vertices with more
/// than 4 per_side neighbours (vertex 0: the top centre; 1: the bottom one).
inline SimplicialMesh fan_box(int per_side) {
    const int n = 4 * per_side;
    std::vector<Eigen::Vector3d> points = {{0, 0, 1}, {0, 0, 0}};
    const std::array<Eigen::Vector2d, 5> corners = {{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}}};
    for (int z = 1; z >= 0; --z) {
        for (int i = 0; i < n; ++i) {
            const int side = i / per_side;
            const double t = double(i % per_side) / per_side;
            const Eigen::Vector2d q = (1 - t) * corners[side] + t * corners[side + 1];
            points.emplace_back(q.x(), q.y(), double(z));
        }
    }
    auto top = [&](int i) { return Index(2 + i % n); };
    auto bottom = [&](int i) { return Index(2 + n + i % n); };
    std::vector<std::array<Index, 4>> tets;
    for (int i = 0; i < n; ++i) {
        tets.push_back({0, 1, top(i), top(i + 1)});
        tets.push_back({1, top(i), top(i + 1), bottom(i + 1)});
        tets.push_back({1, top(i), bottom(i + 1), bottom(i)});
    }
    SimplicialMesh mesh;
    mesh.vertices.resize(Index(points.size()), 3);
    for (std::size_t v = 0; v < points.size(); ++v) mesh.vertices.row(Index(v)) = points[v];
    mesh.simplices.resize(Index(tets.size()), 4);
    for (std::size_t t = 0; t < tets.size(); ++t) {
        auto tet = tets[t];
        Eigen::Matrix3d e;
        for (int k = 0; k < 3; ++k) e.col(k) = points[tet[k + 1]] - points[tet[0]];
        if (e.determinant() < 0) std::swap(tet[1], tet[2]);
        for (int k = 0; k < 4; ++k) mesh.simplices(Index(t), k) = tet[k];
    }
    return mesh;
}

/// The same tetrahedra with two vertices of every tetrahedron swapped: all negatively oriented.
inline SimplicialMesh reversed(SimplicialMesh mesh) {
    mesh.simplices.col(1).swap(mesh.simplices.col(2));
    return mesh;
}

/// The unit cube cut into 12^3 voxels, labelled by closest axis, with a hook of +X on its +Y face
/// (y = 1): a bar of 6 x 2 voxels from the +X|+Y edge at z in [0.5, 0.5 + 2/12], and at its far
/// end a leg of 2 voxels hanging down 4 voxels below the bar. The +X|+Y boundary runs up the
/// cube's edge, around the bar and the leg and back: down the leg's inner side, against the
/// direction (+Z) of the rest of it.
struct HookedCube {
    static constexpr int kResolution = 12;

    SimplicialMesh mesh = voxel_tetrahedra({{0, 0, 0}}, kResolution);
    TetBoundary boundary = tet_boundary(mesh, mesh_topology(mesh, "cube"));
    std::vector<int> labels = closest_axis_labels(boundary, mesh.vertices);

    void add_hook() {
        const double h = 1.0 / kResolution;
        for (Index b = 0; b < boundary.size(); ++b) {
            Eigen::Vector3d c = Eigen::Vector3d::Zero();
            for (int i = 0; i < 3; ++i) c += mesh.vertices.row(boundary.triangles(b, i));
            c /= 3.0;
            if (labels[b] != 2) continue;  // +Y
            const bool bar = c.x() > 1.0 - 6 * h && c.z() > 0.5 && c.z() < 0.5 + 2 * h;
            const bool leg = c.x() > 1.0 - 6 * h && c.x() < 1.0 - 4 * h && c.z() > 0.5 - 4 * h &&
                             c.z() < 0.5 + 2 * h;
            if (bar || leg) labels[b] = 0;  // +X
        }
    }
};

}  // namespace sa::testing
