#pragma once
// Clean-up of a computed PolyCube labelling (closest axis per boundary triangle,
// frontends/polycube/polycube_labeling.h), so that every chart can become a face of a PolyCube:
//   - a chart that is too small (fewer than min_triangles triangles, or less than
//     min_area_fraction of the boundary's area) is merged into a neighbour;
//   - a chart with fewer than min_neighbours adjacent charts (a PolyCube face is a rectilinear
//     polygon: at least four sides, each along another face) is merged into a neighbour;
//   - of two adjacent charts with opposite labels of one axis (+X beside -X: their planes would
//     meet at a dihedral angle of 0 or 2 pi), the smaller is merged into a neighbour.
//   - a tooth, a boundary triangle with two of its three neighbours in one other label, takes
//     that label (unless the opposite label of its axis is beside it, or its normal points away
//     from the label's direction): left alone, a chart boundary that zigzags across a PolyCube
//     edge turns by a right angle at every tooth, and the tetrahedra on the edge there must
//     turn with it (on robustPolycube/M1_tet the untangling on the planes flattened them).
// Merging gives every triangle of the chart the label of one of its neighbour charts: the one
// whose direction best fits the chart's area-weighted normals, preferring labels that create no
// new opposite pair. Each merge removes at least one chart, so the clean-up ends; charts are
// treated smallest first, several per round when their neighbourhoods do not overlap.

#include <vector>

#include "frontends/polycube/polycube_labeling.h"

namespace sa {

struct LabelCleanupOptions {
    /// A chart with fewer triangles is too small: one triangle cannot be a PolyCube face (a
    /// rectilinear polygon has at least four corners).
    int min_triangles = 2;
    double min_area_fraction = 1e-3;  ///< ... or with less of the total boundary area
    int min_neighbours = 4;
    bool remove_teeth = true;
    int max_rounds = 10000;
};

struct LabelCleanupReport {
    int charts_before = 0;
    int charts_after = 0;
    int merged_small = 0;           ///< charts merged for their size
    int merged_few_neighbours = 0;  ///< ... for having fewer than min_neighbours neighbours
    int merged_opposite = 0;        ///< ... for touching the opposite label of their axis
    Index teeth = 0;                ///< teeth relabelled (a triangle may count more than once)
    Index triangles_changed = 0;    ///< boundary triangles whose label changed
    int rounds = 0;
    bool clean = false;  ///< no chart left that breaks a rule
};

/// Cleans `labels` (one per boundary triangle, 0..5) in place. `positions` #V x 3 (rest).
LabelCleanupReport clean_polycube_labels(const TetBoundary& boundary,
                                         const Eigen::MatrixXd& positions, std::vector<int>& labels,
                                         const LabelCleanupOptions& options = {});

/// As clean_polycube_labels(), from the boundary triangles' area vectors (boundary_area_vectors()
/// of the rest positions, #B x 3): for callers that clean many labellings of one shape. When
/// `charts` is given, it receives polycube_charts() of the labels as they end.
LabelCleanupReport clean_polycube_labels_of_areas(const TetBoundary& boundary,
                                                  const Eigen::MatrixXd& area_vectors,
                                                  std::vector<int>& labels,
                                                  const LabelCleanupOptions& options = {},
                                                  PolycubeCharts* charts = nullptr);

}  // namespace sa
