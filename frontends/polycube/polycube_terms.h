#pragma once
// The PolyCube-specific terms of the solve (issue 21), built from a prepared mesh, for the
// Simplex Assembly engine to add (issue 20): each builder gives the element energies and, per
// element, the simplices or vertices whose variables it takes, in the order the energy expects.
// The engine maps them to variable indices (linear_variables(t) is vec(A_t), 9 entries,
// column-major; vertex v is 3 entries in the vertex stage). Rest frames keep the mesh's axes
// (geometry/mesh/rest_frames.h), so rest edge vectors are coordinate differences.
//
//   planarity_elements         Ẽ_assembly, A-form: per labelled boundary triangle, its tet.
//   planarity_vertex_elements  the same in vertex form: per boundary triangle, its 3 vertices.
//   dihedral_sum_elements      E_e in A-form: per boundary edge, its tetrahedra.
//   solid_angle_sum_elements   E_v in A-form: per boundary vertex, its tetrahedra.
//   dihedral_sum_vertex_elements, solid_angle_sum_vertex_elements   the same in vertex form: per
//                              boundary edge p, q and its ring; per boundary vertex, it and its
//                              ring.
// The barriers are of run-time arity (frontends/polycube/tet_angle_barriers.h): every boundary edge
// and vertex has one, whatever the number of its tetrahedra.

#include <array>
#include <vector>

#include "energies/linear_constraint_energy.h"
#include "frontends/polycube/polycube_preparation.h"
#include "frontends/polycube/tet_angle_barriers.h"
#include "optim/ragged_elements.h"

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

/// A barrier's energy and, per element, the tetrahedra (A-form: vec(A) of each, 9 variables)
/// or the vertices (vertex form: 3 coordinates each) whose variables it takes, in order.
template <class Energy>
struct AngleBarrierElements {
    Energy energy;
    RaggedElements items;
};

AngleBarrierElements<DihedralSumEnergy> dihedral_sum_elements(const PreparedPolycube& p);
AngleBarrierElements<DihedralSumVertexEnergy> dihedral_sum_vertex_elements(
    const PreparedPolycube& p);
AngleBarrierElements<SolidAngleSumEnergy> solid_angle_sum_elements(const PreparedPolycube& p);
AngleBarrierElements<SolidAngleSumVertexEnergy> solid_angle_sum_vertex_elements(
    const PreparedPolycube& p);

namespace detail {

/// Rest vector from vertex a to b.
inline Eigen::Vector3d rest(const PreparedPolycube& p, Index a, Index b) {
    return (p.mesh.vertices.row(b) - p.mesh.vertices.row(a)).transpose();
}

}  // namespace detail

}  // namespace sa
