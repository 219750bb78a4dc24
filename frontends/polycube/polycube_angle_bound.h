#pragma once
// A lower bound, from the labels alone, on the conformal distortion of every valid PolyCube map.
//
// In a PolyCube every chart is a planar rectilinear polygon, so the angle a chart makes at a
// boundary vertex v is fixed by how many chart wedges meet there (a wedge: the chart's triangles
// around v that share edges at v):
//   one wedge (v inside its chart):     2 pi;
//   two wedges (v on one PolyCube edge): pi for each;
//   three or more (a PolyCube corner):   pi/2, pi or 3 pi/2 for each.
// The map is linear on every tetrahedron, and a linear map whose singular values have ratio K
// (restricted to the plane of a rest triangle: at most the tetrahedron's sigma_max / sigma_min,
// delta_con in geometry/quality/map_quality.h) takes an angle alpha to an angle between
// 2 atan(tan(alpha/2) / K) and 2 atan(K tan(alpha/2)). A wedge of rest angles alpha_i that must
// become beta therefore needs some tetrahedron under it with delta_con >= the least K for which
// those ranges can sum to beta (wedge_distortion_bound()). The largest such K over the boundary
// bounds max delta_con of any valid PolyCube map of these labels on this mesh, whatever the
// solver: a chart that ends in a sliver of a fraction of a degree at a vertex on its edge with
// another chart, where it must open to 180 degrees, forces a distortion in the hundreds
// (docs/measurements.md, PolyCube).
//
// Angles in radians; positions in any units (angles do not see them).

#include <string>
#include <vector>

#include "frontends/polycube/polycube_labeling.h"

namespace sa {

/// One chart wedge at a boundary vertex and what it forces.
struct WedgeAngleBound {
    Index vertex = -1;         ///< the boundary vertex (0-based)
    int chart = -1;            ///< PolycubeCharts numbering
    int label = -1;            ///< the chart's label (0..5: +X, -X, ..., -Z)
    int wedges = 0;            ///< chart wedges at the vertex (all charts)
    Index triangles = 0;       ///< the wedge's boundary triangles
    double rest_angle = 0.0;   ///< sum of their rest angles at the vertex
    double image_angle = 0.0;  ///< the PolyCube angle that needs the least distortion
    double bound = 1.0;        ///< delta_con some tetrahedron under the wedge reaches at least

    /// "at vertex 11 (0-based) the +X chart's wedge of 0.7416 degrees (2 triangles) must open
    /// to 180".
    std::string describe() const;
};

struct PolycubeAngleBound {
    /// max delta_con of any valid PolyCube map is at least this (1: the angles force nothing;
    /// +inf: no valid map, as when one triangle must open to pi).
    double bound = 1.0;
    /// The wedges with the largest bounds, largest first, one per vertex (at most `keep`).
    std::vector<WedgeAngleBound> worst;
};

/// The least K >= 1 such that angles beta_i with 2 atan(tan(alpha_i/2) / K) <= beta_i <=
/// 2 atan(K tan(alpha_i/2)) can sum to `target`; +inf when none can (target >= n pi).
/// `rest_angles` alpha_i each in (0, pi); `target` > 0.
double wedge_distortion_bound(const std::vector<double>& rest_angles, double target);

/// The bound of `labels`' charts (polycube_charts() of the boundary) on the mesh with rest
/// `positions` (#V x 3), keeping the `keep` worst wedges. Vertices where the boundary pinches
/// (its triangles there form several fans) are left out.
PolycubeAngleBound polycube_angle_bound(const TetBoundary& boundary, const PolycubeCharts& charts,
                                        const Eigen::MatrixXd& positions, int keep = 5);

}  // namespace sa
