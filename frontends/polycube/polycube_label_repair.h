#pragma once
// Repair of chart boundaries that turn back along their PolyCube edge
// (frontends/polycube/polycube_boundary_monotonicity.h) in a computed, cleaned PolyCube labelling.
//
// A turning boundary between two fixed corners cannot be undone by relabelling one triangle at a
// time: flipping a triangle replaces a boundary edge u -> v by u -> w -> v with the same net
// travel, so the backward travel falls only when a corner moves. The repair therefore moves
// patches: for a strongly backward edge, the triangles of one of its two charts within r rings of
// it (r = 0 .. max_rings, rings taken inside that chart) take the label of a chart beside the
// patch (not the opposite of their own). Each trial labelling is cleaned again
// (frontends/polycube/polycube_label_cleanup.h) and must stay usable: clean, every chart facing its
// side. Of all trials the one with the fewest strongly backward edges (then the least backward
// travel, then the fewest triangles changed) is kept when it has fewer than the current labels; the
// repair stops when no trial improves, or after max_moves moves. Greedy and local: a boundary
// that needs a chart it has no neighbour for stays as it is.

#include <vector>

#include "frontends/polycube/polycube_label_cleanup.h"
#include "frontends/polycube/polycube_labeling.h"

namespace sa {

struct LabelRepairOptions {
    int max_moves = 16;
    /// Patch sizes tried: the rings around a backward edge's triangle, inside its chart.
    int max_rings = 4;
    /// Backward edges tried per turning boundary and move (spread along it).
    int edges_per_boundary = 3;
    /// Cosine of strongly backward (non_monotone_boundaries's strong_cosine).
    double strong_cosine = 0.5;
    LabelCleanupOptions cleanup;
};

struct LabelRepairReport {
    int turning_before = 0;  ///< chart boundaries with strongly backward edges
    int turning_after = 0;
    Index backward_before = 0;  ///< strongly backward edges, over all boundaries
    Index backward_after = 0;
    int moves = 0;                ///< patches relabelled
    Index triangles_changed = 0;  ///< boundary triangles whose label changed
    int trials = 0;               ///< labellings tried
};

/// Repairs `labels` (one per boundary triangle, 0..5, clean: clean_polycube_labels() reported
/// clean) in place at rest `positions` (#V x 3). Labels without turning boundaries are unchanged.
LabelRepairReport repair_turning_boundaries(const TetBoundary& boundary,
                                            const Eigen::MatrixXd& positions,
                                            std::vector<int>& labels,
                                            const LabelRepairOptions& options = {});

}  // namespace sa
