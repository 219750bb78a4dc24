#pragma once
// A simplicial mesh: triangles (in the plane or in space) or tetrahedra, libigl-style.
//
//   vertices   #V x 2 or #V x 3 rest positions (one row per vertex)
//   simplices  #S x 3 (triangles) or #S x 4 (tetrahedra), 0-based vertex indices (one row each)
//
// The simplex dimension d is simplices.cols() - 1. A map of the mesh has d coordinates per vertex
// (triangles map to the plane, tetrahedra to space). Each element's orientation is taken from its
// rest shape: an element of a map is inverted when its orientation differs from its rest one
// (for triangles in space, the rest orientation is that of its own plane frame: always positive).

#include <Eigen/Core>
#include <string>

#include "optim/types.h"

namespace sa {

struct SimplicialMesh {
    Eigen::MatrixXd vertices;
    Eigen::MatrixXi simplices;

    int simplex_dimension() const { return static_cast<int>(simplices.cols()) - 1; }
    int ambient_dimension() const { return static_cast<int>(vertices.cols()); }
    Index num_vertices() const { return static_cast<Index>(vertices.rows()); }
    Index num_simplices() const { return static_cast<Index>(simplices.rows()); }
    /// Vertex v in space: z = 0 for a planar mesh.
    Eigen::Vector3d point(Index v) const {
        Eigen::Vector3d p = Eigen::Vector3d::Zero();
        p.head(ambient_dimension()) = vertices.row(v).transpose();
        return p;
    }
};

/// Checks the mesh's shape and indices: 2 or 3 columns of finite coordinates, 3 or 4 vertex
/// indices per simplex, each in range and distinct, tetrahedra only in 3D, and no simplex of zero
/// rest volume (relative to the bounding box). Throws InputError naming `source` (a file name or
/// a description) and the first offending simplex or vertex.
void validate_mesh(const SimplicialMesh& mesh, const std::string& source);

/// Length of the diagonal of the bounding box of the rows of `points`.
double bounding_box_diagonal(const Eigen::MatrixXd& points);

/// The exponent k of the power of two nearest below the bounding-box diagonal of `points` (0 when
/// the diagonal is 0 or not finite): multiplied by 2^-k the points have a diagonal in [1, 2), and
/// every ratio, angle or linear part computed from them keeps its bits, while areas and volumes
/// of a mesh at 1e200 or 1e-200 neither overflow nor underflow. Use it to measure in unit scale.
int scale_exponent(const Eigen::MatrixXd& points);

}  // namespace sa
