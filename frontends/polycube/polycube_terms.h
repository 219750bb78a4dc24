#pragma once
// The PolyCube-specific terms of the solve (issue 21), built from a prepared mesh, for the
// Simplex Assembly engine to add (issue 20): each builder gives the element energies and, per
// element, the simplices or vertices whose variables it takes, in the order the energy expects.
// The engine maps them to variable indices (linear_variables(t) is vec(A_t), 9 entries,
// column-major; vertex v is 3 entries in the vertex stage). Rest frames keep the mesh's axes
// (geometry/rest_frames.h), so rest edge vectors are coordinate differences.
//
//   planarity_elements         Ẽ_assembly, A-form: per labelled boundary triangle, its tet.
//   planarity_vertex_elements  the same in vertex form: per boundary triangle, its 3 vertices.
//   for_each_dihedral_term     E_e in A-form (tets) and vertex form (p, q, ring), one call per
//   for_each_solid_angle_term  size present; E_v likewise. The A-forms hold fans and stars of at
//                              most kMaxAngleFan tetrahedra, the vertex forms at most
//                              kMaxAngleRing ring vertices (energies/tet_angle_barriers.h says
//                              why): larger ones are left out of that form and listed in
//                              `skipped`. The angle sums themselves (boundary_angle_sums.h) take
//                              any size.

#include <array>
#include <utility>
#include <vector>

#include "energies/linear_constraint_energy.h"
#include "energies/tet_angle_barriers.h"
#include "frontends/polycube/polycube_preparation.h"

namespace sa {

struct PlanarityElements {
    std::vector<LinearConstraintRows<9, 2>> rows;  ///< per boundary triangle
    std::vector<Index> tet;                        ///< its tetrahedron (vec(A) variables)
};
PlanarityElements planarity_elements(const PreparedPolycube& prepared);

struct PlanarityVertexElements {
    std::vector<LinearConstraintRows<9, 2>> rows;
    std::vector<std::array<Index, 3>> vertices;  ///< per boundary triangle, its vertices
};
PlanarityVertexElements planarity_vertex_elements(const PreparedPolycube& prepared);

namespace detail {

/// Calls f(std::integral_constant<int, k>{}) for k in [first, last].
template <int first, int last, class F>
void for_sizes(F&& f) {
    [&]<int... k>(std::integer_sequence<int, k...>) {
        (f(std::integral_constant<int, first + k>{}), ...);
    }
    (std::make_integer_sequence<int, last - first + 1>{});
}

/// Rest vector from vertex a to b.
inline Eigen::Vector3d rest(const PreparedPolycube& p, Index a, Index b) {
    return (p.mesh.vertices.row(b) - p.mesh.vertices.row(a)).transpose();
}

/// The place of each vertex of `ring` (the position in the vertex-form variables).
inline int ring_index(const std::vector<Index>& ring, Index v) {
    return int(std::find(ring.begin(), ring.end(), v) - ring.begin());
}

}  // namespace detail

/// E_e over every boundary edge. `a_form(DihedralSumEnergy<K>, std::vector<std::array<Index, K>>
/// tets)` once per fan size K present; `vertex_form(DihedralSumVertexEnergy<M>,
/// std::vector<std::array<Index, M + 2>> vertices)` (p, q, then the ring) once per ring size M.
/// A fan of more than kMaxAngleFan tetrahedra or kMaxAngleRing ring vertices (none on
/// ../shared/data/polycube: at most 7 and 8) is left out of that form and its index in p.fans
/// appended to `skipped` (when given; once per fan).
template <class AForm, class VertexForm>
void for_each_dihedral_term(const PreparedPolycube& p, AForm&& a_form, VertexForm&& vertex_form,
                            std::vector<Index>* skipped = nullptr) {
    for (std::size_t f = 0; f < p.fans.size(); ++f) {
        const BoundaryEdgeFan& fan = p.fans[f];
        if ((fan.tets.size() > std::size_t(kMaxAngleFan) || fan.ring.size() > kMaxAngleRing) &&
            skipped != nullptr) {
            skipped->push_back(Index(f));
        }
    }
    detail::for_sizes<1, kMaxAngleFan>([&](auto size) {
        constexpr int K = decltype(size)::value;
        DihedralSumEnergy<K> energy;
        std::vector<std::array<Index, K>> tets;
        for (const BoundaryEdgeFan& fan : p.fans) {
            if (int(fan.tets.size()) != K) continue;
            std::array<typename DihedralSumEnergy<K>::Tet, K> element;
            std::array<Index, K> ids;
            for (int k = 0; k < K; ++k) {
                const Index a = fan.edge[0];
                element[k] = {detail::rest(p, a, fan.edge[1]), detail::rest(p, a, fan.others[k][0]),
                              detail::rest(p, a, fan.others[k][1])};
                ids[k] = fan.tets[k];
            }
            energy.fans.push_back(element);
            tets.push_back(ids);
        }
        if (!tets.empty()) a_form(std::move(energy), std::move(tets));
    });
    detail::for_sizes<2, kMaxAngleRing>([&](auto size) {
        constexpr int M = decltype(size)::value;
        DihedralSumVertexEnergy<M> energy;
        std::vector<std::array<Index, M + 2>> vertices;
        for (const BoundaryEdgeFan& fan : p.fans) {
            if (int(fan.ring.size()) != M) continue;
            std::array<Index, M + 2> ids;
            ids[0] = fan.edge[0];
            ids[1] = fan.edge[1];
            for (int m = 0; m < M; ++m) ids[2 + m] = fan.ring[m];
            std::vector<std::array<int, 2>> tets;
            for (const auto& rs : fan.others) {
                tets.push_back(
                    {detail::ring_index(fan.ring, rs[0]), detail::ring_index(fan.ring, rs[1])});
            }
            energy.tets.push_back(std::move(tets));
            vertices.push_back(ids);
        }
        if (!vertices.empty()) vertex_form(std::move(energy), std::move(vertices));
    });
}

/// E_v over every boundary vertex, as for_each_dihedral_term: `a_form(SolidAngleSumEnergy<K>,
/// std::vector<std::array<Index, K>> tets)` for the stars of at most kMaxAngleFan tetrahedra,
/// `vertex_form(SolidAngleSumVertexEnergy<M>, std::vector<std::array<Index, M + 1>> vertices)`
/// (v, then the ring) for the stars of at most kMaxAngleRing ring vertices (on the data up to 31
/// tetrahedra and 20 ring vertices; the Stanford bunny of ../shared/data/tet has a vertex of 43
/// neighbours). A star left out of either form has its vertex appended to `skipped` (when given;
/// once per star).
template <class AForm, class VertexForm>
void for_each_solid_angle_term(const PreparedPolycube& p, AForm&& a_form, VertexForm&& vertex_form,
                               std::vector<Index>* skipped = nullptr) {
    for (const BoundaryVertexStar& star : p.stars) {
        if ((star.tets.size() > std::size_t(kMaxAngleFan) || star.ring.size() > kMaxAngleRing) &&
            skipped != nullptr) {
            skipped->push_back(star.vertex);
        }
    }
    detail::for_sizes<1, kMaxAngleFan>([&](auto size) {
        constexpr int K = decltype(size)::value;
        SolidAngleSumEnergy<K> energy;
        std::vector<std::array<Index, K>> tets;
        for (const BoundaryVertexStar& star : p.stars) {
            if (int(star.tets.size()) != K) continue;
            std::array<typename SolidAngleSumEnergy<K>::Tet, K> element;
            std::array<Index, K> ids;
            for (int k = 0; k < K; ++k) {
                const Index v = star.vertex;
                element[k] = {detail::rest(p, v, star.others[k][0]),
                              detail::rest(p, v, star.others[k][1]),
                              detail::rest(p, v, star.others[k][2])};
                ids[k] = star.tets[k];
            }
            energy.stars.push_back(element);
            tets.push_back(ids);
        }
        if (!tets.empty()) a_form(std::move(energy), std::move(tets));
    });
    detail::for_sizes<3, kMaxAngleRing>([&](auto size) {
        constexpr int M = decltype(size)::value;
        SolidAngleSumVertexEnergy<M> energy;
        std::vector<std::array<Index, M + 1>> vertices;
        for (const BoundaryVertexStar& star : p.stars) {
            if (int(star.ring.size()) != M) continue;
            std::array<Index, M + 1> ids;
            ids[0] = star.vertex;
            for (int m = 0; m < M; ++m) ids[1 + m] = star.ring[m];
            std::vector<std::array<int, 3>> tets;
            for (const auto& abc : star.others) {
                tets.push_back({detail::ring_index(star.ring, abc[0]),
                                detail::ring_index(star.ring, abc[1]),
                                detail::ring_index(star.ring, abc[2])});
            }
            energy.tets.push_back(std::move(tets));
            vertices.push_back(ids);
        }
        if (!vertices.empty()) vertex_form(std::move(energy), std::move(vertices));
    });
}

}  // namespace sa
