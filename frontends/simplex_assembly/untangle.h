#pragma once
// Untangling in vertex variables by a regularized barrier (Garanzha et al. 2021, "Foldover-free
// maps in 50 lines of code"; energies/untangling_energy.h): Newton on the positions of the free
// vertices (the fixed ones stay where they are) of
//     sum_i w_i f_eps(A_i),
// the simplices whose vertices are all fixed left out (they cannot change). f_eps is finite for
// inverted simplices, so the start may be any map. After every Newton step eps follows the
// paper's rule: with sigma = max(1 - E / E_prev, 0.1) (the step's relative decrease) and
// mu = (1 - sigma) chi(min det A, eps), eps becomes 2 sqrt(mu (mu - min det A)) while min det A
// < mu (so that chi(min det A) shrinks by the factor 1 - sigma), and 1e-10 afterwards (f_eps is
// then the plain distortion, infinite on inverted simplices). The minimizers for decreasing eps
// are untangled when an untangled map exists (the paper's argument; in practice on the Locally
// Injective Mappings benchmark's 3D problems, and here on ../shared/data/tlc/armadillo-598).
// It is the engine (engine.h) in its vertex layout with f_eps as the only per-simplex energy and
// no assembly term; the eps rule and the stopping test run in the engine's hook.
//
// Used as the start of the submesh mode when the initial map and the local/global iterations
// leave bad simplices (submesh_start.h): the Simplex Assembly barrier E_C needs a feasible start,
// this energy does not, and its growth (|A|^2 / det^(2/D), no exponential) lets the simplices
// that a fixed boundary forces to extreme distortion coexist with the rest.

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "frontends/simplex_assembly/stage_trace.h"
#include "geometry/mesh/rest_frames.h"
#include "optim/hessian_projection.h"
#include "optim/linear_solver.h"
#include "optim/logger.h"
#include "optim/newton_summary.h"

namespace sa {

struct UntangleOptions {
    /// Stop at the first iterate where every simplex with a free vertex has det A > 0 and that
    /// `accept` takes (any, when `accept` is empty); otherwise, or when none is taken, go on until
    /// that holds and a step changes the energy by less than energy_tolerance (relative) at the
    /// final eps.
    bool until_valid = true;
    /// Receives the positions (#V x D) of an untangled iterate.
    std::function<bool(const Eigen::MatrixXd&)> accept;
    /// Single coordinates that keep their value besides the fixed vertices: empty, or D #V flags,
    /// coordinate c of vertex v at D v + c (a vertex sliding on a plane keeps the coordinate along
    /// the plane's normal: PolyCube). A vertex with some coordinates fixed still moves.
    std::vector<unsigned char> fixed_coordinates;
    /// Single coordinates that are one variable (SimplexAssemblyEngine::vertex_positions): empty,
    /// or D #V entries, coordinate D v + c sharing the variable of coordinate
    /// shared_coordinates[D v + c]. A PolyCube plane's vertices share the coordinate along its
    /// normal, so the plane moves as one. Shared coordinates start at their mean; fixing one
    /// (fixed_coordinates) fixes them all.
    std::vector<Index> shared_coordinates;
    double energy_tolerance = 1e-5;
    int max_iterations = 500;
    double max_time_seconds = kInfinity;
    ProjectionMode projection = ProjectionMode::kClamp;
    double projection_epsilon = 1e-8;
    LinearSolverType linear_solver = LinearSolverType::kAuto;
    int num_threads = 0;
};

struct UntangleResult {
    Eigen::MatrixXd positions;  ///< #V x D: the last untangled iterate, or the last one
    bool untangled = false;     ///< every simplex with a free vertex has det A > 0
    Index inverted = 0;         ///< simplices with a free vertex and det A <= 0 in `positions`
    double min_det = 0.0;       ///< smallest det A over those simplices
    double epsilon = 0.0;       ///< eps at the end
    int iterations = 0;         ///< Newton steps
    UntangleOutcome outcome = UntangleOutcome::kNothingFree;
    AssemblyStop stop = AssemblyStop::kConverged;  ///< the engine's reason, when Newton ran
    NewtonSummary newton;
};

/// `start` #V x D (any map: inverted simplices allowed); `fixed` flags the vertices that keep
/// their positions (each connected part needs one, or its rigid motions are left to the
/// solver's regularization). Positions in the caller's units; A_i against `frames`.
template <int D>
UntangleResult untangle(const SimplicialMesh& mesh, const RestFrames<D>& frames,
                        const Eigen::MatrixXd& start, const std::vector<unsigned char>& fixed,
                        const UntangleOptions& options, const Logger& logger = {});

}  // namespace sa
