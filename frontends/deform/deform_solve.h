#pragma once
// Deformation posing (the paper's 5.4): from the rest shape and the handles' targets alone, an
// ARAP start (deform_start.h), then Simplex Assembly configured as
//   E_m = mu sum_i |A_i - A_i^0|^2     unit weights, A_i^0 the start's linear parts
//                                      (energies/difference_energy.h);
//   E_C = the conformal barrier (the driver's built-in, bound K1) and a volumetric barrier
//         (a DistortionBarrier term, bound K2), both at once;
//   the handles at their targets (Eq. 8), the disassembly's projection options.initialization;
// and, with options.optimal_bound, the optimal-bound rounds of 5.1 lowering both bounds together
// (optimal_bound.h: each round takes the largest d^c and the largest d^vol reached as its next
// bounds). Without it a single round with the given bounds (inf: an unbounded barrier, which
// still keeps every simplex positively oriented).
//
// The result is verified on the output positions by the driver (no inverted or degenerate
// simplex, no branched vertex or edge, handles at their targets, every bound held).

#include "frontends/deform/deform_options.h"
#include "frontends/deform/deform_start.h"
#include "frontends/simplex_assembly/optimal_bound.h"

namespace sa {

/// The name of the volumetric barrier among the problem's energies (its BoundCheck in the
/// verification and the rounds).
inline constexpr const char* kVolumetricBarrierName = "volumetric";

struct DeformResult {
    DeformStart start;
    /// The problem Simplex Assembly solved: the rest mesh, the start as initial map and
    /// reference, the handles and targets, the E_m and volumetric terms.
    MappingProblem problem;
    SimplexAssemblyOptions solver;  ///< the options of its first round
    /// Every round (one without options.optimal_bound); solve.solve is the result.
    OptimalBound solve;
    double seconds = 0.0;  ///< start and solve
    /// Verified, and within both bounds (those given, or those the last round kept).
    bool success() const {
        return solve.verified && solve.solve.success && solve.solve.verification.within_bound();
    }
    /// Empty, or one sentence when the result's mean isometric distortion is more than
    /// kDistortionWarningRatio times the ARAP start's: the solve pulls towards the start (E_m),
    /// so a result that far from it had folds repaired by squashing or stretching simplices
    /// that the vertex stage could not bring back. Verified maps are still a success.
    std::string distortion_warning() const;
};

/// The ratio of mean isometric distortions (result over ARAP start) above which
/// DeformResult::distortion_warning() speaks.
inline constexpr double kDistortionWarningRatio = 2.0;

/// The mapping problem and solver options of the solve from a computed start (exposed for tests
/// and for users who bring their own start).
MappingProblem deform_problem(const SimplicialMesh& mesh, const HandleTargets& handle_targets,
                              const Eigen::MatrixXd& start, const DeformOptions& options);
SimplexAssemblyOptions deform_solver_options(const DeformOptions& options);

/// The whole pose. `observer.logger` receives the start's rows and the solve's. Throws
/// InvalidArgumentError or InputError for bad input (deform_start()); numerical outcomes are in
/// the result.
DeformResult deform(const SimplicialMesh& mesh, const HandleTargets& handle_targets,
                    const DeformOptions& options, const SimplexAssemblyObserver& observer = {});

}  // namespace sa
