#pragma once
// Distances from points to a triangle surface in space, for comparing two surfaces (a hex mesh's
// boundary against its input's).
//
//   SurfaceDistance surface(vertices, triangles);   // #V x 3, #F x 3
//   double d = surface.distance(point);              // to the closest point of any triangle
//
// The triangles are binned in a uniform grid of about one cell per triangle; a query visits the
// cells in growing shells around the point's and stops once no unvisited cell can be closer
// than the best triangle found. Exact up to rounding.

#include <Eigen/Core>
#include <vector>

#include "optim/types.h"

namespace sa {

/// The distance from `p` to triangle (a, b, c), degenerate ones included.
double point_triangle_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                               const Eigen::Vector3d& b, const Eigen::Vector3d& c);

class SurfaceDistance {
  public:
    /// `vertices` #V x 3, `triangles` #F x 3 (at least one). Throws InvalidArgumentError on bad
    /// shapes or indices.
    SurfaceDistance(const Eigen::MatrixXd& vertices, const Eigen::MatrixXi& triangles);

    /// The distance from `p` to the surface.
    double distance(const Eigen::Vector3d& p) const;

    /// The largest distance from the rows of `points` (#P x 3) to the surface; 0 for none.
    /// In parallel over the points.
    double max_distance(const Eigen::MatrixXd& points) const;

  private:
    Eigen::Vector3d triangle_corner(Index f, int k) const;
    Index cell_index(const Eigen::Vector3i& cell) const;

    Eigen::MatrixXd vertices_;
    Eigen::MatrixXi triangles_;
    Eigen::Vector3d origin_;
    double cell_ = 1.0;
    Eigen::Vector3i cells_;
    std::vector<Index> start_;    ///< per cell + 1: offsets into members_
    std::vector<Index> members_;  ///< triangles per cell
};

}  // namespace sa
