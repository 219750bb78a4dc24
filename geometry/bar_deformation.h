#pragma once
// The paper's Figure 16 experiment, generated: a bar of tetrahedra (5:1:1) whose handle slabs at
// both ends are moved rigidly, the left one kept in place and the right one
//   bent        turned by `bend_degrees` about z and carried to the end of the circular arc of
//               the bar's length: the centre line becomes a quarter circle for 90 degrees;
//   twisted     turned by `twist_degrees` about the bar's axis;
//   translated  moved sideways (along y) by `shift` bar widths.
// The interior is free: a deformation problem of handles and targets, without an initial map
// (the paper starts from an ARAP deformation; tests and benchmarks use it the same way).
//
// The bar is [0, length] x [0, width] x [0, width], cut into length_cells x cross_cells x
// cross_cells boxes of six positively oriented tetrahedra (grid_tetrahedra, scaled): with the
// defaults 36 x 6 x 6 boxes, 7,776 tetrahedra and 1,813 vertices ("about 8,000 tetrahedra").

#include <Eigen/Core>
#include <string>
#include <vector>

#include "geometry/simplicial_mesh.h"

namespace sa {

enum class BarPose { kBend, kTwist, kTranslate };

/// "bend", "twist", "translate".
std::string to_string(BarPose pose);
/// The names of to_string(); throws InvalidArgumentError otherwise.
BarPose parse_bar_pose(const std::string& name);

struct BarDeformationOptions {
    int length_cells = 36;  ///< boxes along x
    int cross_cells = 6;    ///< boxes along y and along z
    double length = 5.0;
    double width = 1.0;
    /// Handles: the vertices within slab * length of either end.
    double slab = 0.05;
    double bend_degrees = 90.0;
    double twist_degrees = 180.0;
    double shift = 1.0;  ///< in bar widths

    /// Throws InvalidArgumentError naming the first bad field and its value.
    void validate() const;
};

/// A deformation problem: the rest mesh, the handle vertices and where they go.
struct BarDeformation {
    std::string name;  ///< "bar-bend", "bar-twist", "bar-translate"
    SimplicialMesh mesh;
    std::vector<Index> handles;  ///< increasing
    Eigen::MatrixXd targets;     ///< #handles x 3
};

BarDeformation bar_deformation(BarPose pose, const BarDeformationOptions& options = {});

}  // namespace sa
