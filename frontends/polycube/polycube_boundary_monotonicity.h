#pragma once
// Monotone chart boundaries of a PolyCube labelling, measured at rest.
//
// Where charts a and b meet, the PolyCube has a straight edge along d = n_a x n_b (n the label
// directions): walked with chart a on its left (outward winding), every mesh edge on it maps to
// +d at a convex PolyCube edge and to -d at a concave one. A chart boundary whose rest edges go
// both ways along d (a "turning point": the boundary runs past a corner and comes back, or is
// U-shaped) can only become straight if the map reverses part of it, which folds or flattens the
// tetrahedra around it unless the mesh can make room ("Validity-first automatic polycube
// labeling for CAD models", 2024, counts such turning points as invalid). A boundary is a connected
// chain of mesh edges between two charts whose labels have different axes (two charts may meet
// along several); its direction is the sign of sum_e h_e . d over its edges (h_e the rest edge
// vector); an edge is backward when h_e . d has the other sign, strongly backward when h_e . d <
// -strong_cosine |h_e| (a zigzag across d is not).

#include <array>
#include <vector>

#include "frontends/polycube/polycube_labeling.h"

namespace sa {

/// A chart boundary (one chain) with strongly backward edges.
struct NonMonotoneBoundary {
    int chart_a = -1, chart_b = -1;  ///< chart_a < chart_b (PolycubeCharts numbering)
    int label_a = -1, label_b = -1;  ///< their labels (0..5)
    Index edges = 0;                 ///< mesh edges on the boundary
    Index strongly_backward = 0;     ///< of which strongly backward
    double length = 0.0;             ///< rest length of the boundary (rest units)
    double backward_travel = 0.0;    ///< sum over backward edges of |h_e . d| (rest units)
    Index vertex = -1;               ///< a vertex of a strongly backward edge (0-based)
    /// Per strongly backward edge: its two boundary triangles, chart_a's first.
    std::vector<std::array<Index, 2>> backward_triangles;
};

/// The non-monotone boundaries of `labels` (one per boundary triangle, 0..5) at rest `positions`
/// (#V x 3), longest backward travel first. `charts` must be polycube_charts() of `labels`.
std::vector<NonMonotoneBoundary> non_monotone_boundaries(const TetBoundary& boundary,
                                                         const Eigen::MatrixXd& positions,
                                                         const std::vector<int>& labels,
                                                         const PolycubeCharts& charts,
                                                         double strong_cosine = 0.5);

}  // namespace sa
