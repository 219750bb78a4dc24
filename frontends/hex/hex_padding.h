#pragma once
// A padding layer of hexes along the boundary (pillowing: Mitchell and Tautges 1995; the
// PolyCube hex meshers' padding, as in Gregson et al. 2011 and Fu et al. 2016): every boundary
// vertex v gets a copy v' at its place, which the boundary quads take instead of v, and every
// boundary quad (a, b, c, d) gets the hex (a, b, c, d, a', b', c', d') between the old boundary
// and the new one. The old boundary vertices move inward along the mean of their quads' inward
// normals, so that each quad's plane moves by `depth` times their mean boundary edge length (a
// box's corner along its diagonal; at most twice the depth).
//
// Why: extraction puts a hex at every PolyCube edge and corner with all four vertices of a
// corner on the boundary (the corner and its three neighbours along the boundary), so its shape
// is the input surface's there: where the PolyCube turns 90 degrees and the surface does not
// (robustPolycube S3's cylinder, cup's rim) the corner is flat or inverted, and no motion of
// the inner vertices changes it. After padding, every corner of every hex has a vertex off the
// boundary, and the layer takes the turn.
//
// The moved vertices may fold hexes (a thin part, a concave feature): the optimization
// (hex_optimization.h) untangles them. It is needed exactly where
// boundary_locked_inverted_corners() (hex_quality.h) finds a corner.

#include <vector>

#include "geometry/mesh/hex_mesh.h"

namespace sa {

struct HexPadding {
    HexMesh mesh;  ///< the padded mesh: the old vertices first, then the copies
    /// Per vertex of `mesh`: the vertex of the input it is or copies (the copies are the new
    /// boundary, where the old one was).
    std::vector<Index> source;
    Index added_hexes = 0;  ///< one per boundary quad
};

/// The padding above, `depth` > 0 (a fraction of the boundary edge length). Throws
/// InvalidArgumentError on a depth <= 0.
HexPadding pad_boundary(const HexMesh& mesh, double depth);

}  // namespace sa
