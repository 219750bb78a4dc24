#include "geometry/quality/local_injectivity.h"

#include <tbb/parallel_for.h>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <optional>

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

/// The local index (0..D) of vertex v in simplex s, which contains it.
int corner_of(const SimplicialMesh& mesh, Index s, Index v) {
    int k = 0;
    while (mesh.simplices(s, k) != v) ++k;
    return k;
}

/// The whole number k of an angle sum 2 pi k, or -1 when the sum is not within a quarter turn of
/// one (not a full wrap: a fan that does not close up).
long turns(double sum) {
    const double k = std::round(sum / (2.0 * M_PI));
    return std::abs(sum - 2.0 * M_PI * k) < 0.5 * M_PI ? static_cast<long>(k) : -1;
}

/// The position of an edge {a, b} in topology.edges (sorted pairs, lexicographic): a search
/// among the edges of the smaller end only.
class EdgeLookup {
  public:
    explicit EdgeLookup(const MeshTopology& topology) : edges_(topology.edges) {
        first_.assign(topology.vertex_begin.size() + 1, Index(edges_.size()));
        for (Index e = Index(edges_.size()) - 1; e >= 0; --e) first_[edges_[e][0]] = e;
        for (Index v = Index(first_.size()) - 2; v >= 0; --v)
            first_[v] = std::min(first_[v], first_[v + 1]);
    }
    Index operator()(Index a, Index b) const {
        const std::array<Index, 2> key{std::min(a, b), std::max(a, b)};
        return static_cast<Index>(std::lower_bound(edges_.begin() + first_[key[0]],
                                                   edges_.begin() + first_[key[0] + 1], key) -
                                  edges_.begin());
    }

  private:
    const std::vector<std::array<Index, 2>>& edges_;
    std::vector<Index> first_;  ///< the first edge whose smaller end is >= v
};

/// Per edge of a tetrahedral mesh (topology.edges): whether it lies on a boundary facet.
std::vector<unsigned char> boundary_edges(const MeshTopology& topology, const EdgeLookup& edge) {
    std::vector<unsigned char> on_boundary(topology.edges.size(), 0);
    for (const BoundaryFacet& f : topology.boundary_facets) {
        for (int k = 0; k < 3; ++k) on_boundary[edge(f.vertices[k], f.vertices[(k + 1) % 3])] = 1;
    }
    return on_boundary;
}

/// The local vertices of a tetrahedron's six edges, then of the two others.
constexpr int kTetEdge[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};

/// The unsigned dihedral angles of a tetrahedron (its corners, one per column) at its six edges,
/// in kTetEdge's order. At edge ab between the faces through c and d, with n1 = ab x ac and
/// n2 = ab x ad: |n1 x n2| = |ab| |det(ab, ac, ad)| and n1 . n2 = |ab|^2 (ac . ad) -
/// (ab . ad)(ab . ac). The edges are scaled to unit size first: the products neither overflow
/// nor underflow on meshes at 1e+-200.
std::array<double, 6> dihedral_angles(const Eigen::Matrix<double, 3, 4>& corners) {
    Eigen::Matrix<double, 3, 4> c = corners.colwise() - corners.col(0);
    const double size = c.cwiseAbs().maxCoeff();
    if (size > 0.0 && std::isfinite(size)) c /= size;
    std::array<double, 6> angles;
    for (int i = 0; i < 6; ++i) {
        const int* e = kTetEdge[i];
        const Eigen::Vector3d ab = c.col(e[1]) - c.col(e[0]), ac = c.col(e[2]) - c.col(e[0]),
                              ad = c.col(e[3]) - c.col(e[0]);
        angles[i] = std::atan2(ab.norm() * std::abs(ab.dot(ac.cross(ad))),
                               ab.squaredNorm() * ac.dot(ad) - ab.dot(ad) * ab.dot(ac));
    }
    return angles;
}

}  // namespace

TetEdges tet_edges(const SimplicialMesh& mesh, const MeshTopology& topology) {
    if (mesh.simplex_dimension() != 3) throw InvalidArgumentError("tet_edges: a tetrahedral mesh");
    const EdgeLookup edge_index(topology);
    TetEdges edges;
    edges.on_boundary = boundary_edges(topology, edge_index);
    edges.of_tet.resize(mesh.num_simplices());
    tbb::parallel_for(Index(0), mesh.num_simplices(), [&](Index s) {
        for (int i = 0; i < 6; ++i) {
            edges.of_tet[s][i] =
                edge_index(mesh.simplices(s, kTetEdge[i][0]), mesh.simplices(s, kTetEdge[i][1]));
        }
    });
    return edges;
}

template <>
std::vector<Index> wrapped_simplices<2>(const SimplicialMesh& mesh, const MeshTopology& topology,
                                        const RestFrames<2>& frames, const std::vector<Mat<2>>& A,
                                        const TetEdges*) {
    const Index nv = mesh.num_vertices(), n = mesh.num_simplices();
    if (Index(A.size()) != n || frames.size() != n) {
        throw InvalidArgumentError("wrapped_simplices: one linear part and frame per triangle");
    }
    // Per interior vertex, in parallel: the angles of its triangles, summed in the order of
    // topology.simplices_of_vertex (increasing triangle index).
    std::vector<unsigned char> wraps(nv, 0);
    tbb::parallel_for(Index(0), nv, [&](Index v) {
        if (topology.boundary_vertex[v]) return;
        double sum = 0.0;
        for (Index p = topology.vertex_begin[v]; p < topology.vertex_begin[v + 1]; ++p) {
            const Index s = topology.simplices_of_vertex[p];
            if (!(A[s].determinant() > 0.0)) return;  // a star with an inverted triangle
            const int k = corner_of(mesh, s, v);
            const Eigen::Matrix<double, 2, 3> c = A[s] * frames.corners[s];
            const Eigen::Vector2d e1 = (c.col((k + 1) % 3) - c.col(k)).stableNormalized(),
                                  e2 = (c.col((k + 2) % 3) - c.col(k)).stableNormalized();
            sum += std::atan2(e1.x() * e2.y() - e1.y() * e2.x(), e1.dot(e2));
        }
        wraps[v] = turns(sum) != 1;
    });
    std::vector<Index> wrapped;
    for (Index s = 0; s < n; ++s) {
        for (int k = 0; k < 3; ++k) {
            if (wraps[mesh.simplices(s, k)]) {
                wrapped.push_back(s);
                break;
            }
        }
    }
    return wrapped;
}

template <>
std::vector<Index> wrapped_simplices<3>(const SimplicialMesh& mesh, const MeshTopology& topology,
                                        const RestFrames<3>& frames, const std::vector<Mat<3>>& A,
                                        const TetEdges* edges) {
    const Index n = mesh.num_simplices();
    if (Index(A.size()) != n || frames.size() != n) {
        throw InvalidArgumentError("wrapped_simplices: one linear part and frame per tetrahedron");
    }
    std::optional<TetEdges> computed;
    if (edges == nullptr) edges = &computed.emplace(tet_edges(mesh, topology));
    if (Index(edges->of_tet.size()) != n || edges->on_boundary.size() != topology.edges.size())
        throw InvalidArgumentError("wrapped_simplices: the edges of another mesh");
    const std::vector<std::array<Index, 6>>& edge_of = edges->of_tet;
    const std::vector<unsigned char>& on_boundary = edges->on_boundary;
    // Per tetrahedron, in parallel: the signed dihedral angles at its edges (an inverted
    // tetrahedron turns the other way around the edge); then summed per edge.
    std::vector<std::array<double, 6>> angle_of(n);
    std::vector<unsigned char> up(n);
    tbb::parallel_for(Index(0), n, [&](Index s) {
        up[s] = A[s].determinant() > 0.0;
        const std::array<double, 6> angles = dihedral_angles(A[s] * frames.corners[s]);
        for (int i = 0; i < 6; ++i) angle_of[s][i] = up[s] ? angles[i] : -angles[i];
    });
    const std::size_t ne = topology.edges.size();
    std::vector<double> sum(ne, 0.0);
    std::vector<unsigned char> positive(ne, 1);
    for (Index s = 0; s < n; ++s) {
        for (int i = 0; i < 6; ++i) {
            sum[edge_of[s][i]] += angle_of[s][i];
            positive[edge_of[s][i]] &= up[s];
        }
    }
    std::vector<Index> wrapped;
    for (Index s = 0; s < n; ++s) {
        for (Index e : edge_of[s]) {
            if (!on_boundary[e] && positive[e] && turns(sum[e]) != 1) {
                wrapped.push_back(s);
                break;
            }
        }
    }
    return wrapped;
}

std::vector<Index> branched_vertices(const SimplicialMesh& mesh, const MeshTopology& topology,
                                     const Eigen::MatrixXd& positions) {
    if (mesh.simplex_dimension() != 2 || positions.cols() < 2 ||
        positions.rows() != mesh.num_vertices()) {
        throw InvalidArgumentError("branched_vertices: a triangle mesh and #V x 2 positions");
    }
    // Per interior vertex, in parallel, summed in the order of topology.simplices_of_vertex.
    const Index nv = mesh.num_vertices();
    std::vector<unsigned char> branched_at(nv, 0);
    tbb::parallel_for(Index(0), nv, [&](Index v) {
        if (!topology.used_vertex[v] || topology.boundary_vertex[v]) return;
        const Eigen::Vector2d p = positions.row(v).head<2>().transpose();
        double sum = 0.0;
        for (Index q = topology.vertex_begin[v]; q < topology.vertex_begin[v + 1]; ++q) {
            const Index s = topology.simplices_of_vertex[q];
            const int k = corner_of(mesh, s, v);
            // Unit edges: the angle does not depend on their lengths, and products of raw
            // coordinates would overflow or underflow on meshes at 1e+-200.
            const Eigen::Vector2d e1 =
                (positions.row(mesh.simplices(s, (k + 1) % 3)).head<2>().transpose() - p)
                    .stableNormalized();
            const Eigen::Vector2d e2 =
                (positions.row(mesh.simplices(s, (k + 2) % 3)).head<2>().transpose() - p)
                    .stableNormalized();
            sum += rest_orientation(mesh, s) *
                   std::atan2(e1.x() * e2.y() - e1.y() * e2.x(), e1.dot(e2));
        }
        branched_at[v] = turns(sum) != 1;
    });
    std::vector<Index> branched;
    for (Index v = 0; v < nv; ++v) {
        if (branched_at[v]) branched.push_back(v);
    }
    return branched;
}

std::vector<Index> branched_edges(const SimplicialMesh& mesh, const MeshTopology& topology,
                                  const Eigen::MatrixXd& positions) {
    if (mesh.simplex_dimension() != 3 || positions.cols() < 3 ||
        positions.rows() != mesh.num_vertices()) {
        throw InvalidArgumentError("branched_edges: a tetrahedral mesh and #V x 3 positions");
    }
    const TetEdges edges = tet_edges(mesh, topology);
    std::vector<double> sum(topology.edges.size(), 0.0);
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        Eigen::Matrix<double, 3, 4> corners;
        for (int k = 0; k < 4; ++k)
            corners.col(k) = positions.row(mesh.simplices(s, k)).head<3>().transpose();
        const std::array<double, 6> angles = dihedral_angles(corners);
        for (int i = 0; i < 6; ++i) sum[edges.of_tet[s][i]] += angles[i];
    }
    std::vector<Index> branched;
    for (std::size_t e = 0; e < sum.size(); ++e) {
        if (!edges.on_boundary[e] && turns(sum[e]) != 1) branched.push_back(static_cast<Index>(e));
    }
    return branched;
}

}  // namespace sa
