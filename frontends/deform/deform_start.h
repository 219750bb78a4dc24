#pragma once
// The start of deformation posing (the paper's 5.4): an ARAP deformation of the rest shape with
// the handles fixed at their targets (geometry/maps/arap_deformation.h, Anderson-accelerated), and
// how good it is: inverted and degenerate simplices and the conformal, isometric and volumetric
// distortion of the others (geometry/quality/map_quality.h). It may invert simplices; Simplex
// Assembly starts from it (E_m = sum_i |A_i - A_i^0|^2 to its linear parts A_i^0) and repairs them.

#include <Eigen/Core>
#include <string>

#include "frontends/deform/handle_targets.h"
#include "geometry/maps/arap_deformation.h"
#include "geometry/quality/map_quality.h"
#include "optim/logger.h"

namespace sa {

struct DeformStart {
    Eigen::MatrixXd positions;  ///< #V x d, the handles at their targets
    MapQuality quality;         ///< of the map rest -> positions, per simplex included
    double handle_error = 0.0;  ///< largest |x_h - target_h| (zero: the handles are fixed)
    /// The iterations: count, Q before and after, why they stopped, their time (positions are
    /// moved to `positions` above).
    ArapResult arap;
    double seconds = 0.0;  ///< all of it: frames, the factorization, iterations, measuring
};

/// ARAP from `mesh`'s rest shape (planar triangles or tetrahedra: simplices of dimension d in
/// d-space) with the handles at their targets. `logger` gets a row every 10 iterations and at
/// the end. Throws InvalidArgumentError for a triangle mesh in space (a surface has no
/// deformation of this kind), inconsistent handles and targets, or a connected component without
/// a handle.
DeformStart deform_start(const SimplicialMesh& mesh, const HandleTargets& handle_targets,
                         const ArapOptions& options = {}, const Logger& logger = {});

/// One line: iterations and why they stopped, inverted and degenerate simplices, the distortion
/// (max / mean) and the time.
std::string describe(const DeformStart& start);

}  // namespace sa
