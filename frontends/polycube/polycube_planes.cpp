#include "frontends/polycube/polycube_planes.h"

#include <algorithm>
#include <map>

#include "geometry/detail/union_find.h"
#include "optim/errors.h"

namespace sa {

PolycubePlanes polycube_planes(const TetBoundary& boundary, const PolycubeCharts& charts,
                               Index num_vertices) {
    if (static_cast<Index>(charts.chart_of.size()) != boundary.size()) {
        throw InvalidArgumentError("polycube_planes: the charts are not those of this boundary");
    }
    // Union of the charts of one axis that share a vertex.
    UnionFind same_plane(charts.size());
    std::vector<std::array<int, 3>> chart_at(num_vertices, {-1, -1, -1});
    for (Index b = 0; b < boundary.size(); ++b) {
        const int c = charts.chart_of[b];
        const int axis = label_axis(charts.label[c]);
        for (int i = 0; i < 3; ++i) {
            int& mine = chart_at[boundary.triangles(b, i)][axis];
            if (mine < 0) {
                mine = c;
            } else {
                same_plane.join(mine, c);
            }
        }
    }
    PolycubePlanes planes;
    planes.plane_of_chart.assign(charts.size(), -1);
    for (int c = 0; c < charts.size(); ++c) {
        const int root = same_plane.find(c);
        if (planes.plane_of_chart[root] < 0) {
            planes.plane_of_chart[root] = planes.size();
            planes.axis.push_back(label_axis(charts.label[c]));
        }
        planes.plane_of_chart[c] = planes.plane_of_chart[root];
    }
    planes.plane_of_vertex.assign(num_vertices, {-1, -1, -1});
    for (Index v = 0; v < num_vertices; ++v) {
        for (int axis = 0; axis < 3; ++axis) {
            if (chart_at[v][axis] >= 0)
                planes.plane_of_vertex[v][axis] = planes.plane_of_chart[chart_at[v][axis]];
        }
    }
    return planes;
}

std::vector<PolycubeEdgeOrder> polycube_edge_orders(const TetBoundary& boundary,
                                                    const PolycubeCharts& charts,
                                                    const PolycubePlanes& planes,
                                                    const Eigen::MatrixXd& rest) {
    // Mesh edges between planes of different axes, grouped by their pair of planes.
    std::map<std::pair<int, int>, std::vector<std::array<Index, 2>>> by_pair;
    for (Index b = 0; b < boundary.size(); ++b) {
        for (int i = 0; i < 3; ++i) {
            const Index other = boundary.adjacent[b][i];
            if (other < b) continue;  // each edge once, none across a non-manifold edge
            const int p = planes.plane_of_chart[charts.chart_of[b]];
            const int q = planes.plane_of_chart[charts.chart_of[other]];
            if (planes.axis[p] == planes.axis[q]) continue;
            by_pair[{std::min(p, q), std::max(p, q)}].push_back(
                {Index(boundary.triangles(b, i)), Index(boundary.triangles(b, (i + 1) % 3))});
        }
    }
    std::vector<PolycubeEdgeOrder> orders;
    for (const auto& [pair, edges] : by_pair) {
        const int axis = 3 - planes.axis[pair.first] - planes.axis[pair.second];
        auto corner = [&](Index v) { return planes.plane_of_vertex[v][axis] >= 0; };
        // Per vertex: its edges of this pair, as (other end, edge).
        std::map<Index, std::vector<std::pair<Index, std::size_t>>> around;
        for (std::size_t e = 0; e < edges.size(); ++e) {
            around[edges[e][0]].push_back({edges[e][1], e});
            around[edges[e][1]].push_back({edges[e][0], e});
        }
        std::vector<unsigned char> walked(edges.size(), 0);
        for (const auto& [start, incident] : around) {
            if (!corner(start)) continue;
            for (const auto& [first, first_edge] : incident) {
                if (walked[first_edge]) continue;
                walked[first_edge] = 1;
                Index previous = start, current = first, count = 1;
                std::vector<Index> chain{start, first};
                bool ends_at_corner = true;
                while (!corner(current)) {
                    const auto& next = around[current];
                    if (next.size() != 2) {
                        ends_at_corner = false;  // a branch or a dead end
                        break;
                    }
                    const auto& step = next[0].first == previous ? next[1] : next[0];
                    if (walked[step.second]) {
                        ends_at_corner = false;
                        break;
                    }
                    walked[step.second] = 1;
                    previous = current;
                    current = step.first;
                    chain.push_back(current);
                    ++count;
                }
                if (!ends_at_corner) continue;
                PolycubeEdgeOrder order;
                order.axis = axis;
                order.from = start;
                order.to = current;
                if (rest(order.to, axis) < rest(order.from, axis)) {
                    std::swap(order.from, order.to);
                    std::reverse(chain.begin(), chain.end());
                }
                order.vertices = std::move(chain);
                order.from_plane = planes.plane_of_vertex[order.from][axis];
                order.to_plane = planes.plane_of_vertex[order.to][axis];
                order.rest_extent = rest(order.to, axis) - rest(order.from, axis);
                order.mesh_edges = count;
                orders.push_back(order);
            }
        }
    }
    return orders;
}

}  // namespace sa
