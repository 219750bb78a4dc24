#include "frontends/polycube/tet_boundary_fans.h"

#include <algorithm>

#include "geometry/detail/union_find.h"
#include "optim/errors.h"

namespace sa {

namespace {

Eigen::Vector3d at(const Eigen::MatrixXd& positions, Index v) {
    return positions.row(v).transpose();
}

/// Groups `tets` (all containing `shared`, 1 or 2 vertices) by the facets through `shared` they
/// share.
std::vector<std::vector<Index>> sheets(const SimplicialMesh& mesh, const MeshTopology& topology,
                                       const std::vector<Index>& tets,
                                       const std::vector<Index>& shared) {
    UnionFind group(Index(tets.size()));
    for (std::size_t i = 0; i < tets.size(); ++i) {
        for (int k = 0; k < 4; ++k) {
            // The facet opposite k contains every shared vertex unless k is one of them.
            const Index opposite = mesh.simplices(tets[i], k);
            if (std::find(shared.begin(), shared.end(), opposite) != shared.end()) continue;
            const Index n = topology.neighbour_of(tets[i], k);
            if (n < 0) continue;
            const auto j = std::find(tets.begin(), tets.end(), n) - tets.begin();
            if (j < Index(tets.size())) group.join(Index(i), Index(j));
        }
    }
    std::vector<std::vector<Index>> out;
    std::vector<int> slot(tets.size(), -1);
    for (std::size_t i = 0; i < tets.size(); ++i) {
        const Index r = group.find(Index(i));
        if (slot[r] < 0) {
            slot[r] = int(out.size());
            out.emplace_back();
        }
        out[slot[r]].push_back(tets[i]);
    }
    return out;
}

bool has_boundary_facet_through(const SimplicialMesh& mesh, const TetBoundary& boundary,
                                const std::vector<Index>& tets, const std::vector<Index>& shared) {
    for (const Index t : tets) {
        for (int k = 0; k < 4; ++k) {
            if (boundary.of_tet_facet[4 * t + k] < 0) continue;
            if (std::find(shared.begin(), shared.end(), mesh.simplices(t, k)) == shared.end()) {
                return true;
            }
        }
    }
    return false;
}

void add_ring(std::vector<Index>& ring, Index v) {
    if (std::find(ring.begin(), ring.end(), v) == ring.end()) ring.push_back(v);
}

}  // namespace

std::vector<BoundaryEdgeFan> boundary_edge_fans(const SimplicialMesh& mesh,
                                                const MeshTopology& topology,
                                                const TetBoundary& boundary) {
    std::vector<BoundaryEdgeFan> fans;
    fans.reserve(boundary.edges.size());
    for (const auto& edge : boundary.edges) {
        const Index p = edge[0], q = edge[1];
        std::vector<Index> around;
        for (Index i = topology.vertex_begin[p]; i < topology.vertex_begin[p + 1]; ++i) {
            const Index t = topology.simplices_of_vertex[i];
            for (int k = 0; k < 4; ++k) {
                if (mesh.simplices(t, k) == q) around.push_back(t);
            }
        }
        for (const std::vector<Index>& sheet : sheets(mesh, topology, around, {p, q})) {
            if (!has_boundary_facet_through(mesh, boundary, sheet, {p, q})) continue;
            BoundaryEdgeFan fan;
            fan.edge = edge;
            for (const Index t : sheet) {
                std::array<Index, 2> rs{};
                int m = 0;
                for (int k = 0; k < 4; ++k) {
                    const Index v = mesh.simplices(t, k);
                    if (v != p && v != q) rs[m++] = v;
                }
                const Eigen::Vector3d o = at(mesh.vertices, p);
                Eigen::Matrix3d e;
                e << at(mesh.vertices, q) - o, at(mesh.vertices, rs[0]) - o,
                    at(mesh.vertices, rs[1]) - o;
                if (e.determinant() < 0.0) std::swap(rs[0], rs[1]);
                fan.tets.push_back(t);
                fan.others.push_back(rs);
                add_ring(fan.ring, rs[0]);
                add_ring(fan.ring, rs[1]);
            }
            fans.push_back(std::move(fan));
        }
    }
    return fans;
}

std::vector<BoundaryVertexStar> boundary_vertex_stars(const SimplicialMesh& mesh,
                                                      const MeshTopology& topology,
                                                      const TetBoundary& boundary) {
    std::vector<BoundaryVertexStar> stars;
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        if (!boundary.on_boundary[v]) continue;
        const std::vector<Index> around(
            topology.simplices_of_vertex.begin() + topology.vertex_begin[v],
            topology.simplices_of_vertex.begin() + topology.vertex_begin[v + 1]);
        for (const std::vector<Index>& sheet : sheets(mesh, topology, around, {v})) {
            if (!has_boundary_facet_through(mesh, boundary, sheet, {v})) continue;
            BoundaryVertexStar star;
            star.vertex = v;
            for (const Index t : sheet) {
                std::array<Index, 3> abc{};
                int m = 0;
                for (int k = 0; k < 4; ++k) {
                    if (mesh.simplices(t, k) != v) abc[m++] = mesh.simplices(t, k);
                }
                const Eigen::Vector3d o = at(mesh.vertices, v);
                Eigen::Matrix3d e;
                e << at(mesh.vertices, abc[0]) - o, at(mesh.vertices, abc[1]) - o,
                    at(mesh.vertices, abc[2]) - o;
                if (e.determinant() < 0.0) std::swap(abc[1], abc[2]);
                star.tets.push_back(t);
                star.others.push_back(abc);
                for (const Index u : abc) add_ring(star.ring, u);
            }
            stars.push_back(std::move(star));
        }
    }
    return stars;
}

}  // namespace sa
