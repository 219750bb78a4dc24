#pragma once
// A hexahedral mesh from a tetrahedral one through its PolyCube map (issue 48), as explicit
// stages, each on what the one before it verified:
//
//   1. PolyCube      solve_polycube() (frontends/polycube/polycube_solve.h): a verified PolyCube
//                    map with free planes;
//   2. quantization  the planes onto an integer grid of cell size h (plane_quantization.h): h
//                    from the target hex count (PolyCube volume / count, cube root) or from a hex
//                    size in the input's units (scaled by the PolyCube's size against the input's);
//                    the corner planes of every PolyCube edge a cell apart;
//   3. PolyCube on the grid   solve_polycube_on_planes(): the same configuration with every plane
//                    held at its integer position (grid units), from the PolyCube with its planes
//                    moved there (grid_start.h); verified as a PolyCube map again;
//   4. extraction    every grid cell inside becomes a hex, mapped back to the input
//                    (hex_extraction.h);
//   5. padding       when a hex corner with all four vertices on the boundary is inverted or
//                    flat (no motion of the inner vertices repairs it), a layer of hexes along
//                    the boundary (hex_padding.h), after which every corner has an inner vertex;
//   6. optimization  the inner vertices moved to improve the worst corners, inverted hexes
//                    untangled first (hex_optimization.h), the boundary kept;
//   7. verification  verify_hex_mesh() on the hex mesh's positions (hex_verification.h).
//
// A stage whose input did not verify is not run; the outcome names the first that failed.
// Hex positions are in the input's frame and units.

#include <string>

#include "frontends/hex/hex_extraction.h"
#include "frontends/hex/hex_optimization.h"
#include "frontends/hex/hex_padding.h"
#include "frontends/hex/hex_verification.h"
#include "frontends/hex/plane_quantization.h"
#include "frontends/polycube/polycube_solve.h"

namespace sa {

struct HexMeshingOptions {
    /// The hex count aimed at (the grid's cells follow the PolyCube's shape: the count is near,
    /// not equal). Used when hex_size is 0.
    Index hexes = 10000;
    /// > 0: the cell size in the input's units, instead of `hexes`.
    double hex_size = 0.0;
    /// Both PolyCube solves (the second gets what the first left of max_time; the hex
    /// optimization what is left after that).
    PolycubeSolveOptions polycube;
    /// Stage 5: the depth of the padding layer, a fraction of the boundary edge length, when it
    /// is needed; 0: none. Where it is not needed it costs quality (robustPolycube B0, pente:
    /// the scaled Jacobian's minimum 0.71 and 0.57 without, 0.48 and 0.30 with).
    double padding = 0.5;
    bool optimize = true;  ///< stage 6
    int optimization_iterations = 100;
};

enum class HexOutcome {
    kVerified,            ///< every stage passed and so did verify_hex_mesh()
    kPolycubeFailed,      ///< stage 1's map did not verify
    kGridPolycubeFailed,  ///< stage 3's map did not verify
    kHexMeshNotVerified,  ///< the hex mesh has an inverted hex, an open boundary or no hex
};
std::string to_string(HexOutcome outcome);

struct HexMeshing {
    HexOutcome outcome = HexOutcome::kPolycubeFailed;
    PolycubeSolve polycube;  ///< stage 1
    PlaneQuantization quantization;
    PolycubeSolve grid_polycube;  ///< stage 3, in grid units (empty when not run)
    HexExtraction extraction;
    HexQuality extracted_quality;  ///< the hexes as extracted, before stages 5 and 6
    /// boundary_locked_inverted_corners() (hex_quality.h) after extraction
    Index locked_inverted_corners = 0;
    Index padding_hexes = 0;  ///< added by stage 5
    HexOptimization optimization;
    HexVerification verification;
    std::string message;  ///< the outcome in a sentence or two
    double polycube_seconds = 0.0, quantization_seconds = 0.0, grid_polycube_seconds = 0.0,
           extraction_seconds = 0.0, padding_seconds = 0.0, optimization_seconds = 0.0,
           verification_seconds = 0.0;
    bool success() const { return outcome == HexOutcome::kVerified; }
    /// The hex mesh (after stage 6), in the input's frame and units.
    const HexMesh& output() const { return optimization.mesh; }
};

/// Runs the stages above on `prepared`. Progress goes to `logger`. Bad options throw
/// InvalidArgumentError (hexes < 1, a hex size < 0 or not finite), and solve_polycube()'s errors
/// pass through.
HexMeshing hex_mesh_from_polycube(const PreparedPolycube& prepared,
                                  const HexMeshingOptions& options, const Logger& logger = {});

}  // namespace sa
