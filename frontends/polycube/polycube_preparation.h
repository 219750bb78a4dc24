#pragma once
// The input side of `sa polycube` (issue 21), everything before the solve: a tetrahedral mesh and
// its boundary labelling (from a .flags file, from per-triangle labels of a boundary surface, or
// computed by closest axis, cleaned and, where chart boundaries turn back, repaired
// (polycube_label_repair.h), in the input's axes or turned by
// polycube_orientation(), whichever labelling is better), checked, the mesh split where
// planarity would squash it (frontends/polycube/polycube_splits.h), and the least conformal
// distortion the labels force on any valid map measured
// (frontends/polycube/polycube_angle_bound.h).
//
//   PolycubeLabelInput input;                 // empty: compute the labels
//   input.flags = "S1.flags";
//   const PreparedPolycube p = prepare_polycube(mesh, "S1.mesh", input, logger);
//   // p.mesh: the rest mesh of the map (the input after the splits); p.charts, p.fans, ...
//
// Errors (InputError, one line, naming the file and the tetrahedron, facet or chart): a mesh that
// is not tetrahedral, degenerate rest tetrahedra, a boundary that is not a closed manifold
// surface (a non-conforming mesh, whose neighbouring tetrahedra split a common face differently,
// has one through its inside), labels with a wrong count or out of range,
// interior facets labelled, boundary facets without a label, a surface that is not the mesh's
// boundary, a chart that cannot be planar, labels that leave tetrahedra flat for every position
// of the planes after the splits (no valid PolyCube map exists: refused before any solve).

#include <optional>
#include <string>
#include <vector>

#include "frontends/polycube/polycube_angle_bound.h"
#include "frontends/polycube/polycube_boundary_monotonicity.h"
#include "frontends/polycube/polycube_label_cleanup.h"
#include "frontends/polycube/polycube_label_repair.h"
#include "frontends/polycube/polycube_orientation.h"
#include "frontends/polycube/polycube_splits.h"
#include "frontends/polycube/polycube_verification.h"
#include "frontends/polycube/tet_boundary_fans.h"
#include "optim/logger.h"

namespace sa {

/// Where the labels come from: `flags`, or `labels` with `surface`, or neither (computed).
struct PolycubeLabelInput {
    std::string flags;            ///< a .flags file: one label per tet facet
    std::string labels;           ///< one label per triangle of `surface`
    std::string surface;          ///< the boundary surface that `labels` refers to
    LabelCleanupOptions cleanup;  ///< for computed labels
    /// Computed labels: label (and map) the input turned by polycube_orientation(), which the
    /// map does not otherwise see; false: in the input's own axes.
    bool orient = true;
    /// Computed labels: repair chart boundaries that turn back (polycube_label_repair.h).
    bool repair = true;
};

struct PreparedPolycube {
    SimplicialMesh input;  ///< the mesh as given
    /// Computed labels: the rotation R that `mesh` is turned by (its vertices are R x of the
    /// input's), chosen so that the labels face the axes best; empty otherwise (R = I).
    std::optional<PolycubeOrientation> orientation;
    /// The rest mesh of the map: the input after the splits (its vertices and tetrahedra first,
    /// in their order; a split tetrahedron's first child keeps its index), turned by
    /// `orientation` and at unit scale (times 2^-scale_exponent). The map's energies see neither;
    /// maps of `mesh` are in its units (in_input_units() for what is written).
    SimplicialMesh mesh;
    /// scale_exponent(input.vertices) (simplicial_mesh.h): `mesh` is the input times 2^-k, so
    /// that a mesh at 1e100 or 1e-100 is prepared and solved as at 1, with the same bits.
    int scale_exponent = 0;
    std::vector<int> facet_labels;  ///< per tet facet of `mesh`: -1 or 0..5 (+X, -X, ..., -Z)
    MeshTopology topology;
    TetBoundary boundary;
    std::vector<int> labels;  ///< per boundary triangle
    PolycubeCharts charts;
    std::vector<BoundaryEdgeFan> fans;
    std::vector<BoundaryVertexStar> stars;
    double input_volume = 0.0;  ///< of `mesh`, in its units

    std::string label_source;  ///< "computed" or the file the labels came from
    /// File labels: how their parity related to the geometry.
    std::optional<LabelConvention> convention;
    /// The parity .flags outputs are written in: the input file's when it followed one
    /// convention throughout, otherwise even = +axis along the outward normal.
    FlagSign output_sign = FlagSign::kOutward;
    std::optional<LabelCleanupReport> cleanup;  ///< computed labels
    std::optional<LabelRepairReport> repair;    ///< computed labels that turned back
    /// Chart boundaries of the labels (on `input`) that turn back along their PolyCube edge.
    std::vector<NonMonotoneBoundary> non_monotone;
    PolycubeSplitReport splits;
    /// What the labels force on `mesh`: every valid PolyCube map has max delta_con >= its bound.
    PolycubeAngleBound angle_bound;
    double read_labels_seconds = 0.0, splits_seconds = 0.0;

    /// Pointers into this object, for verify_polycube().
    PolycubeLayout layout() const { return {&mesh, &boundary, &charts, &fans, &stars}; }
    /// `mesh`'s vertices in the input's frame and units (#V x 3): the input's own, then the
    /// splits' new vertices turned and scaled back. What OUT.rest.mesh holds.
    Eigen::MatrixXd rest_positions() const;
    /// A map of `mesh` (#V x 3) in the input's units (times 2^scale_exponent, exactly): what
    /// OUT.mesh holds.
    Eigen::MatrixXd in_input_units(const Eigen::MatrixXd& positions) const;
    /// The .flags array of `mesh` in output_sign's convention.
    std::vector<int> output_flags() const;
};

/// Prepares `mesh` (read from `source`) for a PolyCube map. Progress lines go to `logger`.
PreparedPolycube prepare_polycube(const SimplicialMesh& mesh, const std::string& source,
                                  const PolycubeLabelInput& input, const Logger& logger = {});

}  // namespace sa
