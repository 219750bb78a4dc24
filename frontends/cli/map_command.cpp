#include "frontends/cli/map_command.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>

#include "frontends/cli/cli_support.h"
#include "frontends/cli/out_of_memory.h"
#include "frontends/cli/output_plan.h"
#include "frontends/output/iteration_recorder.h"
#include "frontends/output/map_output.h"
#include "frontends/output/map_picture.h"
#include "frontends/output/map_report.h"
#include "frontends/simplex_assembly/map_solve.h"
#include "geometry/io/index_list_io.h"
#include "geometry/io/mesh_file.h"
#include "optim/errors.h"
#include "optim/stopwatch.h"

namespace sa::cli {

double parse_bound(const std::string& text) {
    if (text == "inf" || text == "infinity" || text == "none") return kInfinity;
    try {
        std::size_t used = 0;
        const double k = std::stod(text, &used);
        if (used == text.size() && k > 1.0) return k;
    } catch (const std::exception&) {
    }
    throw InvalidArgumentError("--bound " + text + ": expected a number > 1 or 'inf'");
}

namespace {

std::string format_quality(const MapQuality& q) {
    char line[256];
    std::snprintf(
        line, sizeof line,
        "%ld inverted, %ld degenerate; conformal max %.4g avg %.4g; isometric max %.4g avg %.4g",
        long(q.inverted), long(q.degenerate), q.conformal.max, q.conformal.mean, q.isometric.max,
        q.isometric.mean);
    return line;
}

}  // namespace

int run_map_command(const MapArguments& a) {
    // Options and output locations first: a typo should not cost a solve.
    SimplexAssemblyOptions options;
    options.distortion = parse_distortion_among(
        "--distortion", a.distortion,
        {DistortionType::kConformal, DistortionType::kVolumetric, DistortionType::kIsometric});
    options.bound = parse_bound(a.bound);
    if (a.energy != "none")
        options.mapping_distortion = parse_option("--energy", a.energy, parse_distortion);
    options.mu = a.mu;
    options.s = a.s;
    options.lambda_max = a.lambda_max;
    options.vertex_stage = !a.no_vertex_stage;
    options.until_valid = a.until_valid;
    options.mode = parse_option("--mode", a.mode, parse_solve_mode);
    options.linear_solver = parse_option("--linear-solver", a.linear_solver, parse_linear_solver);
    options.rings = a.rings;
    options.max_rings = a.max_rings;
    options.max_rounds = a.max_rounds;
    if (a.max_rings < a.rings) {
        throw InvalidArgumentError("--max-rings " + std::to_string(a.max_rings) +
                                   ": must be >= --rings (" + std::to_string(a.rings) + ")");
    }
    options.projection = parse_option("--projection", a.projection, parse_projection);
    options.translation_shift = a.translation_shift;
    if (!std::isfinite(a.translation_shift * a.lambda_max)) {
        std::ostringstream message;
        message << "--translation-shift " << a.translation_shift << ": times --lambda-max ("
                << a.lambda_max << ") it is not a finite number";
        throw InvalidArgumentError(message.str());
    }
    options.variant = parse_option("--variant", a.variant, parse_variant);
    if (!a.initialization.empty())
        options.initialization =
            parse_option("--initialization", a.initialization, parse_initialization);
    options.seed = a.seed;
    options.max_iterations = a.max_iterations;
    options.max_time_seconds = a.max_time;
    options.num_threads = a.threads;
    options.validate();
    PictureOutput picture(a.png, a.no_png, a.out, a.max_time);
    OutputPlan plan(a.force);
    plan.input("--rest", a.rest);
    plan.input("--init", a.init);
    plan.input("--handles", a.handles);
    plan.input("--targets", a.targets);
    plan.file("--out", a.out);
    picture.plan(plan);
    plan.file("--report", a.report);
    plan.folder("--record", a.record, {"assembly.pvd"});
    plan.check();

    MeshFile rest = read_input_mesh("--rest", a.rest);
    MappingProblem problem;
    problem.source = a.rest;
    problem.mesh = std::move(rest.mesh);
    const int d = problem.mesh.simplex_dimension();
    const Index nv = problem.mesh.num_vertices();
    check_output_format(a.out, d);
    set_activity("reading --handles " + a.handles);
    std::string handles_reading;
    if (a.handles.empty()) {
        problem.handles = rest.handles;
        for (Index h : problem.handles) {
            if (h < 0 || h >= nv) {
                throw InputError(a.rest + ": handle vertex " + std::to_string(h) + " outside [0, " +
                                 std::to_string(nv) + ")");
            }
        }
    } else {
        IndexList list = read_index_list(a.handles);
        for (std::size_t k = 0; k < list.indices.size(); ++k) {
            if (list.indices[k] >= nv)
                throw InputError(a.handles + ":" + std::to_string(list.lines[k]) +
                                 ": handle vertex " + std::to_string(list.indices[k]) +
                                 " outside [0, " + std::to_string(nv) + ")");
        }
        handles_reading = first_number_reading(a.handles, list);
        problem.handles = std::move(list.indices);
    }
    Eigen::MatrixXd targets;
    if (!a.targets.empty()) {
        set_activity("reading --targets " + a.targets);
        const Eigen::MatrixXd positions = read_positions(a.targets, nv, d);
        targets.resize(problem.handles.size(), d);
        for (std::size_t k = 0; k < problem.handles.size(); ++k)
            targets.row(k) = positions.row(problem.handles[k]);
        problem.targets = targets;
    }
    if (!a.init.empty()) {
        set_activity("reading --init " + a.init);
        problem.initial = read_positions(a.init, nv, d);
    } else if (rest.initial) {
        problem.initial = *rest.initial;
    } else if (!a.targets.empty() && problem.mesh.ambient_dimension() == d) {
        problem.initial = problem.mesh.vertices;
        for (std::size_t k = 0; k < problem.handles.size(); ++k)
            problem.initial.row(problem.handles[k]) = targets.row(k);
    } else {
        throw InputError(
            a.rest +
            ": no initial map: give --init, or --targets to move the handles of the rest shape, "
            "or a --rest file that carries one (a problem file, an OBJ with vt)");
    }

    plan.open_folders();
    std::unique_ptr<IterationRecorder> recorder;
    SimplexAssemblyObserver observer;
    observer.logger = stderr_logger(a.quiet);
    if (!a.record.empty()) {
        recorder = std::make_unique<IterationRecorder>(a.record, problem.mesh, a.force);
        observer.snapshot = [&recorder](int iteration, const Eigen::MatrixXd& corners) {
            const auto lock = output_lock();
            recorder->record(iteration, corners);
        };
    }
    std::cout << "sa map: " << problem.mesh.num_simplices()
              << (d == 2 ? " triangles" : " tetrahedra") << ", " << nv << " vertices, "
              << problem.handles.size() << " handles (" << a.rest << ")\n"
              << (handles_reading.empty() ? "" : "  handles: " + handles_reading + "\n");
    set_activity("solving (Simplex Assembly on " + std::to_string(problem.mesh.num_simplices()) +
                 (d == 2 ? " triangles)" : " tetrahedra)"));
    std::optional<SimplexAssemblyResult> solved;
    try {
        solved = run_simplex_assembly(problem, options, observer);
    } catch (const InfeasibleProblemError& e) {
        // Nothing was optimized and no map is written: the handles alone rule out a solution.
        // The report says why; a --record folder is closed with no frame.
        set_activity("writing the report");
        if (!a.report.empty()) {
            const nlohmann::json report = infeasible_report(problem, e);
            plan.write(a.report, [&](const std::string& path) { write_json(path, report); });
        }
        if (recorder) {
            const auto lock = output_lock();
            recorder->finish();
        }
        plan.commit("  INFEASIBLE: " + one_line(e.what()) + "\n" +
                    (a.report.empty() ? "" : "  wrote " + a.report + "\n"));
        return kExitNotVerified;
    }
    const SimplexAssemblyResult& result = *solved;

    set_activity("writing the outputs");
    plan.write(a.out, [&](const std::string& path) { write_map_result(path, problem, result); });
    if (!a.report.empty()) {
        const nlohmann::json report = map_report(problem, options, result);
        plan.write(a.report, [&](const std::string& path) { write_json(path, report); });
    }
    // The picture last, after the solve.
    picture.draw(plan, [&](const std::string& path) { write_map_png(path, problem, result); });
    std::string series;
    if (recorder) {
        const auto lock = output_lock();
        series = recorder->finish();
    }

    char times[200];
    std::snprintf(
        times, sizeof times,
        "%.3f s (setup %.3f, disassembly %.3f, assembly %.3f, recovery %.3f, vertex stage %.3f, "
        "verification %.3f)",
        result.times.total, result.times.setup, result.times.disassembly, result.times.optimization,
        result.times.recovery, result.times.vertex_stage, result.times.verification);
    std::ostringstream summary;
    summary << "  initial map: " << format_quality(result.initial_quality) << "\n"
            << "  result:      " << format_quality(result.final_quality) << "\n"
            << "  "
            << (result.mode == SolveMode::kDescent
                    ? std::string("descent")
                    : to_string(options.variant) + ", " + std::to_string(result.num_variables) +
                          " variables")
            << ", " << result.newton.num_steps() + result.vertex_stage.num_steps()
            << " iterations, time " << times << "\n"
            << "  " << result.message << "\n"
            << "  wrote " << a.out << picture.wrote() << (a.report.empty() ? "" : ", " + a.report)
            << (series.empty() ? "" : ", " + series) << "\n";
    plan.commit(summary.str());
    picture.warn(std::cerr);
    return result.success ? kExitVerified : kExitNotVerified;
}

}  // namespace sa::cli
