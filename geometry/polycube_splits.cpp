#include "geometry/polycube_splits.h"

#include <algorithm>
#include <map>

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

/// The squashed elements of a mesh whose boundary facets carry chart ids (4 per tetrahedron, -1
/// on interior facets).
struct Classified {
    std::vector<std::array<Index, 2>> boundary_edges, interior_edges;
    std::vector<std::array<Index, 3>> boundary_triangles;  ///< sorted vertices
    std::vector<Index> tets;

    SquashedElements counts() const {
        return {Index(tets.size()), Index(interior_edges.size()), Index(boundary_edges.size()),
                Index(boundary_triangles.size())};
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

Classified classify(const SimplicialMesh& mesh, const std::vector<int>& chart) {
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
    SplitMesh(const SimplicialMesh& mesh, std::vector<int> chart)
        : points_(mesh.vertices), tets_(mesh.num_simplices()), chart_(mesh.num_simplices()) {
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
    int local(Index t, Index v) const {
        for (int k = 0; k < 4; ++k) {
            if (tets_[t][k] == v) return k;
        }
        return -1;
    }
    Index add_point(const Eigen::RowVector3d& p) {
        if (num_points_ == points_.rows()) points_.conservativeResize(2 * num_points_ + 16, 3);
        points_.row(num_points_) = p;
        tets_of_.emplace_back();
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
    Index edge_splits_ = 0, face_splits_ = 0;
};

}  // namespace

SquashedElements count_squashed_elements(const SimplicialMesh& mesh,
                                         const std::vector<int>& facet_labels) {
    return classify(mesh, facet_charts(mesh, facet_labels, "count_squashed_elements", nullptr))
        .counts();
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
        const Classified bad = classify(mesh, chart);
        if (round == 0) report.before = bad.counts();
        report.after = bad.counts();
        if (bad.counts().total() == 0) break;
        if (round == kMaxRounds) {
            throw InputError(source + ": squashed elements remain after " +
                             std::to_string(kMaxRounds) + " rounds of splits");
        }
        SplitMesh split(mesh, chart);
        // One kind per round, in this order: boundary edges, interior edges, boundary
        // triangles, tetrahedra (earlier kinds often repair later ones).
        if (!bad.boundary_edges.empty()) {
            for (const auto& e : bad.boundary_edges) split.split_edge(e[0], e[1]);
        } else if (!bad.interior_edges.empty()) {
            for (const auto& e : bad.interior_edges) split.split_edge(e[0], e[1]);
        } else if (!bad.boundary_triangles.empty()) {
            for (const auto& f : bad.boundary_triangles) split.split_facet(f);
        } else {
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
