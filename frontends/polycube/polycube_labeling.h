#pragma once
// PolyCube labellings of a tetrahedral mesh's boundary (the paper's 5.3, "PolyCube mapping"):
// every boundary triangle gets one of the six axis directions, the outward normal of the
// PolyCube face it maps to. A chart is a connected set of boundary triangles (across boundary
// edges) with one label; the PolyCube map makes each chart planar and orthogonal to its axis.
//
// Labels are 0..5 = +X, -X, +Y, -Y, +Z, -Z (2 axis + 1 on the negative side), per boundary
// triangle in TetBoundary's numbering (geometry/mesh/tet_boundary.h). In .flags files (one label
// per tet facet, -1 on interior facets; geometry/io/polycube_labels_io.h) the parity is a sign
// convention that files do not agree on, so a file's label gives the axis only and the side comes
// from the geometry: per chart (a connected set of triangles with one file label), the sign of
// the area-weighted outward normal along the axis. Which convention the file followed is
// reported (LabelConvention).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "geometry/mesh/tet_boundary.h"

namespace sa {

inline constexpr int kNoLabel = -1;

inline int label_axis(int label) {
    return label / 2;
}
/// +1 or -1.
inline int label_sign(int label) {
    return label % 2 == 0 ? 1 : -1;
}
inline int make_label(int axis, int sign) {
    return 2 * axis + (sign < 0 ? 1 : 0);
}
/// The unit vector of a label.
Eigen::Vector3d label_direction(int label);
/// "+X", "-X", ..., "-Z".
std::string label_name(int label);

/// The charts of a labelling: connected components of boundary triangles with one label, across
/// boundary edges shared by exactly two boundary triangles.
struct PolycubeCharts {
    std::vector<int> chart_of;                 ///< per boundary triangle
    std::vector<int> label;                    ///< per chart
    std::vector<std::vector<Index>> members;   ///< per chart: its boundary triangles, increasing
    std::vector<std::vector<int>> neighbours;  ///< per chart: adjacent charts, distinct, sorted
    std::vector<double> area;                  ///< per chart: rest area
    /// Per chart: sum over its triangles of area * (outward unit normal . label direction).
    std::vector<double> aligned_area;

    int size() const { return static_cast<int>(label.size()); }
};

/// Charts of `labels` (one per boundary triangle, 0..5) on the mesh with vertex `positions`
/// (#V x 3, the rest shape). Throws InvalidArgumentError on a label outside 0..5.
PolycubeCharts polycube_charts(const TetBoundary& boundary, const Eigen::MatrixXd& positions,
                               const std::vector<int>& labels);

/// As polycube_charts(), from the boundary triangles' area vectors (boundary_area_vectors() of
/// the rest positions, #B x 3) instead of the positions: for callers that chart many labellings
/// of one shape.
PolycubeCharts polycube_charts_of_areas(const TetBoundary& boundary,
                                        const Eigen::MatrixXd& area_vectors,
                                        const std::vector<int>& labels);

/// Each boundary triangle's closest direction: the label maximizing (outward normal . direction)
/// (ties to the lower label).
std::vector<int> closest_axis_labels(const TetBoundary& boundary, const Eigen::MatrixXd& positions);

/// How a file's label parity related to the geometry: counted over boundary triangles.
struct LabelConvention {
    /// Even labels point along +axis of the outward normal (0..5 = +X, -X, ..., the README of
    /// polycube_withHexEx).
    Index outward = 0;
    /// Even labels point along -axis of the outward normal: the opposite convention.
    Index inward = 0;
    /// Rest tetrahedra with negative orientation: their ultimaille facet winding points inwards,
    /// so a labeller that takes that winding for the normal (ultimaille's facet_normal) writes the
    /// opposite convention on them.
    Index negative_tets = 0;
    Index tets = 0;
    /// One line: which convention, and why it may be so.
    std::string describe() const;
};

/// Labels from a file's per-boundary-triangle labels (0..5): the axis from the file, the side
/// from the geometry (per chart of equal file labels, the sign of its area-weighted outward normal
/// along the axis). Fills `convention`. Throws InputError `SOURCE: ...` naming a tetrahedron and
/// facet of a chart whose area-weighted normal has no side along its axis (|sum| <= 1e-9 of its
/// area): no plane orthogonal to that axis can take it without folding.
std::vector<int> labels_from_file_axes(const SimplicialMesh& mesh, const TetBoundary& boundary,
                                       const std::vector<int>& file_labels,
                                       const std::string& source, LabelConvention* convention);

/// Per-boundary-triangle file labels from a .flags array (4 per tetrahedron). Throws InputError
/// `SOURCE: tetrahedron T facet K ...` for a boundary facet without a label (-1) or an interior
/// facet with one, and for a count other than 4 #T.
std::vector<int> boundary_labels_from_flags(const TetBoundary& boundary, Index num_tets,
                                            const std::vector<int>& flags,
                                            const std::string& source);

/// Which parity a written .flags file uses (see LabelConvention).
enum class FlagSign {
    kOutward,  ///< even = +axis along the outward normal
    kInward,   ///< even = +axis along the inward normal
};

/// A .flags array (4 #T entries, -1 on interior facets) for `labels` in the given convention.
std::vector<int> facet_flags(const TetBoundary& boundary, Index num_tets,
                             const std::vector<int>& labels, FlagSign sign = FlagSign::kOutward);

/// Checks that a labelling can be made planar: every chart's area-weighted outward normal points
/// to its label's side (aligned_area > 0), and no two charts of opposite labels on one axis share
/// an edge (their planes would meet at a dihedral angle of 0 or 2 pi). Throws InputError
/// `SOURCE: ...` naming the chart by a tetrahedron and facet, its label and size.
void validate_polycube_labels(const SimplicialMesh& mesh, const TetBoundary& boundary,
                              const std::vector<int>& labels, const std::string& source);

/// "tetrahedron T facet K" for boundary triangle b.
std::string describe_boundary_triangle(const TetBoundary& boundary, Index b);

}  // namespace sa
