#pragma once
// Verification of a PolyCube map from its output vertex positions (issue 21): the map passes
// when every check holds.
//   - no inverted and no degenerate tetrahedron (geometry/quality/map_quality.h's rules, against
//   each
//     rest tetrahedron's orientation);
//   - every chart planar: the spread of its vertices along its axis at most `planarity_tolerance`
//     times the output's bounding-box diagonal, and its area-weighted normal on its label's side;
//   - no zero-length PolyCube edge: each connected run of mesh edges between two charts longer
//     than `planarity_tolerance` times the diagonal;
//   - every boundary edge's dihedral-angle sum below 2 pi and every boundary vertex's solid-angle
//     sum below 4 pi (frontends/polycube/boundary_angle_sums.h).
// Distortion is measured too, after scaling the output to the input's volume (delta_con does not
// change; delta_iso and delta_vol do).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "frontends/polycube/polycube_labeling.h"
#include "frontends/polycube/tet_boundary_fans.h"
#include "geometry/quality/map_quality.h"

namespace sa {

/// A PolyCube map to check: the rest mesh (after the splits) with its boundary, charts, fans and
/// stars.
struct PolycubeLayout {
    const SimplicialMesh* mesh = nullptr;
    const TetBoundary* boundary = nullptr;
    const PolycubeCharts* charts = nullptr;
    const std::vector<BoundaryEdgeFan>* fans = nullptr;
    const std::vector<BoundaryVertexStar>* stars = nullptr;
};

struct PolycubeVerification {
    MapQuality quality;          ///< after scaling to the input volume
    double volume_scale = 1.0;   ///< the factor applied to the output's positions for `quality`
    double diagonal = 0.0;       ///< the output's bounding-box diagonal
    double max_planarity = 0.0;  ///< largest chart spread along its axis / diagonal
    int nonplanar_charts = 0;
    int wrong_side_charts = 0;
    int polycube_edges = 0;
    int zero_length_edges = 0;
    double shortest_edge = kInfinity;  ///< shortest PolyCube edge / diagonal
    Index edge_angle_violations = 0;   ///< boundary edges with theta_e >= 2 pi
    Index vertex_angle_violations = 0;
    double max_edge_angle_sum = 0.0;  ///< radians
    double max_vertex_angle_sum = 0.0;
    bool passed = false;
    /// One line per failed check, naming a witness (a tetrahedron, chart, edge or vertex).
    std::vector<std::string> failures;
};

/// Checks `positions` (#V x 3, one row per vertex of layout.mesh). `input_volume` is the volume
/// of the input mesh (the distortion's scale).
PolycubeVerification verify_polycube(const PolycubeLayout& layout, const Eigen::MatrixXd& positions,
                                     double input_volume, double planarity_tolerance = 1e-9);

/// The total unsigned volume of a tetrahedral mesh's tetrahedra at `positions`.
double tet_mesh_volume(const SimplicialMesh& mesh, const Eigen::MatrixXd& positions);

}  // namespace sa
