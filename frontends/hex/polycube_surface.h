#pragma once
// The boundary of a quantized PolyCube map and its map back to the rest surface: where the hex
// mesh's boundary vertices slide (hex_optimization.h).
//
//   grid   #V x 3, the PolyCube map in grid units (plane_quantization.h): every boundary triangle
//          lies on a plane x_a = k, k an integer, a its axis;
//   rest   #V x 3, the rest positions (where the hexes are built).
//
// A point of the PolyCube's boundary is located on one plane (axis a, the point's coordinate a
// rounded): among the boundary triangles on that plane, the one containing the point in the
// plane's two other coordinates (barycentric coordinates >= -1e-9, the deepest when several do).
// Its rest position is the same barycentric combination of the triangle's rest vertices: on the
// rest boundary, and on the rest's feature curve when the point is on a PolyCube edge. The
// triangles of a plane are binned by unit cell, so a location costs a few triangle tests.

#include <Eigen/Core>
#include <optional>
#include <unordered_map>
#include <vector>

#include "optim/types.h"

namespace sa {

struct SurfacePoint {
    Index triangle = -1;
    Eigen::Vector3d grid = Eigen::Vector3d::Zero();  ///< the point in grid units
    Eigen::Vector3d rest = Eigen::Vector3d::Zero();  ///< the point on the rest boundary
    /// d rest / d(grid coordinates): columns along the plane's two in-plane axes are the
    /// triangle's affine map, the column along the plane's axis is zero.
    Eigen::Matrix3d jacobian = Eigen::Matrix3d::Zero();
};

class PolycubeSurface {
  public:
    /// The surface of `triangles` (#B x 3, the boundary triangles, indices into both position
    /// arrays). A triangle that is not on one integer plane (spread over 1e-6 along every axis)
    /// is left out: the map is not quantized there.
    PolycubeSurface(const Eigen::MatrixXi& triangles, const Eigen::MatrixXd& grid,
                    const Eigen::MatrixXd& rest);

    /// The point `grid_point` located on the plane of axis `axis` at its rounded coordinate, or
    /// nothing when no triangle of that plane contains it.
    std::optional<SurfacePoint> locate(int axis, const Eigen::Vector3d& grid_point) const;

    /// The point of the plane of axis `axis` (at near_grid's rounded coordinate) closest in rest
    /// space to `rest_point`, among the triangles binned within `radius` cells of `near_grid`;
    /// with `line_axis` >= 0, the closest point of the PolyCube edge where that plane meets the
    /// plane of axis `line_axis` at near_grid's rounded coordinate (the triangle sides on both).
    /// Nothing when no candidate is found. This is how a point moved on the rest surface's
    /// tangent plane returns to the surface: exact on a flat face, whatever the map's distortion.
    std::optional<SurfacePoint> closest(int axis, const Eigen::Vector3d& near_grid,
                                        const Eigen::Vector3d& rest_point, int line_axis,
                                        double radius) const;

    Index triangles_left_out() const { return left_out_; }

  private:
    /// The point with barycentric `weights` in triangle t, its tangent map at `axis`'s plane.
    SurfacePoint point_in(Index t, int axis, const Eigen::Vector3d& weights) const;
    std::uint64_t bin(int axis, long plane, long i, long j) const;

    Eigen::MatrixXi triangles_;
    Eigen::MatrixXd grid_, rest_;
    std::unordered_map<std::uint64_t, std::vector<Index>> bins_;
    Index left_out_ = 0;
};

}  // namespace sa
