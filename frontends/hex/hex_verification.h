#pragma once
// The checks of a hex mesh made from a tetrahedral one (issue 48), measured on the hex mesh's
// vertex positions alone:
//   - it has hexes and none is inverted: all eight corner Jacobians > 0 (hex_quality.h);
//   - its boundary is closed: every boundary edge in exactly two boundary faces.
// A mesh passes when both hold. Reported beside them: the scaled Jacobian (min, mean, histogram),
// the distances between the hex boundary and the input's boundary surface in both directions
// (the largest distance from a boundary vertex of one to the other surface; quads split along
// a diagonal), as fractions of the input's bounding-box diagonal, and the ratio of the volumes.

#include <string>

#include "geometry/quality/hex_quality.h"

namespace sa {

struct HexVerification {
    Index hexes = 0, vertices = 0;
    HexQuality quality;
    Index boundary_faces = 0;
    Index open_boundary_edges = 0;           ///< HexBoundary::open_edges
    Index faces_in_more_than_two_hexes = 0;  ///< HexBoundary
    double diagonal = 0.0;                   ///< the input's bounding-box diagonal
    /// Largest distance from a hex boundary vertex to the input's boundary, and from an input
    /// boundary vertex to the hex boundary, / diagonal.
    double distance_to_input = 0.0, distance_from_input = 0.0;
    double volume_ratio = 0.0;  ///< hex volume / input volume
    bool passed = false;
    std::string summary;  ///< one sentence: what passed or failed, with the figures
};

/// Verifies `hexes` against the input: its vertices `input_vertices` (#V x 3, the hexes' units),
/// its boundary triangles `input_boundary` (#B x 3) and its volume `input_volume` > 0.
HexVerification verify_hex_mesh(const HexMesh& hexes, const Eigen::MatrixXd& input_vertices,
                                const Eigen::MatrixXi& input_boundary, double input_volume);

}  // namespace sa
