#pragma once
// The quality of a hexahedral mesh (geometry/mesh/hex_mesh.h), from its vertex positions alone.
//
//   corner Jacobian  J_c = det[e_1, e_2, e_3] of corner c's three edges (kHexCornerEdges), in
//                    the positions' units cubed; > 0 at all eight corners: the hex is not
//                    inverted;
//   scaled Jacobian  min over the corners of det[e_1/|e_1|, e_2/|e_2|, e_3/|e_3|], in [-1, 1]:
//                    1 for a cuboid, <= 0 for a hex with an inverted or flat corner.
//
// The boundary is the set of hex faces that belong to one hex only. It is closed when each of
// its edges is shared by exactly two boundary faces (and no face by more than two hexes).

#include <array>
#include <vector>

#include "geometry/mesh/hex_mesh.h"

namespace sa {

/// The Jacobian of corner `c` (0..7) of hex `h`: det of its three edges (kHexCornerEdges).
double hex_corner_jacobian(const HexMesh& mesh, Index h, int c);

/// The scaled Jacobian of hex `h`; 0 when a corner has an edge of zero length.
double hex_scaled_jacobian(const HexMesh& mesh, Index h);

/// The smallest corner Jacobian of hex `h`.
double hex_min_corner_jacobian(const HexMesh& mesh, Index h);

/// The volume of hex `h` by kHexTetrahedra (signed; exact for planar faces).
double hex_volume(const HexMesh& mesh, Index h);

struct HexQuality {
    std::vector<double> scaled_jacobian;  ///< per hex
    Index inverted = 0;                   ///< hexes with a corner Jacobian <= 0
    double min_scaled_jacobian = 0.0, mean_scaled_jacobian = 0.0;
    /// Hexes per scaled-Jacobian bin: (-inf, 0], (0, 0.1], ..., (0.9, 1].
    std::array<Index, 11> histogram{};
    double volume = 0.0;  ///< sum of hex_volume()
};

/// Every hex's measures; the mean and the minimum are 0 for a mesh without hexes.
HexQuality hex_quality(const HexMesh& mesh);

struct HexBoundary {
    /// #Q x 4 boundary faces, each turning counter-clockwise seen from outside.
    Eigen::MatrixXi quads;
    std::vector<unsigned char> on_boundary;  ///< per vertex: in a boundary face
    Index faces_in_more_than_two_hexes = 0;
    /// Boundary edges not shared by exactly two boundary faces.
    Index open_edges = 0;
    bool closed() const { return faces_in_more_than_two_hexes == 0 && open_edges == 0; }
};

/// The boundary of `mesh`'s hexes, described above.
HexBoundary hex_boundary(const HexMesh& mesh);

/// The hex corners (a corner and its three neighbours) with all four vertices on the boundary
/// and a Jacobian <= 0: inverted or flat whatever the inner vertices do.
Index boundary_locked_inverted_corners(const HexMesh& mesh, const HexBoundary& boundary);

}  // namespace sa
