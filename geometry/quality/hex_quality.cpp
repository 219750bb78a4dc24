#include "geometry/quality/hex_quality.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace sa {

namespace {

Eigen::Vector3d corner(const HexMesh& mesh, Index h, int c) {
    return mesh.positions.row(mesh.hexes(h, c)).transpose();
}

/// The three edges of corner c of hex h, as columns.
Eigen::Matrix3d corner_edges(const HexMesh& mesh, Index h, int c) {
    const Eigen::Vector3d x = corner(mesh, h, c);
    Eigen::Matrix3d edges;
    for (int k = 0; k < 3; ++k) edges.col(k) = corner(mesh, h, kHexCornerEdges[c][k]) - x;
    return edges;
}

}  // namespace

double hex_corner_jacobian(const HexMesh& mesh, Index h, int c) {
    return corner_edges(mesh, h, c).determinant();
}

double hex_scaled_jacobian(const HexMesh& mesh, Index h) {
    double worst = 1.0;
    for (int c = 0; c < 8; ++c) {
        Eigen::Matrix3d edges = corner_edges(mesh, h, c);
        for (int k = 0; k < 3; ++k) {
            const double length = edges.col(k).norm();
            if (!(length > 0.0)) return 0.0;
            edges.col(k) /= length;
        }
        worst = std::min(worst, edges.determinant());
    }
    return worst;
}

double hex_min_corner_jacobian(const HexMesh& mesh, Index h) {
    double worst = hex_corner_jacobian(mesh, h, 0);
    for (int c = 1; c < 8; ++c) worst = std::min(worst, hex_corner_jacobian(mesh, h, c));
    return worst;
}

double hex_volume(const HexMesh& mesh, Index h) {
    double volume = 0.0;
    for (const auto& t : kHexTetrahedra) {
        const Eigen::Vector3d a = corner(mesh, h, t[0]);
        Eigen::Matrix3d edges;
        for (int k = 0; k < 3; ++k) edges.col(k) = corner(mesh, h, t[k + 1]) - a;
        volume += edges.determinant() / 6.0;
    }
    return volume;
}

HexQuality hex_quality(const HexMesh& mesh) {
    HexQuality q;
    const Index n = mesh.num_hexes();
    q.scaled_jacobian.resize(n);
    double sum = 0.0;
    q.min_scaled_jacobian = n > 0 ? 1.0 : 0.0;
    for (Index h = 0; h < n; ++h) {
        const double sj = hex_scaled_jacobian(mesh, h);
        q.scaled_jacobian[h] = sj;
        sum += sj;
        q.min_scaled_jacobian = std::min(q.min_scaled_jacobian, sj);
        if (!(hex_min_corner_jacobian(mesh, h) > 0.0)) ++q.inverted;
        const int bin = sj <= 0.0 ? 0 : std::clamp(static_cast<int>(std::ceil(sj * 10.0)), 1, 10);
        ++q.histogram[bin];
        q.volume += hex_volume(mesh, h);
    }
    q.mean_scaled_jacobian = n > 0 ? sum / double(n) : 0.0;
    return q;
}

HexBoundary hex_boundary(const HexMesh& mesh) {
    // Faces keyed by their sorted vertices: the hexes' faces that appear once are the boundary.
    std::map<std::array<int, 4>, std::pair<int, std::array<int, 4>>> faces;
    for (Index h = 0; h < mesh.num_hexes(); ++h) {
        for (const auto& f : kHexFaces) {
            std::array<int, 4> face;
            for (int k = 0; k < 4; ++k) face[k] = mesh.hexes(h, f[k]);
            std::array<int, 4> key = face;
            std::sort(key.begin(), key.end());
            auto [it, inserted] = faces.try_emplace(key, 0, face);
            ++it->second.first;
        }
    }
    HexBoundary out;
    std::vector<std::array<int, 4>> quads;
    std::map<std::pair<int, int>, int> edge_uses;
    for (const auto& [key, value] : faces) {
        const auto& [count, face] = value;
        if (count > 2) ++out.faces_in_more_than_two_hexes;
        if (count != 1) continue;
        quads.push_back(face);
        for (int k = 0; k < 4; ++k) {
            const int a = face[k], b = face[(k + 1) % 4];
            ++edge_uses[{std::min(a, b), std::max(a, b)}];
        }
    }
    for (const auto& [edge, uses] : edge_uses)
        if (uses != 2) ++out.open_edges;
    out.quads.resize(static_cast<Eigen::Index>(quads.size()), 4);
    out.on_boundary.assign(mesh.num_vertices(), 0);
    for (std::size_t i = 0; i < quads.size(); ++i) {
        for (int k = 0; k < 4; ++k) {
            out.quads(static_cast<Eigen::Index>(i), k) = quads[i][k];
            out.on_boundary[quads[i][k]] = 1;
        }
    }
    return out;
}

Index boundary_locked_inverted_corners(const HexMesh& mesh, const HexBoundary& boundary) {
    Index count = 0;
    for (Index h = 0; h < mesh.num_hexes(); ++h) {
        for (int c = 0; c < 8; ++c) {
            bool locked = boundary.on_boundary[mesh.hexes(h, c)] != 0;
            for (const int k : kHexCornerEdges[c])
                locked &= boundary.on_boundary[mesh.hexes(h, k)] != 0;
            if (locked && !(hex_corner_jacobian(mesh, h, c) > 0.0)) ++count;
        }
    }
    return count;
}

}  // namespace sa
