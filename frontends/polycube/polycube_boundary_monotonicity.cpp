#include "frontends/polycube/polycube_boundary_monotonicity.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "geometry/detail/union_find.h"

namespace sa {

namespace {

using ChartPair = std::pair<int, int>;

ChartPair chart_pair(int a, int b) {
    return a < b ? ChartPair{a, b} : ChartPair{b, a};
}

/// Side i of boundary triangle b (from corner i to corner i + 1, triangle b on its left) as a
/// rest edge vector.
Eigen::Vector3d side_vector(const TetBoundary& boundary, const Eigen::MatrixXd& positions, Index b,
                            int i) {
    const Index u = boundary.triangles(b, i);
    const Index v = boundary.triangles(b, (i + 1) % 3);
    return (positions.row(v) - positions.row(u)).transpose();
}

/// h . (n_left x n_right): the same for either triangle of the edge taken as the left one.
double along_polycube_edge(const Eigen::Vector3d& h, int left_label, int right_label) {
    return h.dot(label_direction(left_label).cross(label_direction(right_label)));
}

/// Calls visit(b, i, n) once per boundary edge between labels of different axes (b < n).
template <typename Visit>
void for_each_chart_boundary_edge(const TetBoundary& boundary, const std::vector<int>& labels,
                                  Visit&& visit) {
    for (Index b = 0; b < boundary.size(); ++b) {
        for (int i = 0; i < 3; ++i) {
            const Index n = boundary.adjacent[b][i];
            if (n > b && label_axis(labels[n]) != label_axis(labels[b])) visit(b, i, n);
        }
    }
}

}  // namespace

std::vector<NonMonotoneBoundary> non_monotone_boundaries(const TetBoundary& boundary,
                                                         const Eigen::MatrixXd& positions,
                                                         const std::vector<int>& labels,
                                                         const PolycubeCharts& charts,
                                                         double strong_cosine) {
    struct Edge {
        double along, length;
        Index from, to;
        std::array<Index, 2> triangles;  // chart_a's first
    };
    std::map<ChartPair, std::vector<Edge>> pairs;
    for_each_chart_boundary_edge(boundary, labels, [&](Index b, int i, Index n) {
        const Eigen::Vector3d h = side_vector(boundary, positions, b, i);
        const bool b_first = charts.chart_of[b] < charts.chart_of[n];
        pairs[chart_pair(charts.chart_of[b], charts.chart_of[n])].push_back(
            {along_polycube_edge(h, labels[b], labels[n]), h.norm(), boundary.triangles(b, i),
             boundary.triangles(b, (i + 1) % 3),
             b_first ? std::array<Index, 2>{b, n} : std::array<Index, 2>{n, b}});
    });
    // Two charts may meet along several separate boundaries (around a handle, say), each with
    // its own direction: the edges of a pair are split into connected chains (union-find on
    // their vertices).
    UnionFind chain_of(Index(positions.rows()));
    std::vector<NonMonotoneBoundary> found;
    for (const auto& [key, edges] : pairs) {
        for (const Edge& e : edges) chain_of.join(e.from, e.to);
        std::map<Index, std::vector<const Edge*>> chains;
        for (const Edge& e : edges) chains[chain_of.find(e.from)].push_back(&e);
        for (const auto& [chain_root, chain] : chains) {
            double net = 0.0;
            for (const Edge* e : chain) net += e->along;
            const double sign = net >= 0.0 ? 1.0 : -1.0;
            NonMonotoneBoundary turning;
            turning.chart_a = key.first;
            turning.chart_b = key.second;
            turning.label_a = charts.label[key.first];
            turning.label_b = charts.label[key.second];
            turning.edges = static_cast<Index>(chain.size());
            for (const Edge* e : chain) {
                turning.length += e->length;
                if (sign * e->along < 0.0) turning.backward_travel += -sign * e->along;
                if (sign * e->along < -strong_cosine * e->length) {
                    if (turning.strongly_backward++ == 0) turning.vertex = e->from;
                    turning.backward_triangles.push_back(e->triangles);
                }
            }
            if (turning.strongly_backward > 0) found.push_back(turning);
        }
        for (const Edge& e : edges) chain_of.reset(e.from), chain_of.reset(e.to);
    }
    std::stable_sort(found.begin(), found.end(), [](const auto& x, const auto& y) {
        return x.backward_travel > y.backward_travel;
    });
    return found;
}

}  // namespace sa
