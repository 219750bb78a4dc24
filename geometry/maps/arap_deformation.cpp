#include "geometry/maps/arap_deformation.h"

#include <cmath>

#include "geometry/maps/arap_local_step.h"
#include "geometry/maps/handle_rotation_start.h"
#include "geometry/quality/map_quality.h"
#include "optim/anderson_acceleration.h"
#include "optim/errors.h"
#include "optim/stopwatch.h"

namespace sa {

namespace {

Eigen::VectorXd flatten(const Eigen::MatrixXd& m) {
    return Eigen::Map<const Eigen::VectorXd>(m.data(), m.size());
}

Eigen::MatrixXd unflatten(const Eigen::VectorXd& v, Eigen::Index rows) {
    return Eigen::Map<const Eigen::MatrixXd>(v.data(), rows, v.size() / rows);
}

}  // namespace

void ArapOptions::validate() const {
    auto fail = [](const std::string& what) { throw InvalidArgumentError("ArapOptions: " + what); };
    if (max_iterations < 0) fail("max_iterations = " + std::to_string(max_iterations) + " < 0");
    if (!(tolerance >= 0.0)) fail("tolerance = " + std::to_string(tolerance) + " must be >= 0");
    if (anderson_history < 0)
        fail("anderson_history = " + std::to_string(anderson_history) + " < 0");
    if (!(max_time_seconds > 0.0))
        fail("max_time_seconds = " + std::to_string(max_time_seconds) + " must be > 0");
}

template <int D>
ArapResult arap_iterations(const SimplicialMesh& mesh, const RestFrames<D>& frames,
                           const VertexRecovery<D>& recovery, const Eigen::MatrixXd& start,
                           const ArapOptions& options) {
    options.validate();
    if (start.rows() != mesh.num_vertices() || start.cols() != D) {
        throw InvalidArgumentError("arap_iterations: start is " + std::to_string(start.rows()) +
                                   " x " + std::to_string(start.cols()) + ", expected " +
                                   std::to_string(mesh.num_vertices()) + " x " + std::to_string(D));
    }
    const Stopwatch watch;
    const Eigen::Index rows = start.rows();
    const double limit = options.tolerance * bounding_box_diagonal(start);
    AndersonAcceleration anderson(std::max(options.anderson_history, 1));
    const bool accelerate = options.anderson_history > 0;

    ArapResult result;
    result.positions = start;
    std::vector<Mat<D>> M;
    std::vector<Mat<D>> A = linear_parts<D>(mesh, frames, result.positions);
    double previous = fit_rigid_parts<D>(frames, A, options.similarity, M);
    result.initial_energy = result.energy = previous;
    result.stop = "iteration limit";
    if (options.max_iterations == 0) return result;

    Eigen::MatrixXd plain = recovery.recover(M, start);
    Eigen::MatrixXd x =
        accelerate ? unflatten(anderson.next(flatten(result.positions), flatten(plain)), rows)
                   : plain;
    for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
        A = linear_parts<D>(mesh, frames, x);
        double energy = fit_rigid_parts<D>(frames, A, options.similarity, M);
        bool accelerated = accelerate;
        if (accelerate && !(energy <= previous)) {  // the accelerated point raised Q
            ++result.rejected;
            anderson.reset();
            x = plain;
            A = linear_parts<D>(mesh, frames, x);
            energy = fit_rigid_parts<D>(frames, A, options.similarity, M);
            accelerated = false;
        }
        const double move = (x - result.positions).cwiseAbs().maxCoeff();
        result.positions = x;
        result.energy = previous = energy;
        result.iterations = iteration;
        ArapIterate iterate;
        iterate.iteration = iteration;
        iterate.energy = energy;
        iterate.max_move = move;
        iterate.accelerated = accelerated;
        iterate.positions = &result.positions;
        if (options.after_iteration && options.after_iteration(iterate)) {
            result.stop = "stopped by the caller";
            break;
        }
        if (watch.seconds() >= options.max_time_seconds) {
            result.stop = "time limit";
            break;
        }
        if (iteration == options.max_iterations) break;
        plain = recovery.recover(M, start);
        // The fixed-point residual |G(x) - x|: an accelerated iterate's own move says little (it
        // may land close to the last one by chance, or oscillate about the fixed point).
        if ((plain - x).cwiseAbs().maxCoeff() <= limit) {
            result.converged = true;
            result.stop = "converged";
            break;
        }
        x = accelerate ? unflatten(anderson.next(flatten(x), flatten(plain)), rows) : plain;
    }
    result.seconds = watch.seconds();
    return result;
}

template <int D>
ArapResult arap_deformation(const SimplicialMesh& mesh, const std::vector<Index>& handles,
                            const Eigen::MatrixXd& targets, const ArapOptions& options) {
    if (mesh.simplex_dimension() != D || mesh.ambient_dimension() != D) {
        throw InvalidArgumentError("arap_deformation: expected simplices of dimension " +
                                   std::to_string(D) + " in " + std::to_string(D) +
                                   "D, got dimension " + std::to_string(mesh.simplex_dimension()) +
                                   " in " + std::to_string(mesh.ambient_dimension()) + "D");
    }
    if (targets.rows() != static_cast<Eigen::Index>(handles.size()) || targets.cols() != D) {
        throw InvalidArgumentError("arap_deformation: " + std::to_string(handles.size()) +
                                   " handles but targets are " + std::to_string(targets.rows()) +
                                   " x " + std::to_string(targets.cols()));
    }
    std::vector<unsigned char> fixed(mesh.num_vertices(), 0);
    Eigen::MatrixXd start = mesh.vertices;
    for (std::size_t k = 0; k < handles.size(); ++k) {
        const Index h = handles[k];
        if (h < 0 || h >= mesh.num_vertices()) {
            throw InvalidArgumentError("arap_deformation: handle vertex " + std::to_string(h) +
                                       " outside [0, " + std::to_string(mesh.num_vertices()) + ")");
        }
        if (fixed[h]) {
            throw InvalidArgumentError("arap_deformation: handle vertex " + std::to_string(h) +
                                       " listed twice");
        }
        fixed[h] = 1;
        start.row(h) = targets.row(k);
    }
    const RestFrames<D> frames = rest_frames<D>(mesh);
    const VertexRecovery<D> recovery(mesh, frames, std::move(fixed));
    std::string description = "rest shape";
    if (options.rotation_start && !handles.empty()) {
        HandleRotationStart rotated = handle_rotation_start<D>(mesh, frames, recovery, start);
        std::vector<Mat<D>> M;
        const double q_rest =
            fit_rigid_parts<D>(frames, linear_parts<D>(mesh, frames, start), options.similarity, M);
        const double q_rotated = fit_rigid_parts<D>(
            frames, linear_parts<D>(mesh, frames, rotated.positions), options.similarity, M);
        if (q_rotated < q_rest) {
            start = std::move(rotated.positions);
            description = "handle rotations (" + std::to_string(rotated.rotation_groups) + " of " +
                          std::to_string(rotated.groups) + " groups)";
        }
    }
    ArapResult result = arap_iterations<D>(mesh, frames, recovery, start, options);
    result.start = description;
    return result;
}

template ArapResult arap_iterations<2>(const SimplicialMesh&, const RestFrames<2>&,
                                       const VertexRecovery<2>&, const Eigen::MatrixXd&,
                                       const ArapOptions&);
template ArapResult arap_iterations<3>(const SimplicialMesh&, const RestFrames<3>&,
                                       const VertexRecovery<3>&, const Eigen::MatrixXd&,
                                       const ArapOptions&);
template ArapResult arap_deformation<2>(const SimplicialMesh&, const std::vector<Index>&,
                                        const Eigen::MatrixXd&, const ArapOptions&);
template ArapResult arap_deformation<3>(const SimplicialMesh&, const std::vector<Index>&,
                                        const Eigen::MatrixXd&, const ArapOptions&);

}  // namespace sa
