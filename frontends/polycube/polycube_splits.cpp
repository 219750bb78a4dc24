#include "frontends/polycube/polycube_splits.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cstdint>
#include <map>

#include "geometry/detail/union_find.h"
#include "optim/errors.h"

namespace sa {

namespace {

using Charts = std::vector<int>;  // sorted, distinct

bool contains(const Charts& set, int c) {
    return std::binary_search(set.begin(), set.end(), c);
}

Charts intersect(const Charts& a, const Charts& b) {
    Charts out;
    std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
    return out;
}

/// Per axis, the plane a vertex lies on (-1: that coordinate is free).
using VertexPlanes = std::array<int, 3>;
constexpr VertexPlanes kFree = {-1, -1, -1};

/// The squashed elements of a mesh whose boundary facets carry chart ids (4 per tetrahedron, -1
/// on interior facets).
struct Classified {
    std::vector<std::array<Index, 2>> boundary_edges, interior_edges;
    std::vector<std::array<Index, 3>> boundary_triangles;  ///< sorted vertices
    std::vector<Index> tets;
    std::vector<Index> flattened_tets;  ///< flat on the planes, not in `tets`
    /// Per vertex: the plane it keeps along each axis, or -1 (geometry of forced_flat()).
    std::vector<VertexPlanes> planes;

    SquashedElements counts() const {
        return {Index(tets.size()), Index(interior_edges.size()), Index(boundary_edges.size()),
                Index(boundary_triangles.size()), Index(flattened_tets.size())};
    }
};

std::vector<Charts> vertex_charts(const SimplicialMesh& mesh, const std::vector<int>& chart) {
    std::vector<Charts> of(mesh.num_vertices());
    for (Index t = 0; t < mesh.num_simplices(); ++t) {
        for (int k = 0; k < 4; ++k) {
            const int c = chart[4 * t + k];
            if (c < 0) continue;
            for (const int i : kTetFacetCorners[k]) of[mesh.simplices(t, i)].push_back(c);
        }
    }
    for (Charts& s : of) {
        std::sort(s.begin(), s.end());
        s.erase(std::unique(s.begin(), s.end()), s.end());
    }
    return of;
}

/// The planes of the charts: charts of one axis that share a vertex lie in one plane (the solve
/// gives them one coordinate: frontends/polycube/polycube_solve.cpp,
/// frontends/polycube/cube_cover.h). Returns each vertex's plane per axis.
std::vector<VertexPlanes> vertex_planes(const std::vector<Charts>& of,
                                        const std::vector<int>& chart_label) {
    UnionFind same_plane(Index(chart_label.size()));
    for (const Charts& charts : of) {
        for (std::size_t i = 0; i < charts.size(); ++i) {
            for (std::size_t j = i + 1; j < charts.size(); ++j) {
                if (label_axis(chart_label[charts[i]]) == label_axis(chart_label[charts[j]]))
                    same_plane.join(charts[i], charts[j]);
            }
        }
    }
    std::vector<VertexPlanes> planes(of.size(), kFree);
    for (std::size_t v = 0; v < of.size(); ++v) {
        for (const int c : of[v]) planes[v][label_axis(chart_label[c])] = same_plane.find(c);
    }
    return planes;
}

/// A pseudo-random integer in [-2^15, 2^15) for `key` (splitmix64 of key and seed).
std::int64_t sample(std::uint64_t key, std::uint64_t seed) {
    std::uint64_t z = key * 0x9e3779b97f4a7c15ull + seed * 0xbf58476d1ce4e5b9ull + 1;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return std::int64_t(z >> 48) - (std::int64_t(1) << 15);
}

/// Whether the planes flatten a tetrahedron whatever the solve does: its determinant vanishes
/// for every position of its vertices in which each vertex keeps the coordinate of its plane
/// along each axis (`planes`; vertex ids `ids` name the free coordinates, two entries with one
/// id are one vertex), and every plane's coordinate is free. Four vertices on one plane, three on
/// one PolyCube edge (two planes), two on each of two parallel PolyCube edges, two on one corner
/// all are. The determinant is a polynomial of degree 3 in those coordinates, so it is
/// identically zero when it vanishes at two independent samples of integers below 2^15 (exact
/// in 64 bits; Schwartz-Zippel: a nonzero one vanishes at both with probability < 1e-8).
bool forced_flat(const std::array<Index, 4>& ids, const std::array<VertexPlanes, 4>& planes) {
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
        std::array<std::array<std::int64_t, 3>, 4> p{};
        for (int k = 0; k < 4; ++k) {
            for (int a = 0; a < 3; ++a) {
                const std::uint64_t key =
                    planes[k][a] >= 0 ? 2 * std::uint64_t(planes[k][a])
                                      : 2 * (3 * std::uint64_t(ids[k] + 1) + std::uint64_t(a)) + 1;
                p[k][a] = sample(key, seed);
            }
        }
        std::array<std::array<std::int64_t, 3>, 3> e{};
        for (int k = 0; k < 3; ++k) {
            for (int a = 0; a < 3; ++a) e[k][a] = p[k + 1][a] - p[0][a];
        }
        const std::int64_t det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                                 e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                                 e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
        if (det != 0) return false;
    }
    return true;
}

Classified classify(const SimplicialMesh& mesh, const std::vector<int>& chart,
                    const std::vector<int>& chart_label) {
    const std::vector<Charts> of = vertex_charts(mesh, chart);
    // The charts of the boundary facets around each boundary edge, and the boundary triangles.
    std::map<std::array<Index, 2>, Charts> boundary_edge;
    Classified out;
    for (Index t = 0; t < mesh.num_simplices(); ++t) {
        for (int k = 0; k < 4; ++k) {
            const int c = chart[4 * t + k];
            if (c < 0) continue;
            std::array<Index, 3> v{};
            for (int i = 0; i < 3; ++i) v[i] = mesh.simplices(t, kTetFacetCorners[k][i]);
            std::sort(v.begin(), v.end());
            for (int i = 0; i < 3; ++i) {
                for (int j = i + 1; j < 3; ++j) boundary_edge[{v[i], v[j]}].push_back(c);
            }
            for (const int other : intersect(intersect(of[v[0]], of[v[1]]), of[v[2]])) {
                if (other != c) {
                    out.boundary_triangles.push_back(v);
                    break;
                }
            }
        }
    }
    for (auto& [edge, charts] : boundary_edge) {
        std::sort(charts.begin(), charts.end());
        for (const int c : intersect(of[edge[0]], of[edge[1]])) {
            if (!contains(charts, c)) {
                out.boundary_edges.push_back(edge);
                break;
            }
        }
    }
    // Interior edges: every edge of a tetrahedron that is not a boundary edge.
    std::vector<std::array<Index, 2>> edges;
    edges.reserve(6 * std::size_t(mesh.num_simplices()));
    for (Index t = 0; t < mesh.num_simplices(); ++t) {
        for (int i = 0; i < 4; ++i) {
            for (int j = i + 1; j < 4; ++j) {
                const Index a = mesh.simplices(t, i), b = mesh.simplices(t, j);
                edges.push_back({std::min(a, b), std::max(a, b)});
            }
        }
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    for (const auto& e : edges) {
        if (boundary_edge.count(e)) continue;
        if (!intersect(of[e[0]], of[e[1]]).empty()) out.interior_edges.push_back(e);
    }
    for (Index t = 0; t < mesh.num_simplices(); ++t) {
        Charts common = of[mesh.simplices(t, 0)];
        for (int i = 1; i < 4 && !common.empty(); ++i) {
            common = intersect(common, of[mesh.simplices(t, i)]);
        }
        if (!common.empty()) out.tets.push_back(t);
    }
    // Tetrahedra that the planes flatten otherwise (on M1_tet: two vertices on each of two
    // parallel PolyCube edges). The untangling on the planes cannot lift them, and one of them
    // holds its eps at the scale of round-off, which freezes the whole untangling.
    out.planes = vertex_planes(of, chart_label);
    for (Index t = 0; t < mesh.num_simplices(); ++t) {
        std::array<Index, 4> ids{};
        std::array<VertexPlanes, 4> planes{};
        for (int k = 0; k < 4; ++k) {
            ids[k] = mesh.simplices(t, k);
            planes[k] = out.planes[ids[k]];
        }
        if (forced_flat(ids, planes) && !std::binary_search(out.tets.begin(), out.tets.end(), t)) {
            out.flattened_tets.push_back(t);
        }
    }
    return out;
}

/// Chart ids per tet facet (-1 on interior facets) from labels per tet facet, and each chart's
/// label.
std::vector<int> facet_charts(const SimplicialMesh& mesh, const std::vector<int>& facet_labels,
                              const std::string& source, std::vector<int>* chart_label) {
    const MeshTopology topology = mesh_topology(mesh, source);
    const TetBoundary boundary = tet_boundary(mesh, topology);
    const std::vector<int> labels =
        boundary_labels_from_flags(boundary, mesh.num_simplices(), facet_labels, source);
    for (Index b = 0; b < boundary.size(); ++b) {
        if (labels[b] < 0 || labels[b] > 5) {
            throw InputError(source + ": " + describe_boundary_triangle(boundary, b) +
                             " has label " + std::to_string(labels[b]) + ", outside 0..5");
        }
    }
    const PolycubeCharts charts = polycube_charts(boundary, mesh.vertices, labels);
    std::vector<int> chart(facet_labels.size(), -1);
    for (Index b = 0; b < boundary.size(); ++b) chart[boundary.tet_facet[b]] = charts.chart_of[b];
    if (chart_label != nullptr) *chart_label = charts.label;
    return chart;
}

/// The mesh being split: tetrahedra with per-facet chart ids, and the tetrahedra around each
/// vertex.
class SplitMesh {
  public:
    SplitMesh(const SimplicialMesh& mesh, std::vector<int> chart,
              std::vector<VertexPlanes> planes = {})
        : points_(mesh.vertices),
          tets_(mesh.num_simplices()),
          chart_(mesh.num_simplices()),
          planes_(std::move(planes)) {
        planes_.resize(mesh.num_vertices(), kFree);
        tets_of_.resize(mesh.num_vertices());
        for (Index t = 0; t < mesh.num_simplices(); ++t) {
            for (int k = 0; k < 4; ++k) {
                tets_[t][k] = mesh.simplices(t, k);
                chart_[t][k] = chart[4 * t + k];
                tets_of_[tets_[t][k]].push_back(t);
            }
        }
        num_points_ = mesh.num_vertices();
    }

    /// Splits edge (a, b) at its midpoint; false when no tetrahedron has it any more.
    bool split_edge(Index a, Index b) {
        std::vector<Index> around;
        for (const Index t : tets_of_[a]) {
            if (local(t, b) >= 0) around.push_back(t);
        }
        if (around.empty()) return false;
        const Index m = add_point(0.5 * (points_.row(a) + points_.row(b)));
        for (const Index t : around) {
            const int ja = local(t, a), jb = local(t, b);
            std::array<Index, 4> second = tets_[t];
            std::array<int, 4> second_chart = chart_[t];
            second[ja] = m;
            second_chart[jb] = -1;
            replace(t, jb, m);
            chart_[t][ja] = -1;
            add_tet(second, second_chart);
        }
        ++edge_splits_;
        return true;
    }

    /// Splits the facet with vertices `facet` at its centroid (the one or two tetrahedra on it in
    /// three each); false when no tetrahedron has it any more.
    bool split_facet(const std::array<Index, 3>& facet) {
        std::vector<Index> on;
        for (const Index t : tets_of_[facet[0]]) {
            if (local(t, facet[1]) >= 0 && local(t, facet[2]) >= 0) on.push_back(t);
        }
        if (on.empty()) return false;
        const Index m = add_point(
            (points_.row(facet[0]) + points_.row(facet[1]) + points_.row(facet[2])) / 3.0);
        for (const Index t : on) {
            const std::array<Index, 4> base = tets_[t];
            const std::array<int, 4> base_chart = chart_[t];
            int opposite = 0;
            while (std::find(facet.begin(), facet.end(), base[opposite]) != facet.end()) {
                ++opposite;
            }
            bool first = true;
            for (int p = 0; p < 4; ++p) {
                if (p == opposite) continue;
                std::array<int, 4> child_chart{-1, -1, -1, -1};
                child_chart[p] = base_chart[p];
                child_chart[opposite] = base_chart[opposite];
                if (first) {
                    replace(t, p, m);
                    chart_[t] = child_chart;
                    first = false;
                } else {
                    std::array<Index, 4> child = base;
                    child[p] = m;
                    add_tet(child, child_chart);
                }
            }
        }
        ++face_splits_;
        return true;
    }

    /// The interior facet of tetrahedron t with the largest area, or false if it has none.
    bool interior_facet(Index t, std::array<Index, 3>* facet) const {
        double best = -1.0;
        for (int k = 0; k < 4; ++k) {
            if (chart_[t][k] >= 0) continue;
            std::array<Index, 3> f{};
            for (int i = 0; i < 3; ++i) f[i] = tets_[t][kTetFacetCorners[k][i]];
            const Eigen::Vector3d a = points_.row(f[0]).transpose(),
                                  b = points_.row(f[1]).transpose(),
                                  c = points_.row(f[2]).transpose();
            const double area = (b - a).cross(c - a).norm();
            if (area > best) {
                best = area;
                *facet = f;
            }
        }
        return best >= 0.0;
    }

    /// Splits tetrahedron t, which the planes flatten (forced_flat), by the first split after
    /// which its children and those of its neighbours on the split element can all be positive
    /// with the other vertices where `model` puts them: one of its facets at the centroid (a
    /// boundary one puts the new vertex on that facet's plane), else one of its interior edges
    /// at the midpoint. Returns false, splitting nothing, when none can. `chart_label` per chart.
    ///
    /// A face split is not always enough: with two vertices on each of two parallel PolyCube
    /// edges, two of its children hold one edge's two vertices and one of the other's, and their
    /// volumes have opposite signs wherever the new vertex goes; only the split of the right
    /// edge between the two lines (given the order of the vertices along them) can be valid.
    bool split_flattened(Index t, const std::vector<int>& chart_label) {
        const std::array<Index, 4> tet = tets_[t];
        const Index m = num_points_;  // the index the new vertex gets
        for (int k = 0; k < 4; ++k) {
            std::array<Index, 3> facet{};
            for (int i = 0; i < 3; ++i) facet[i] = tet[kTetFacetCorners[k][i]];
            VertexPlanes on = kFree;
            if (chart_[t][k] >= 0) {
                const int axis = label_axis(chart_label[chart_[t][k]]);
                on[axis] = planes_[facet[0]][axis];
            }
            std::vector<std::array<Index, 4>> children;
            for (const Index s : tets_of_[facet[0]]) {
                if (local(s, facet[1]) < 0 || local(s, facet[2]) < 0) continue;
                for (const Index f : facet) {
                    children.push_back(tets_[s]);
                    children.back()[local(s, f)] = m;
                }
            }
            const Eigen::RowVector3d at =
                (model_.row(facet[0]) + model_.row(facet[1]) + model_.row(facet[2])) / 3.0;
            if (can_be_positive(children, m, on, at)) {
                split_facet(facet);
                planes_[m] = on;
                model_.row(m) = at;
                return true;
            }
        }
        for (int i = 0; i < 4; ++i) {
            for (int j = i + 1; j < 4; ++j) {
                const Index a = tet[i], b = tet[j];
                if (boundary_edge(a, b)) continue;
                std::vector<std::array<Index, 4>> children;
                for (const Index s : tets_of_[a]) {
                    if (local(s, b) < 0) continue;
                    for (const Index end : {a, b}) {
                        children.push_back(tets_[s]);
                        children.back()[local(s, end)] = m;
                    }
                }
                const Eigen::RowVector3d at = 0.5 * (model_.row(a) + model_.row(b));
                if (can_be_positive(children, m, kFree, at)) {
                    split_edge(a, b);
                    model_.row(m) = at;
                    return true;
                }
            }
        }
        return false;
    }

    /// Where the planes put each vertex, roughly (#V x 3), for split_flattened().
    void set_model(Eigen::MatrixXd model) {
        model_ = std::move(model);
        model_.conservativeResize(points_.rows(), 3);
    }

    SimplicialMesh mesh() const {
        SimplicialMesh out;
        out.vertices = points_.topRows(num_points_);
        out.simplices.resize(Index(tets_.size()), 4);
        for (std::size_t t = 0; t < tets_.size(); ++t) {
            for (int k = 0; k < 4; ++k) out.simplices(Index(t), k) = tets_[t][k];
        }
        return out;
    }
    std::vector<int> charts() const {
        std::vector<int> out(4 * tets_.size());
        for (std::size_t t = 0; t < tets_.size(); ++t) {
            for (int k = 0; k < 4; ++k) out[4 * t + k] = chart_[t][k];
        }
        return out;
    }
    const std::array<Index, 4>& tet(Index t) const { return tets_[t]; }
    Index edge_splits() const { return edge_splits_; }
    Index face_splits() const { return face_splits_; }

  private:
    /// Whether some position of the new vertex m (starting from `at`, keeping its coordinate
    /// along the axes of `m_planes`) gives every tetrahedron of `children` a positive volume,
    /// the other vertices at model_. Each volume is affine in m: a feasibility problem in at
    /// most three unknowns, solved by cyclic projections onto the violated half-spaces (they
    /// converge when it is feasible; a child that is flat on the planes, or infeasible ones,
    /// exhaust the iterations).
    bool can_be_positive(const std::vector<std::array<Index, 4>>& children, Index m,
                         const VertexPlanes& m_planes, const Eigen::RowVector3d& at) const {
        auto volume = [&](const std::array<Index, 4>& c, const Eigen::RowVector3d& pm) {
            std::array<Eigen::RowVector3d, 4> p;
            for (int k = 0; k < 4; ++k)
                p[k] = c[k] == m ? pm : Eigen::RowVector3d(model_.row(c[k]));
            Eigen::Matrix3d e;
            for (int k = 0; k < 3; ++k) e.row(k) = p[k + 1] - p[0];
            return e.determinant() / 6.0;
        };
        // Child volume = g . (x - at) + v0, with x the position of m.
        std::vector<Eigen::RowVector3d> g(children.size());
        std::vector<double> v0(children.size());
        double scale = 0.0;
        for (const auto& c : children) {
            for (int k = 0; k < 4; ++k) {
                if (c[k] != m) scale = std::max(scale, (model_.row(c[k]) - at).norm());
            }
        }
        if (!(scale > 0.0)) return false;
        for (std::size_t i = 0; i < children.size(); ++i) {
            v0[i] = volume(children[i], at);
            for (int a = 0; a < 3; ++a) {
                Eigen::RowVector3d shifted = at;
                shifted[a] += scale;
                g[i][a] = m_planes[a] >= 0 ? 0.0 : (volume(children[i], shifted) - v0[i]) / scale;
            }
        }
        // A margin relative to the size: a volume of 1e-6 of scale^3.
        const double margin = 1e-6 * scale * scale * scale;
        Eigen::RowVector3d x = at;
        for (int iteration = 0; iteration < 200; ++iteration) {
            bool all = true;
            for (std::size_t i = 0; i < children.size(); ++i) {
                const double v = g[i].dot(x - at) + v0[i];
                if (v >= margin) continue;
                all = false;
                const double gg = g[i].squaredNorm();
                if (!(gg > 0.0)) return false;  // m cannot change it
                x += ((2.0 * margin - v) / gg) * g[i];
            }
            if (all) return true;
        }
        return false;
    }

    /// Whether edge (a, b) lies on a boundary facet.
    bool boundary_edge(Index a, Index b) const {
        for (const Index s : tets_of_[a]) {
            const int ja = local(s, a), jb = local(s, b);
            if (jb < 0) continue;
            for (int k = 0; k < 4; ++k) {
                if (k != ja && k != jb && chart_[s][k] >= 0) return true;
            }
        }
        return false;
    }

    int local(Index t, Index v) const {
        for (int k = 0; k < 4; ++k) {
            if (tets_[t][k] == v) return k;
        }
        return -1;
    }
    Index add_point(const Eigen::RowVector3d& p) {
        if (num_points_ == points_.rows()) {
            points_.conservativeResize(2 * num_points_ + 16, 3);
            if (model_.rows() > 0) model_.conservativeResize(points_.rows(), 3);
        }
        points_.row(num_points_) = p;
        tets_of_.emplace_back();
        planes_.push_back(kFree);
        return num_points_++;
    }
    void replace(Index t, int k, Index v) {
        auto& list = tets_of_[tets_[t][k]];
        list.erase(std::find(list.begin(), list.end(), t));
        tets_[t][k] = v;
        tets_of_[v].push_back(t);
    }
    void add_tet(const std::array<Index, 4>& tet, const std::array<int, 4>& chart) {
        const Index t = Index(tets_.size());
        tets_.push_back(tet);
        chart_.push_back(chart);
        for (const Index v : tet) tets_of_[v].push_back(t);
    }

    Eigen::MatrixXd points_;
    Index num_points_ = 0;
    std::vector<std::array<Index, 4>> tets_;
    std::vector<std::array<int, 4>> chart_;
    std::vector<std::vector<Index>> tets_of_;
    std::vector<VertexPlanes> planes_;  ///< per vertex (flattened tetrahedra only)
    Eigen::MatrixXd model_;             ///< per vertex: where the planes put it, roughly
    Index edge_splits_ = 0, face_splits_ = 0;
};

}  // namespace

SquashedElements count_squashed_elements(const SimplicialMesh& mesh,
                                         const std::vector<int>& facet_labels) {
    std::vector<int> chart_label;
    const std::vector<int> chart =
        facet_charts(mesh, facet_labels, "count_squashed_elements", &chart_label);
    return classify(mesh, chart, chart_label).counts();
}

PolycubeSplitReport split_squashed_elements(SimplicialMesh& mesh, std::vector<int>& facet_labels,
                                            const std::string& source) {
    std::vector<int> chart_label;
    std::vector<int> chart = facet_charts(mesh, facet_labels, source, &chart_label);
    PolycubeSplitReport report;
    const Index vertices_before = mesh.num_vertices(), tets_before = mesh.num_simplices();
    // Rounds: a split can leave a new squashed element (the midpoint of a boundary edge is on
    // that edge's charts, and its new edges may reach a vertex of those charts), so classify
    // again until nothing is left.
    constexpr int kMaxRounds = 32;
    for (int round = 0;; ++round) {
        const Classified bad = classify(mesh, chart, chart_label);
        if (round == 0) report.before = bad.counts();
        report.after = bad.counts();
        if (bad.counts().total() == 0) break;
        if (round == kMaxRounds) {
            throw InputError(source + ": squashed elements remain after " +
                             std::to_string(kMaxRounds) + " rounds of splits");
        }
        SplitMesh split(mesh, chart, bad.planes);
        // One kind per round, in this order: boundary edges, interior edges, boundary
        // triangles, tetrahedra (earlier kinds often repair later ones).
        if (!bad.boundary_edges.empty()) {
            for (const auto& e : bad.boundary_edges) split.split_edge(e[0], e[1]);
        } else if (!bad.interior_edges.empty()) {
            for (const auto& e : bad.interior_edges) split.split_edge(e[0], e[1]);
        } else if (!bad.boundary_triangles.empty()) {
            for (const auto& f : bad.boundary_triangles) split.split_facet(f);
        } else if (!bad.tets.empty()) {
            for (const Index t : bad.tets) {
                // A neighbour's split may have replaced it by a child already: next round.
                if (split.tet(t) != std::array<Index, 4>{mesh.simplices(t, 0), mesh.simplices(t, 1),
                                                         mesh.simplices(t, 2),
                                                         mesh.simplices(t, 3)}) {
                    continue;
                }
                std::array<Index, 3> facet{};
                if (!split.interior_facet(t, &facet)) {
                    throw InputError(source + ": tetrahedron " + std::to_string(t) +
                                     " has all four vertices on one chart and no interior "
                                     "facet to split");
                }
                split.split_facet(facet);
            }
        } else {
            // Where the planes put the vertices, roughly: each plane at the mean rest
            // coordinate of its vertices, every other coordinate at rest.
            Eigen::MatrixXd model = mesh.vertices;
            std::map<std::pair<int, int>, std::pair<double, int>> mean;  // (axis, plane)
            for (Index v = 0; v < mesh.num_vertices(); ++v) {
                for (int a = 0; a < 3; ++a) {
                    if (bad.planes[v][a] < 0) continue;
                    auto& [sum, count] = mean[{a, bad.planes[v][a]}];
                    sum += mesh.vertices(v, a);
                    ++count;
                }
            }
            for (Index v = 0; v < mesh.num_vertices(); ++v) {
                for (int a = 0; a < 3; ++a) {
                    if (bad.planes[v][a] < 0) continue;
                    const auto& [sum, count] = mean[{a, bad.planes[v][a]}];
                    model(v, a) = sum / count;
                }
            }
            split.set_model(std::move(model));
            bool any = false;
            for (const Index t : bad.flattened_tets) {
                if (split.tet(t) != std::array<Index, 4>{mesh.simplices(t, 0), mesh.simplices(t, 1),
                                                         mesh.simplices(t, 2),
                                                         mesh.simplices(t, 3)}) {
                    any = true;  // a neighbour's split changed it: next round
                    continue;
                }
                any = split.split_flattened(t, chart_label) || any;
            }
            // None of them has a split without flat children: they stay in report.after.
            if (!any) {
                report.flat_tets = bad.flattened_tets;
                break;
            }
        }
        report.edge_splits += split.edge_splits();
        report.face_splits += split.face_splits();
        mesh = split.mesh();
        chart = split.charts();
    }
    facet_labels.assign(chart.size(), kNoLabel);
    for (std::size_t f = 0; f < chart.size(); ++f) {
        if (chart[f] >= 0) facet_labels[f] = chart_label[chart[f]];
    }
    report.vertices_added = mesh.num_vertices() - vertices_before;
    report.tets_added = mesh.num_simplices() - tets_before;
    return report;
}

}  // namespace sa
