#pragma once
// Each simplex's rest shape in a frame of its own, with the frame's origin at the simplex's
// centroid (from a vertex instead, translations couple strongly to A and line searches stall).
//
// D is the simplex dimension. Triangles in the plane and tetrahedra keep the mesh's axes;
// triangles in space get an orthonormal frame in their own plane (x along the first edge), in
// which they are positively oriented. A map sends a rest point u (in the frame) to A u + T.

#include <Eigen/Core>
#include <vector>

#include "geometry/mesh/simplicial_mesh.h"

namespace sa {

template <int D>
struct RestFrames {
    /// Rest corners in the frame, one column per vertex of the simplex (origin at the centroid).
    std::vector<Eigen::Matrix<double, D, D + 1>> corners;
    /// Inverse of the rest edge matrix [c_1 - c_0 | ... | c_D - c_0].
    std::vector<Mat<D>> edge_inverse;
    /// Unsigned rest volume (area for triangles).
    std::vector<double> volume;
    /// Triangles in space only: the frame's axes (3 x 2, orthonormal columns) per triangle.
    std::vector<Eigen::Matrix<double, 3, 2>> axes;

    Index size() const { return static_cast<Index>(corners.size()); }
    /// The rest corner of simplex s at local vertex k (0..D).
    Vec<D> corner(Index s, int k) const { return corners[s].col(k); }
};

/// Frames of every simplex of `mesh` (D must equal mesh.simplex_dimension()).
template <int D>
RestFrames<D> rest_frames(const SimplicialMesh& mesh);

/// The linear part of the affine map that takes simplex s's rest corners to `mapped`
/// (D x (D + 1), one column per corner): A = [m_1 - m_0 | ...] E^-1.
template <int D>
Mat<D> linear_part(const RestFrames<D>& frames, Index s,
                   const Eigen::Matrix<double, D, D + 1>& mapped) {
    Mat<D> edges;
    for (int k = 0; k < D; ++k) edges.col(k) = mapped.col(k + 1) - mapped.col(0);
    return edges * frames.edge_inverse[s];
}

}  // namespace sa
