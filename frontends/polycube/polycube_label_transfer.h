#pragma once
// Labels given per triangle of a surface that is a tetrahedral mesh's boundary (fastbndpolycube's
// boundary.obj with labeling.txt) moved onto the tetrahedral mesh's boundary triangles.
//
// Surface vertices are matched to boundary vertices of the tetrahedral mesh by position: each to
// the nearest one, which must lie within `tolerance` times that vertex's shortest boundary edge
// (at most a quarter, so that the match is unambiguous). Files often round the coordinates
// differently (a tet mesh written with 6 significant digits, its surface with 15), and short
// boundary edges can be only a few hundred times longer than the rounding. Triangles are then
// matched by their vertex sets; the winding is not compared (labels take their side from the
// geometry, frontends/polycube/polycube_labeling.h).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "geometry/mesh/tet_boundary.h"

namespace sa {

/// For each boundary triangle of the tetrahedral mesh (TetBoundary's numbering), the label of the
/// matching triangle of `surface` (#F x 3 triangles, vertices #V' x 3). Throws InputError
/// `SOURCE: ...` naming the surface vertex that matches no boundary vertex (or two surface
/// vertices that match the same one), the surface triangle that is not a boundary triangle, or
/// the boundary triangle (tetrahedron and facet) that the surface lacks.
std::vector<int> transfer_surface_labels(const SimplicialMesh& mesh, const TetBoundary& boundary,
                                         const SimplicialMesh& surface,
                                         const std::vector<int>& surface_labels,
                                         const std::string& source, double tolerance = 0.1);

}  // namespace sa
