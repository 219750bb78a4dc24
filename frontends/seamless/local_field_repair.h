#pragma once
// The paper's repair of a frame field whose integrable version folds (5.2, "Global seamless
// parameterizations": 7 of its 80 models). Where the input field is not smooth around long, slim
// triangles, Simplex Assembly stops with an edge curl near 1e-7 instead of 1e-18 and the Poisson
// map of phi' has a few foldovers. The paper smooths "the positions of vertices in these local
// regions by several steps of Laplacian smoothing", projects the frame field onto the modified
// faces, and runs Simplex Assembly again.
//
// Here: the region is the faces the result folds (inverted or degenerate), grown by `rings` rings;
// its vertices that are neither on the region's border nor on the mesh boundary take `steps`
// steps of uniform Laplacian smoothing (x <- x + (mean of the neighbours - x) / 2). The input
// field phi, as vectors in space, is projected onto the smoothed faces and the whole pipeline
// (seamless_parameterization.h) runs on the smoothed surface: the same matchings follow from the
// same field, so the singularities stay. The smoothed positions serve the field only: the result's
// (u, v) per corner is attached to the input surface, whose positions are kept, and verified there
// (foldovers and degenerate faces from the (u, v), seam mismatch, cone points against the input
// field's singularities). Attempts grow: (2 rings, 5 steps), (4, 10), (8, 20); the first verified
// one is kept.

#include <string>
#include <vector>

#include "optim/logger.h"
#include "optim/types.h"

namespace sa {

struct SeamlessResult;
struct SeamlessOptions;

struct FieldRepairAttempt {
    int rings = 0;
    int smoothing_steps = 0;  ///< Laplacian smoothing steps
    Index region_faces = 0;
    Index vertices_moved = 0;
    double largest_move = 0.0;  ///< over the bounding-box diagonal of the surface
    Index inverted = 0;         ///< faces of the result, verified on the input surface
    Index degenerate = 0;
    bool assembled = false;
    bool singularities_kept = false;
    bool success = false;
    double time = 0.0;
};

struct FieldRepair {
    bool ran = false;
    Index folded_faces = 0;  ///< inverted or degenerate faces of the result it repairs
    std::vector<FieldRepairAttempt> attempts;
    bool success = false;
    /// One sentence: what was done and how it ended.
    std::string describe() const;
};

/// Repairs `failed` (a result of seamless_parameterization on `failed.surface`, not verified).
/// Returns the repaired result (its `repair` filled, success true) when an attempt verifies,
/// otherwise `failed` with `repair` filled and its message extended.
SeamlessResult repair_folded_field(const SeamlessResult& failed, const SeamlessOptions& options,
                                   const Logger& logger);

}  // namespace sa
