#include "frontends/polycube/polycube_terms.h"

#include <algorithm>

#include "frontends/polycube/polycube_constraints.h"

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

namespace {

/// The place of each vertex of `ring` (the position in the vertex-form variables).
int ring_index(const std::vector<Index>& ring, Index v) {
    return int(std::find(ring.begin(), ring.end(), v) - ring.begin());
}

}  // namespace

AngleBarrierElements<DihedralSumEnergy> dihedral_sum_elements(const PreparedPolycube& p) {
    AngleBarrierElements<DihedralSumEnergy> out;
    for (const BoundaryEdgeFan& fan : p.fans) {
        std::vector<DihedralSumEnergy::Tet>& tets = out.energy.fans.emplace_back();
        const Index a = fan.edge[0];
        for (std::size_t k = 0; k < fan.tets.size(); ++k) {
            tets.push_back({detail::rest(p, a, fan.edge[1]), detail::rest(p, a, fan.others[k][0]),
                            detail::rest(p, a, fan.others[k][1])});
        }
        out.items.push_back(fan.tets);
    }
    return out;
}

AngleBarrierElements<DihedralSumVertexEnergy> dihedral_sum_vertex_elements(
    const PreparedPolycube& p) {
    AngleBarrierElements<DihedralSumVertexEnergy> out;
    for (const BoundaryEdgeFan& fan : p.fans) {
        std::vector<Index> ids{fan.edge[0], fan.edge[1]};
        ids.insert(ids.end(), fan.ring.begin(), fan.ring.end());
        std::vector<std::array<int, 2>>& tets = out.energy.tets.emplace_back();
        for (const auto& rs : fan.others)
            tets.push_back({ring_index(fan.ring, rs[0]), ring_index(fan.ring, rs[1])});
        out.items.push_back(ids);
    }
    return out;
}

AngleBarrierElements<SolidAngleSumEnergy> solid_angle_sum_elements(const PreparedPolycube& p) {
    AngleBarrierElements<SolidAngleSumEnergy> out;
    for (const BoundaryVertexStar& star : p.stars) {
        std::vector<SolidAngleSumEnergy::Tet>& tets = out.energy.stars.emplace_back();
        const Index v = star.vertex;
        for (std::size_t k = 0; k < star.tets.size(); ++k) {
            tets.push_back({detail::rest(p, v, star.others[k][0]),
                            detail::rest(p, v, star.others[k][1]),
                            detail::rest(p, v, star.others[k][2])});
        }
        out.items.push_back(star.tets);
    }
    return out;
}

AngleBarrierElements<SolidAngleSumVertexEnergy> solid_angle_sum_vertex_elements(
    const PreparedPolycube& p) {
    AngleBarrierElements<SolidAngleSumVertexEnergy> out;
    for (const BoundaryVertexStar& star : p.stars) {
        std::vector<Index> ids{star.vertex};
        ids.insert(ids.end(), star.ring.begin(), star.ring.end());
        std::vector<std::array<int, 3>>& tets = out.energy.tets.emplace_back();
        for (const auto& abc : star.others) {
            tets.push_back({ring_index(star.ring, abc[0]), ring_index(star.ring, abc[1]),
                            ring_index(star.ring, abc[2])});
        }
        out.items.push_back(ids);
    }
    return out;
}

}  // namespace sa
