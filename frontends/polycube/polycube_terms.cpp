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

}  // namespace sa
