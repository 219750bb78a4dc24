#include "frontends/simplex_assembly/simplex_assembly.h"

#include <algorithm>
#include <cstdio>
#include <set>
#include <sstream>

#include "energies/distortion.h"
#include "frontends/simplex_assembly/assembly_problem.h"
#include "frontends/simplex_assembly/vertex_polish.h"
#include "geometry/disassembly.h"
#include "geometry/mesh_topology.h"
#include "geometry/rest_frames.h"
#include "geometry/translation_gluing.h"
#include "geometry/vertex_recovery.h"
#include "optim/errors.h"
#include "optim/newton_solver.h"
#include "optim/stopwatch.h"

namespace sa {

std::string Verification::describe() const {
    std::ostringstream out;
    out << "verified from the output positions: " << inverted << " of " << simplices
        << " simplices inverted, " << degenerate << " degenerate";
    if (handles > 0) {
        out << ", largest handle error " << handle_error << " (tolerance " << handle_tolerance
            << ", " << handles << " handles)";
    }
    if (bound < kInfinity) {
        out << ", largest distortion " << max_distortion << (within_bound() ? " <= " : " > ")
            << "bound " << bound;
    }
    return out.str();
}

namespace {

void check_input(const MappingProblem& p, int d) {
    const std::string& src = p.source;
    if (p.initial.rows() != p.mesh.num_vertices()) {
        throw InputError(src + ": the initial map has " + std::to_string(p.initial.rows()) +
                         " vertices, the rest mesh " + std::to_string(p.mesh.num_vertices()));
    }
    if (p.initial.cols() < d) {
        throw InputError(src + ": the initial map has " + std::to_string(p.initial.cols()) +
                         " coordinates per vertex, a map of " +
                         (d == 2 ? "triangles" : "tetrahedra") + " needs " + std::to_string(d));
    }
    if (!p.initial.leftCols(d).allFinite())
        throw InputError(src + ": the initial map has a non-finite coordinate");
    std::set<Index> seen;
    for (Index h : p.handles) {
        if (h < 0 || h >= p.mesh.num_vertices()) {
            throw InputError(src + ": handle vertex " + std::to_string(h) + " outside [0, " +
                             std::to_string(p.mesh.num_vertices()) + ")");
        }
        if (!seen.insert(h).second)
            throw InputError(src + ": handle vertex " + std::to_string(h) + " is listed twice");
    }
    if (p.targets.size() > 0 &&
        (p.targets.rows() != Index(p.handles.size()) || p.targets.cols() < d)) {
        throw InputError(src + ": " + std::to_string(p.targets.rows()) + " handle targets for " +
                         std::to_string(p.handles.size()) + " handles");
    }
}

template <int D>
SimplexAssemblyResult run(const MappingProblem& input, const SimplexAssemblyOptions& options,
                          const SimplexAssemblyObserver& observer) {
    Stopwatch total, stage;
    SimplexAssemblyResult result;
    const SimplicialMesh& original = input.mesh;
    validate_mesh(original, input.source);
    check_input(input, D);
    const MeshTopology topology = mesh_topology(original, input.source);
    for (Index h : input.handles) {
        if (!topology.used_vertex[h]) {
            throw InputError(input.source + ": handle vertex " + std::to_string(h) +
                             " belongs to no simplex");
        }
    }
    const Index n = original.num_simplices();
    const Eigen::MatrixXd initial_map = input.initial.leftCols(D);
    Eigen::MatrixXd target_rows(input.handles.size(), D);
    for (std::size_t k = 0; k < input.handles.size(); ++k) {
        if (input.targets.size() > 0) {
            target_rows.row(k) = input.targets.row(k).head(D);
        } else {
            target_rows.row(k) = initial_map.row(input.handles[k]);
        }
    }

    // 1. Normalize by the rest diagonal; each side centred on its own bounding box.
    const double scale = 1.0 / bounding_box_diagonal(original.vertices);
    const Eigen::RowVectorXd rest_center =
        0.5 * (original.vertices.colwise().minCoeff() + original.vertices.colwise().maxCoeff());
    const Eigen::RowVectorXd map_center =
        0.5 * (initial_map.colwise().minCoeff() + initial_map.colwise().maxCoeff());
    SimplicialMesh mesh = original;
    mesh.vertices = (original.vertices.rowwise() - rest_center) * scale;
    const Eigen::MatrixXd start = (initial_map.rowwise() - map_center) * scale;
    const RestFrames<D> frames = rest_frames<D>(mesh);
    result.times.setup += stage.lap();

    // 2. Disassembly.
    AssemblyInput<D> in;
    in.mesh = &mesh;
    in.topology = &topology;
    in.frames = &frames;
    in.reference_linear = linear_parts<D>(mesh, frames, start);
    result.initial_quality = map_quality<D>(in.reference_linear, frames.volume);
    in.start_linear = in.reference_linear;
    project_linear_parts<D>(in.start_linear, options.effective_initialization(), options.seed);
    in.start_translation.resize(n);
    for (Index s = 0; s < n; ++s) {
        Vec<D> centroid = Vec<D>::Zero();
        for (int k = 0; k <= D; ++k) centroid += start.row(original.simplices(s, k)).transpose();
        in.start_translation[s] = centroid / double(D + 1);
    }
    result.times.disassembly += stage.lap();

    // Handles, targets and an anchor for every connected part without a handle.
    in.handles = input.handles;
    for (Index k = 0; k < target_rows.rows(); ++k) {
        in.targets.push_back(((target_rows.row(k) - map_center) * scale).transpose());
    }
    Index components = 0;
    const std::vector<Index> component = topology.simplex_components(&components);
    std::vector<unsigned char> has_handle(components, 0);
    for (Index h : input.handles)
        has_handle[component[topology.simplices_of_vertex[topology.vertex_begin[h]]]] = 1;
    std::vector<Index> anchor(components, -1);
    for (Index s = 0; s < n; ++s) {
        const Index c = component[s];
        if (has_handle[c]) continue;
        // The least distorted non-inverted simplex of the initial map (the first one if none is).
        const SimplexQuality& q = result.initial_quality.per_simplex[s];
        if (anchor[c] < 0) {
            anchor[c] = s;
            continue;
        }
        const SimplexQuality& best = result.initial_quality.per_simplex[anchor[c]];
        const bool usable = !q.inverted && !q.degenerate,
                   best_usable = !best.inverted && !best.degenerate;
        if ((usable && !best_usable) || (usable == best_usable && q.conformal < best.conformal))
            anchor[c] = s;
    }
    for (Index c = 0; c < components; ++c) {
        if (anchor[c] >= 0) in.anchored_simplices.push_back(anchor[c]);
    }
    result.num_anchored_simplices = static_cast<Index>(in.anchored_simplices.size());

    AssemblyProblem<D> assembly(in, options);
    Problem& problem = assembly.problem();
    result.num_variables = problem.num_variables();
    result.num_translation_simplices = assembly.num_translation_simplices();
    result.num_tree_edges = assembly.num_tree_edges();
    result.times.setup += stage.lap();

    // 3. Assembly: Newton with the lambda schedule and termination rule of section 4.4.
    auto corners_of = [&](const Eigen::VectorXd& x) {
        const std::vector<Mat<D>> A = assembly.linear_parts(x);
        const std::vector<Vec<D>> T = glue_translations<D>(
            mesh, topology, frames, A, assembly.known_translations(x), in.start_translation);
        Eigen::MatrixXd corners((D + 1) * n, D);
        for (Index s = 0; s < n; ++s) {
            for (int k = 0; k <= D; ++k) {
                corners.row((D + 1) * s + k) =
                    (A[s] * frames.corner(s, k) + T[s]).transpose() / scale + map_center;
            }
        }
        return corners;
    };
    double lambda = options.lambda_min;
    auto set_lambda = [&](double value) {
        lambda = value;
        for (TermId t : assembly.assembly_terms()) problem.set_weight(t, lambda);
        if (assembly.shifted_translation_block() >= 0) {
            problem.set_hessian_shift(assembly.shifted_translation_block(),
                                      options.translation_shift * lambda);
        }
    };
    set_lambda(lambda);
    log_line(observer.logger, "iter      energy   assembly     lambda      step  ls     time");
    NewtonOptions newton;
    newton.max_iterations = options.max_iterations;
    newton.max_time_seconds = options.max_time_seconds;
    newton.gradient_tolerance = newton.decrement_tolerance = newton.function_tolerance = 0.0;
    newton.projection = options.projection;
    newton.projection_epsilon = options.projection_epsilon;
    newton.linear_solver = options.linear_solver;
    newton.num_threads = options.num_threads;
    double last_assembly = kInfinity;
    newton.callbacks.push_back([&](const IterationContext& c) {
        double assembly_value = 0.0;
        for (TermId t : assembly.assembly_terms()) assembly_value += c.term_values[t];
        last_assembly = assembly_value;
        AssemblyRecord row;
        row.iteration = c.record.iteration;
        row.energy = c.record.energy;
        row.assembly = assembly_value;
        row.barrier = c.term_values[assembly.simplex_term()];
        row.lambda = lambda;
        row.step = c.record.step_length;
        row.line_search_trials = c.record.line_search_trials;
        row.time = c.record.cumulative_time;
        result.iterations.push_back(row);
        char line[160];
        std::snprintf(line, sizeof line, "%4d  %10.4e  %9.3e  %9.3e  %8.2e  %2d  %6.2fs",
                      row.iteration, row.energy, row.assembly, row.lambda, std::max(row.step, 0.0),
                      std::max(row.line_search_trials, 0), row.time);
        log_line(observer.logger, line);
        if (observer.snapshot) observer.snapshot(row.iteration, corners_of(c.problem.variables()));
        if (row.iteration > 0 && assembly_value < options.assembly_tolerance) {
            if (options.polish) return CallbackResult::kStopSuccess;  // vertex variables take over
            const double before = c.record.energy + c.record.energy_change;
            if (c.record.energy_change <= options.energy_tolerance * std::abs(before))
                return CallbackResult::kStopSuccess;
        }
        const double ratio = assembly_value > 0.0 ? row.barrier / assembly_value : kInfinity;
        set_lambda(std::min(options.lambda_min * std::max(ratio, 1.0), options.lambda_max));
        return CallbackResult::kContinue;
    });
    result.newton = solve(problem, newton);
    result.final_lambda = lambda;
    result.final_assembly = last_assembly;
    result.assembled = last_assembly < options.assembly_tolerance;
    result.times.optimization += stage.lap();

    // 4. Recovery: translations by gluing, positions by Eq. 6 with the handles at their targets.
    const Eigen::VectorXd& x = problem.variables();
    const std::vector<Mat<D>> A = assembly.linear_parts(x);
    const std::vector<Vec<D>> T = glue_translations<D>(
        mesh, topology, frames, A, assembly.known_translations(x), in.start_translation);
    Eigen::MatrixXd pinned = start;
    std::vector<unsigned char> fixed(original.num_vertices(), 0);
    for (std::size_t k = 0; k < in.handles.size(); ++k) {
        pinned.row(in.handles[k]) = in.targets[k].transpose();
        fixed[in.handles[k]] = 1;
    }
    for (Index s : in.anchored_simplices) {
        const Index v = original.simplices(s, 0);
        pinned.row(v) = (A[s] * frames.corner(s, 0) + T[s]).transpose();
        fixed[v] = 1;
    }
    Eigen::MatrixXd recovered = recover_vertices<D>(mesh, frames, A, pinned, fixed);
    result.times.recovery += stage.lap();

    if (options.polish) {
        // The anchored simplices keep all their vertices: a free part has no rigid motion left.
        for (Index s : in.anchored_simplices) {
            for (int k = 0; k <= D; ++k) fixed[original.simplices(s, k)] = 1;
        }
        const SimplexEnergy<D> energy(simplex_energy_options(options), frames.volume,
                                      options.mapping_distortion == DistortionType::kDifference
                                          ? in.reference_linear
                                          : std::vector<Mat<D>>{});
        VertexPolish polish =
            polish_vertices<D>(mesh, frames, energy, recovered, fixed, options, observer.logger);
        result.polished = polish.ran;
        result.polish_note = polish.note;
        result.polish = polish.newton;
        recovered = polish.positions;
        result.times.polish += stage.lap();
    }
    result.positions = (recovered / scale).rowwise() + map_center;
    for (Index v = 0; v < original.num_vertices(); ++v) {
        if (!topology.used_vertex[v]) result.positions.row(v) = initial_map.row(v);  // untouched
    }

    // 5. Verification, from the output positions and the original rest shape.
    const RestFrames<D> rest = rest_frames<D>(original);
    const std::vector<Mat<D>> out = linear_parts<D>(original, rest, result.positions);
    result.final_quality = map_quality<D>(out, rest.volume);
    Verification& v = result.verification;
    v.simplices = n;
    v.inverted = result.final_quality.inverted;
    v.degenerate = result.final_quality.degenerate;
    v.handles = static_cast<Index>(input.handles.size());
    for (std::size_t k = 0; k < input.handles.size(); ++k) {
        v.handle_error = std::max(
            v.handle_error, (result.positions.row(input.handles[k]) - target_rows.row(k)).norm());
    }
    v.handle_tolerance = options.handle_tolerance * bounding_box_diagonal(initial_map);
    v.bound = options.bound;
    for (Index s = 0; s < n; ++s) {
        const MatrixInvariants<double> m = matrix_invariants<D>(out[s], false);
        const double d =
            m.J > 0.0 ? distortion<D>(options.distortion, m, options.gamma) : kInfinity;
        v.max_distortion = std::max(v.max_distortion, d);
    }
    result.success = v.passed();
    std::ostringstream message;
    message << (result.success ? "success: " : "FAILED: ") << v.describe() << ". ";
    if (result.assembled) {
        message << "Assembled (E~ = " << result.final_assembly << ") after "
                << result.newton.num_steps() << " iterations";
    } else {
        message << "Not assembled: E~ = " << result.final_assembly << " after "
                << result.newton.num_steps() << " iterations ("
                << to_string(result.newton.termination) << ")";
    }
    if (result.polished) {
        message << ", then " << result.polish.num_steps() << " in vertex variables ("
                << to_string(result.polish.termination) << ")";
    } else if (options.polish) {
        message << "; vertex stage " << result.polish_note;
    }
    message << ".";
    result.message = message.str();
    result.times.verification += stage.lap();
    result.times.total = total.seconds();
    return result;
}

}  // namespace

SimplexAssemblyResult run_simplex_assembly(const MappingProblem& problem,
                                           const SimplexAssemblyOptions& options,
                                           const SimplexAssemblyObserver& observer) {
    options.validate();
    switch (problem.mesh.simplex_dimension()) {
        case 2:
            return run<2>(problem, options, observer);
        case 3:
            return run<3>(problem, options, observer);
        default:
            throw InputError(problem.source + ": simplices have " +
                             std::to_string(problem.mesh.simplices.cols()) +
                             " vertices, expected 3 or 4");
    }
}

}  // namespace sa
