#include "geometry/mesh/tet_boundary.h"

#include <Eigen/Geometry>
#include <algorithm>

#include "geometry/detail/union_find.h"
#include "optim/errors.h"

namespace sa {

int tet_orientation(const SimplicialMesh& mesh, Index t) {
    const Eigen::Vector3d p0 = mesh.vertices.row(mesh.simplices(t, 0)).transpose();
    Eigen::Matrix3d edges;
    for (int k = 0; k < 3; ++k) {
        edges.col(k) = mesh.vertices.row(mesh.simplices(t, k + 1)).transpose() - p0;
    }
    return edges.determinant() > 0.0 ? 1 : -1;
}

std::array<Index, 3> tet_facet_vertices(const SimplicialMesh& mesh, Index t, int k) {
    return {mesh.simplices(t, kTetFacetCorners[k][0]), mesh.simplices(t, kTetFacetCorners[k][1]),
            mesh.simplices(t, kTetFacetCorners[k][2])};
}

Eigen::Vector3d tet_facet_area_vector(const Eigen::MatrixXd& positions, const SimplicialMesh& mesh,
                                      Index t, int k, int orientation) {
    const std::array<Index, 3> f = tet_facet_vertices(mesh, t, k);
    const Eigen::Vector3d a = positions.row(f[0]).transpose(), b = positions.row(f[1]).transpose(),
                          c = positions.row(f[2]).transpose();
    return 0.5 * orientation * (b - a).cross(c - a);
}

TetBoundary tet_boundary(const SimplicialMesh& mesh, const MeshTopology& topology) {
    if (mesh.simplices.cols() != 4 || mesh.vertices.cols() != 3) {
        throw InvalidArgumentError("tet_boundary: the mesh must be tetrahedra in 3D");
    }
    TetBoundary boundary;
    const Index nb = static_cast<Index>(topology.boundary_facets.size());
    boundary.tet_facet.resize(nb);
    boundary.triangles.resize(nb, 3);
    boundary.of_tet_facet.assign(4 * std::size_t(mesh.num_simplices()), -1);
    boundary.on_boundary.assign(mesh.num_vertices(), 0);
    // Boundary facets in tet-facet order, so that the numbering does not depend on how the
    // topology sorted them.
    std::vector<Index> order(nb);
    for (Index b = 0; b < nb; ++b) {
        const BoundaryFacet& f = topology.boundary_facets[b];
        order[b] = 4 * f.simplex + f.opposite;
    }
    std::sort(order.begin(), order.end());
    for (Index b = 0; b < nb; ++b) {
        const Index t = order[b] / 4;
        const int k = order[b] % 4;
        boundary.tet_facet[b] = order[b];
        boundary.of_tet_facet[order[b]] = b;
        std::array<Index, 3> v = tet_facet_vertices(mesh, t, k);
        if (tet_orientation(mesh, t) < 0) std::swap(v[1], v[2]);
        for (int i = 0; i < 3; ++i) {
            boundary.triangles(b, i) = v[i];
            boundary.on_boundary[v[i]] = 1;
        }
    }
    // Adjacency across edges: sort the triangles' sides by their vertex pair.
    struct Side {
        std::array<Index, 2> edge;
        Index triangle;
        int side;
        bool operator<(const Side& o) const {
            return edge != o.edge ? edge < o.edge : triangle < o.triangle;
        }
    };
    std::vector<Side> sides;
    sides.reserve(3 * std::size_t(nb));
    for (Index b = 0; b < nb; ++b) {
        for (int i = 0; i < 3; ++i) {
            Index p = boundary.triangles(b, i), q = boundary.triangles(b, (i + 1) % 3);
            if (p > q) std::swap(p, q);
            sides.push_back({{p, q}, b, i});
        }
    }
    std::sort(sides.begin(), sides.end());
    boundary.adjacent.assign(nb, {-1, -1, -1});
    for (std::size_t i = 0; i < sides.size();) {
        std::size_t j = i + 1;
        while (j < sides.size() && sides[j].edge == sides[i].edge) ++j;
        boundary.edges.push_back(sides[i].edge);
        if (j - i == 2) {
            boundary.adjacent[sides[i].triangle][sides[i].side] = sides[i + 1].triangle;
            boundary.adjacent[sides[i + 1].triangle][sides[i + 1].side] = sides[i].triangle;
        }
        i = j;
    }
    return boundary;
}

Eigen::MatrixXd boundary_area_vectors(const TetBoundary& boundary,
                                      const Eigen::MatrixXd& positions) {
    Eigen::MatrixXd normals(boundary.size(), 3);
    for (Index b = 0; b < boundary.size(); ++b) {
        const Eigen::Vector3d a = positions.row(boundary.triangles(b, 0)).transpose(),
                              p = positions.row(boundary.triangles(b, 1)).transpose(),
                              c = positions.row(boundary.triangles(b, 2)).transpose();
        normals.row(b) = 0.5 * (p - a).cross(c - a).transpose();
    }
    return normals;
}

Index independent_loops(const TetBoundary& boundary) {
    UnionFind sets(boundary.size());
    for (Index b = 0; b < boundary.size(); ++b) {
        for (const Index n : boundary.adjacent[b]) {
            if (n < 0) {
                throw InvalidArgumentError(
                    "independent_loops: the boundary is not a closed manifold surface");
            }
            sets.join(b, n);
        }
    }
    Index components = 0, vertices = 0;
    for (Index b = 0; b < boundary.size(); ++b) components += sets.find(b) == b;
    for (const unsigned char on : boundary.on_boundary) vertices += on;
    const Index chi = vertices - Index(boundary.edges.size()) + boundary.size();
    return components - chi / 2;
}

}  // namespace sa
