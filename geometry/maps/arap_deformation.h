#pragma once
// As-rigid-as-possible deformation with fixed handles (Sorkine and Alexa 2007's local/global
// iterations on simplices; the start of the paper's 5.4: "Our method starts with the ARAP result
// that contains inverted tetrahedrons"), Anderson-accelerated.
//
// It minimizes Eq. 6's least squares with a rotation per simplex,
//     Q(x, R) = sum_i sum_{edges (a, b) of s_i} |R_i (u_a - u_b) - (x_a - x_b)|^2,
// over the free vertex positions x and the rotations R_i (similarities with `similarity`: ASAP),
// the handles fixed at their targets. Each iteration fits R_i to the current simplices
// (geometry/maps/arap_local_step.h: the exact edge-fit local step) and solves for x with R fixed
// (geometry/maps/vertex_recovery.h: the Laplacian, factored once). Plain iteration never increases
// Q but creeps; the iterates are Anderson-accelerated (optim/anderson_acceleration.h, Peng et al.
// 2018), and an accelerated point that raises Q is replaced by the plain step. Nothing keeps
// simplices from inverting: that is what Simplex Assembly repairs afterwards. arap_deformation()
// starts from the handle groups' rotations interpolated through the mesh
// (geometry/maps/handle_rotation_start.h) when that start has the lower Q: from the rest shape with
// only the handles moved, a twist or a bend must creep in from the handles (the bar twisted by
// 180 degrees: 925 iterations, to a local minimum with 6 tetrahedra folded about the axis).
//
// It stops when the plain step from the last iterate x (a local and a global step, G(x)) would
// move no vertex by more than `tolerance` times the bounding-box diagonal of the start
// (converged: the fixed-point residual, the usual test of Anderson acceleration), after
// max_iterations, after max_time_seconds, or when the caller's after_iteration returns true.
//
// Where the fixed point has inverted simplices, the local step's
// rotation jumps as their two smallest singular values cross, G is not smooth there, and about
// a third of the accelerated points are rejected: such poses still take hundreds of iterations.

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "geometry/maps/vertex_recovery.h"
#include "geometry/mesh/rest_frames.h"

namespace sa {

/// One accepted iterate, for progress and for callers that keep their own best iterate.
struct ArapIterate {
    int iteration = 0;        ///< 1, 2, ...
    double energy = 0.0;      ///< Q at `positions` with the rotations fitted to them
    double max_move = 0.0;    ///< largest vertex move of this iteration, in position units
    bool accelerated = true;  ///< false when the plain step replaced a rejected accelerated one
    const Eigen::MatrixXd* positions = nullptr;  ///< #V x D, valid during the call
};

struct ArapOptions {
    int max_iterations = 1000;
    /// Converged when the plain step from the last iterate moves no vertex by more than
    /// tolerance * diagonal.
    double tolerance = 1e-9;
    /// Differences kept by the Anderson acceleration (Peng et al. use 5 to 10); 0 = plain.
    int anderson_history = 6;
    /// Similarities (ASAP) instead of rotations.
    bool similarity = false;
    /// arap_deformation() only: start from geometry/maps/handle_rotation_start.h (the handle
    /// groups' rotations interpolated through the mesh) when its Q is lower than that of the rest
    /// shape with the handles moved; false: always from the latter.
    bool rotation_start = true;
    double max_time_seconds = kInfinity;
    /// Called after every iteration; returning true stops the iterations there.
    std::function<bool(const ArapIterate&)> after_iteration;

    /// Throws InvalidArgumentError naming the first bad field and its value.
    void validate() const;
};

struct ArapResult {
    Eigen::MatrixXd positions;    ///< #V x D, the handles at their targets
    double initial_energy = 0.0;  ///< Q at the start (rotations fitted to it)
    double energy = 0.0;          ///< Q at `positions`
    int iterations = 0;
    int rejected = 0;  ///< accelerated points replaced by plain steps
    bool converged = false;
    std::string stop;  ///< why it stopped, in a few words
    double seconds = 0.0;
    /// arap_deformation() only: which start, "rest shape" or "handle rotations (G of H groups)".
    std::string start;
};

/// The iterations from `start` (#V x D; its rows at the fixed vertices of `recovery` are the
/// handle targets and stay there). `frames` and `recovery` belong to `mesh`.
template <int D>
ArapResult arap_iterations(const SimplicialMesh& mesh, const RestFrames<D>& frames,
                           const VertexRecovery<D>& recovery, const Eigen::MatrixXd& start,
                           const ArapOptions& options = {});

/// ARAP deformation of `mesh` (simplices of dimension D in D-space: planar triangles or
/// tetrahedra) from its rest shape with `handles` moved to `targets` (#handles x D), or from the
/// handle rotations' start (options.rotation_start). Throws
/// InvalidArgumentError on inconsistent sizes, a handle out of range or repeated, or a connected
/// component without a handle.
template <int D>
ArapResult arap_deformation(const SimplicialMesh& mesh, const std::vector<Index>& handles,
                            const Eigen::MatrixXd& targets, const ArapOptions& options = {});

}  // namespace sa
