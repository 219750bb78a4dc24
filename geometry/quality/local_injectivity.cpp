#include "geometry/quality/local_injectivity.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "optim/errors.h"

namespace sa {

namespace {

/// +1 where a planar triangle is listed counterclockwise, -1 where clockwise; +1 for triangles in
/// space (their rest frames are always positively oriented, simplicial_mesh.h).
double rest_orientation(const SimplicialMesh& mesh, Index s) {
    if (mesh.ambient_dimension() != 2) return 1.0;
    const Eigen::Vector3d a = mesh.point(mesh.simplices(s, 0)),
                          b = mesh.point(mesh.simplices(s, 1)),
                          c = mesh.point(mesh.simplices(s, 2));
    return (b - a).cross(c - a).z() >= 0.0 ? 1.0 : -1.0;
}

/// The whole number k of an angle sum 2 pi k, or -1 when the sum is not within a quarter turn of
/// one (not a full wrap: a fan that does not close up).
long turns(double sum) {
    const double k = std::round(sum / (2.0 * M_PI));
    return std::abs(sum - 2.0 * M_PI * k) < 0.5 * M_PI ? static_cast<long>(k) : -1;
}

}  // namespace

std::vector<Index> branched_vertices(const SimplicialMesh& mesh, const MeshTopology& topology,
                                     const Eigen::MatrixXd& positions) {
    if (mesh.simplex_dimension() != 2 || positions.cols() < 2 ||
        positions.rows() != mesh.num_vertices()) {
        throw InvalidArgumentError("branched_vertices: a triangle mesh and #V x 2 positions");
    }
    std::vector<double> sum(mesh.num_vertices(), 0.0);
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        const double orientation = rest_orientation(mesh, s);
        for (int k = 0; k < 3; ++k) {
            const Index v = mesh.simplices(s, k);
            const Eigen::Vector2d p = positions.row(v).head<2>().transpose();
            // Unit edges: the angle does not depend on their lengths, and products of raw
            // coordinates would overflow or underflow on meshes at 1e+-200.
            const Eigen::Vector2d e1 =
                (positions.row(mesh.simplices(s, (k + 1) % 3)).head<2>().transpose() - p)
                    .stableNormalized();
            const Eigen::Vector2d e2 =
                (positions.row(mesh.simplices(s, (k + 2) % 3)).head<2>().transpose() - p)
                    .stableNormalized();
            sum[v] += orientation * std::atan2(e1.x() * e2.y() - e1.y() * e2.x(), e1.dot(e2));
        }
    }
    std::vector<Index> branched;
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        if (topology.used_vertex[v] && !topology.boundary_vertex[v] && turns(sum[v]) != 1)
            branched.push_back(v);
    }
    return branched;
}

std::vector<Index> branched_edges(const SimplicialMesh& mesh, const MeshTopology& topology,
                                  const Eigen::MatrixXd& positions) {
    if (mesh.simplex_dimension() != 3 || positions.cols() < 3 ||
        positions.rows() != mesh.num_vertices()) {
        throw InvalidArgumentError("branched_edges: a tetrahedral mesh and #V x 3 positions");
    }
    const auto& edges = topology.edges;
    auto edge_index = [&](Index a, Index b) {
        const std::array<Index, 2> key{std::min(a, b), std::max(a, b)};
        return static_cast<Index>(std::lower_bound(edges.begin(), edges.end(), key) -
                                  edges.begin());
    };
    std::vector<unsigned char> on_boundary(edges.size(), 0);
    for (const BoundaryFacet& f : topology.boundary_facets) {
        for (int k = 0; k < 3; ++k)
            on_boundary[edge_index(f.vertices[k], f.vertices[(k + 1) % 3])] = 1;
    }
    std::vector<double> sum(edges.size(), 0.0);
    static constexpr int kEdge[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                        {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        Eigen::Vector3d p[4];
        for (int k = 0; k < 4; ++k)
            p[k] = positions.row(mesh.simplices(s, k)).head<3>().transpose();
        for (const auto& e : kEdge) {
            // The dihedral angle at edge ab between the faces abc and abd, from unit edges (the
            // angle does not depend on their lengths; raw products overflow at 1e+-200).
            const Eigen::Vector3d ab = (p[e[1]] - p[e[0]]).stableNormalized();
            const Eigen::Vector3d n1 = ab.cross((p[e[2]] - p[e[0]]).stableNormalized()),
                                  n2 = ab.cross((p[e[3]] - p[e[0]]).stableNormalized());
            sum[edge_index(mesh.simplices(s, e[0]), mesh.simplices(s, e[1]))] +=
                std::atan2(n1.cross(n2).norm(), n1.dot(n2));
        }
    }
    std::vector<Index> branched;
    for (std::size_t e = 0; e < edges.size(); ++e) {
        if (!on_boundary[e] && turns(sum[e]) != 1) branched.push_back(static_cast<Index>(e));
    }
    return branched;
}

}  // namespace sa
