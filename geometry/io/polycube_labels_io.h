#pragma once
// PolyCube labelling files: one integer label per line (any whitespace separates them).
//
//   .flags (polycube_withHexEx, robustPolycube)  one label per tetrahedron facet, 4 per
//       tetrahedron, tetrahedron by tetrahedron, facets in ultimaille's order: facet k of tet
//       (v0, v1, v2, v3) is the one opposite v_k, wound {1,2,3}, {0,3,2}, {0,1,3}, {0,2,1}
//       (frontends/polycube/polycube_labeling.h: kTetFacetCorners). -1 marks a facet without a
//       label (an interior facet); 0..5 on boundary facets, label / 2 = axis (x, y, z).
//   labeling.txt (fastbndpolycube)  one label 0..5 per triangle of a boundary surface (an OBJ),
//       in the surface's triangle order.
// The readers check the file (count and range); what a label means (its sign convention) is
// decided from the geometry by frontends/polycube/polycube_labeling.h.

#include <string>
#include <vector>

#include "optim/types.h"

namespace sa {

/// Reads a .flags file for a mesh of `num_tets` tetrahedra: 4 * num_tets integers in [-1, 5].
/// Throws InputError `FILE:LINE: ...` on a token that is not an integer or a label outside
/// [-1, 5] (naming the tetrahedron and facet), and `FILE: ...` when the count is not
/// 4 * num_tets.
std::vector<int> read_facet_flags(const std::string& path, Index num_tets);

/// Reads a per-triangle label file for a surface of `num_triangles` triangles: that many
/// integers in [0, 5]. Throws InputError `FILE:LINE: ...` on a bad token or a label out of range
/// (naming the triangle), `FILE: ...` on a wrong count.
std::vector<int> read_triangle_labels(const std::string& path, Index num_triangles);

/// Writes one label per line (the .flags layout). Throws InvalidArgumentError on a label outside
/// [-1, 5] (naming its position) and InputError when the file cannot be written (nothing is left
/// at `path` then).
void write_facet_flags(const std::string& path, const std::vector<int>& flags);

}  // namespace sa
