#include "frontends/seamless/cut_graph.h"

#include <Eigen/Geometry>
#include <cmath>
#include <complex>
#include <queue>

#include "geometry/detail/union_find.h"
#include "optim/errors.h"

namespace sa {

namespace {

/// The direction d of face f relative to the edge vector e, as an angle in the face's plane.
double angle_to(const SimplicialMesh& mesh, Index f, const Eigen::Vector3d& e,
                const Eigen::Vector3d& d) {
    const Eigen::Vector3d p0 = mesh.point(mesh.simplices(f, 0));
    const Eigen::Vector3d n = (mesh.point(mesh.simplices(f, 1)) - p0)
                                  .cross(mesh.point(mesh.simplices(f, 2)) - p0)
                                  .normalized();
    return std::atan2(n.dot(e.cross(d)), e.dot(d));
}

}  // namespace

std::vector<int> cross_field_matchings(const SimplicialMesh& mesh, const MeshTopology& topology,
                                       const Eigen::MatrixXd& directions) {
    if (directions.rows() != mesh.num_simplices() || directions.cols() != 3) {
        throw InputError("cross field: " + std::to_string(directions.rows()) + " x " +
                         std::to_string(directions.cols()) + " directions for " +
                         std::to_string(mesh.num_simplices()) + " faces (expected #F x 3)");
    }
    std::vector<int> matching;
    matching.reserve(topology.interior_facets.size());
    for (const InteriorFacet& facet : topology.interior_facets) {
        // Angles to the shared edge are kept by the transport: compare them modulo quarter turns.
        const Eigen::Vector3d e = mesh.point(facet.vertices[1]) - mesh.point(facet.vertices[0]);
        const Index f = facet.simplex[0], g = facet.simplex[1];
        const double turn = angle_to(mesh, g, e, directions.row(g).transpose()) -
                            angle_to(mesh, f, e, directions.row(f).transpose());
        matching.push_back(int(((long)std::lround(turn / (0.5 * M_PI)) % 4 + 4) % 4));
    }
    return matching;
}

std::vector<unsigned char> cut_graph(const SimplicialMesh& mesh, const MeshTopology& topology,
                                     const std::vector<Index>& through) {
    const Index nf = mesh.num_simplices(), nv = mesh.num_vertices();
    const std::size_t ni = topology.interior_facets.size();
    // Faces' interior facets, for the breadth-first dual tree.
    std::vector<std::vector<std::size_t>> facets_of(nf);
    for (std::size_t i = 0; i < ni; ++i) {
        for (Index s : topology.interior_facets[i].simplex) facets_of[s].push_back(i);
    }
    std::vector<unsigned char> in_tree(ni, 0), reached(nf, 0);
    for (Index root = 0; root < nf; ++root) {
        if (reached[root]) continue;
        std::queue<Index> queue;
        queue.push(root);
        reached[root] = 1;
        while (!queue.empty()) {
            const Index f = queue.front();
            queue.pop();
            for (std::size_t i : facets_of[f]) {
                const auto& s = topology.interior_facets[i].simplex;
                const Index g = s[0] == f ? s[1] : s[0];
                if (reached[g]) continue;
                reached[g] = 1;
                in_tree[i] = 1;
                queue.push(g);
            }
        }
    }
    // Candidate edges: interior edges off the tree and the boundary; prune dangling ends.
    struct Edge {
        Index a, b;
        std::ptrdiff_t interior;  // -1 for a boundary edge
        bool alive = true;
    };
    std::vector<Edge> edges;
    for (std::size_t i = 0; i < ni; ++i) {
        if (!in_tree[i]) {
            const auto& v = topology.interior_facets[i].vertices;
            edges.push_back({v[0], v[1], std::ptrdiff_t(i)});
        }
    }
    for (const BoundaryFacet& b : topology.boundary_facets)
        edges.push_back({b.vertices[0], b.vertices[1], -1});
    std::vector<std::vector<std::size_t>> edges_of(nv);
    std::vector<Index> degree(nv, 0);
    for (std::size_t k = 0; k < edges.size(); ++k) {
        for (Index v : {edges[k].a, edges[k].b}) {
            edges_of[v].push_back(k);
            ++degree[v];
        }
    }
    std::vector<unsigned char> keep(nv, 0);
    for (Index v : through) keep[v] = 1;
    std::queue<Index> leaves;
    for (Index v = 0; v < nv; ++v) {
        if (degree[v] == 1 && !keep[v]) leaves.push(v);
    }
    while (!leaves.empty()) {
        const Index v = leaves.front();
        leaves.pop();
        if (degree[v] != 1) continue;
        for (std::size_t k : edges_of[v]) {
            if (!edges[k].alive) continue;
            edges[k].alive = false;
            for (Index w : {edges[k].a, edges[k].b}) {
                if (--degree[w] == 1 && !keep[w]) leaves.push(w);
            }
        }
    }
    std::vector<unsigned char> cut(ni, 0);
    for (const Edge& e : edges) {
        if (e.alive && e.interior >= 0) cut[e.interior] = 1;
    }
    return cut;
}

CutMesh cut_along(const SimplicialMesh& mesh, const MeshTopology& topology,
                  const std::vector<unsigned char>& cut) {
    const Index nf = mesh.num_simplices();
    const int corners = mesh.simplex_dimension() + 1;
    // Corner (f, k) is joined to the corner of the same vertex in g across every uncut facet.
    UnionFind wedges(nf * corners);
    auto corner_of = [&](Index f, Index v) {
        for (int k = 0; k < corners; ++k) {
            if (mesh.simplices(f, k) == v) return f * corners + k;
        }
        return Index(-1);
    };
    for (std::size_t i = 0; i < topology.interior_facets.size(); ++i) {
        if (cut[i]) continue;
        const InteriorFacet& facet = topology.interior_facets[i];
        for (int k = 0; k < mesh.simplex_dimension(); ++k) {
            const Index v = facet.vertices[k];
            wedges.join(corner_of(facet.simplex[0], v), corner_of(facet.simplex[1], v));
        }
    }
    CutMesh out;
    out.mesh.simplices.resize(nf, corners);
    std::vector<Index> copy(nf * corners, -1);
    for (Index f = 0; f < nf; ++f) {
        for (int k = 0; k < corners; ++k) {
            const Index root = wedges.find(f * corners + k);
            if (copy[root] < 0) {
                copy[root] = Index(out.original_vertex.size());
                out.original_vertex.push_back(mesh.simplices(f, k));
            }
            out.mesh.simplices(f, k) = copy[root];
        }
    }
    out.mesh.vertices.resize(out.original_vertex.size(), mesh.vertices.cols());
    for (std::size_t v = 0; v < out.original_vertex.size(); ++v) {
        out.mesh.vertices.row(v) = mesh.vertices.row(out.original_vertex[v]);
    }
    return out;
}

}  // namespace sa
