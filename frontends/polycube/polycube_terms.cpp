#include "frontends/polycube/polycube_terms.h"

#include <algorithm>

#include "energies/polycube_constraints.h"

namespace sa {

PlanarityElements planarity_elements(const PreparedPolycube& p) {
    PlanarityElements out;
    for (Index b = 0; b < p.boundary.size(); ++b) {
        Eigen::Matrix<double, 3, 2> edges;
        for (int k = 0; k < 2; ++k) {
            edges.col(k) =
                detail::rest(p, p.boundary.triangles(b, 0), p.boundary.triangles(b, k + 1));
        }
        out.rows.push_back(planarity_rows(label_axis(p.labels[b]), edges));
        out.tet.push_back(p.boundary.tet(b));
    }
    return out;
}

PlanarityVertexElements planarity_vertex_elements(const PreparedPolycube& p) {
    PlanarityVertexElements out;
    for (Index b = 0; b < p.boundary.size(); ++b) {
        std::array<Index, 3> v;
        for (int i = 0; i < 3; ++i) v[i] = p.boundary.triangles(b, i);
        out.rows.push_back(planarity_vertex_rows(
            label_axis(p.labels[b]),
            {detail::rest(p, v[0], v[1]).norm(), detail::rest(p, v[0], v[2]).norm()}));
        out.vertices.push_back(v);
    }
    return out;
}

std::vector<SlidingVertex> sliding_vertices(const PreparedPolycube& p) {
    std::vector<std::vector<int>> charts(p.mesh.num_vertices());
    for (Index b = 0; b < p.boundary.size(); ++b) {
        for (int i = 0; i < 3; ++i)
            charts[p.boundary.triangles(b, i)].push_back(p.charts.chart_of[b]);
    }
    std::vector<SlidingVertex> out;
    for (Index v = 0; v < p.mesh.num_vertices(); ++v) {
        if (charts[v].empty()) continue;
        SlidingVertex s;
        s.vertex = v;
        s.charts = charts[v];
        std::sort(s.charts.begin(), s.charts.end());
        s.charts.erase(std::unique(s.charts.begin(), s.charts.end()), s.charts.end());
        for (const int c : s.charts) s.axes.push_back(label_axis(p.charts.label[c]));
        std::sort(s.axes.begin(), s.axes.end());
        s.axes.erase(std::unique(s.axes.begin(), s.axes.end()), s.axes.end());
        out.push_back(std::move(s));
    }
    return out;
}

}  // namespace sa
