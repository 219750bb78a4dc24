#include "frontends/cli/deform_command.h"

#include <cstdio>
#include <iostream>
#include <sstream>

#include "frontends/cli/cli_support.h"
#include "frontends/cli/out_of_memory.h"
#include "frontends/deform/deform_solve.h"
#include "frontends/output/map_output.h"
#include "frontends/output/map_report.h"
#include "frontends/output/pose_picture.h"
#include "geometry/io/mesh_file.h"
#include "optim/errors.h"

namespace sa::cli {

namespace {

/// "inf" or a number > 1, for the option `name`.
double parse_bound_option(const std::string& name, const std::string& text) {
    if (text == "inf" || text == "infinity" || text == "none") return kInfinity;
    try {
        std::size_t used = 0;
        const double k = std::stod(text, &used);
        if (used == text.size() && k > 1.0 && std::isfinite(k)) return k;
    } catch (const std::exception&) {
    }
    throw InvalidArgumentError(name + " " + text + ": expected a number > 1 or 'inf'");
}

/// JSON has no infinity: null.
nlohmann::json number(double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

/// Four significant digits; "inf" for an absent bound.
std::string format_number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", x);
    return std::isfinite(x) ? text : "inf";
}

/// The distortion of a quality summary in one line.
std::string format_quality(const MapQuality& q) {
    char line[300];
    std::snprintf(line, sizeof line,
                  "%ld inverted, %ld degenerate; conformal max %.4g mean %.4g; volumetric max "
                  "%.4g mean %.4g; isometric max %.4g mean %.4g",
                  long(q.inverted), long(q.degenerate), q.conformal.max, q.conformal.mean,
                  q.volumetric.max, q.volumetric.mean, q.isometric.max, q.isometric.mean);
    return line;
}

/// The round's bound on d^c and on d^vol, and the largest of each reached.
struct RoundBounds {
    double conformal_bound, volumetric_bound, conformal, volumetric;
};
RoundBounds round_bounds(const BoundRound& r) {
    RoundBounds b{r.bound, kInfinity, r.max_distortion, 0.0};
    for (const BoundCheck& c : r.bounds) {
        if (c.name != kVolumetricBarrierName) continue;
        b.volumetric_bound = c.bound;
        b.volumetric = c.max_distortion;
    }
    return b;
}

nlohmann::json deform_report(const DeformArguments& a, const DeformResult& r) {
    nlohmann::json rounds = nlohmann::json::array();
    for (const BoundRound& round : r.solve.rounds) {
        const RoundBounds b = round_bounds(round);
        rounds.push_back({{"conformal_bound", number(b.conformal_bound)},
                          {"volumetric_bound", number(b.volumetric_bound)},
                          {"conformal_max", number(b.conformal)},
                          {"volumetric_max", number(b.volumetric)},
                          {"success", round.success},
                          {"iterations", round.iterations},
                          {"seconds", round.time}});
    }
    const DeformStart& s = r.start;
    nlohmann::json report;
    report["command"] = "deform";
    report["files"] = {{"rest", a.rest}, {"handles", a.handles}, {"targets", a.targets}};
    report["start"] = {{"method", "ARAP, handles at their targets"},
                       {"from", s.arap.start},
                       {"iterations", s.arap.iterations},
                       {"stop", s.arap.stop},
                       {"energy", s.arap.energy},
                       {"handle_error", s.handle_error},
                       {"seconds", s.seconds},
                       {"quality", quality_json(s.quality)}};
    report["rounds"] = rounds;
    report["solve"] = map_report(r.problem, r.solver, r.solve.solve);
    report["success"] = r.success();
    const std::string warning = r.distortion_warning();
    report["warnings"] =
        warning.empty() ? nlohmann::json::array() : nlohmann::json::array({warning});
    report["seconds"] = r.seconds;
    return report;
}

}  // namespace

DeformOptions deform_options(const DeformArguments& a) {
    DeformOptions options;
    options.conformal_bound = parse_bound_option("--bound-conformal", a.bound_conformal);
    options.volumetric_bound = parse_bound_option("--bound-volumetric", a.bound_volumetric);
    options.optimal_bound = a.optimal_bound;
    if (a.optimal_bound &&
        (std::isfinite(options.conformal_bound) || std::isfinite(options.volumetric_bound))) {
        throw InvalidArgumentError(
            "--optimal-bound finds both bounds: drop --bound-conformal and --bound-volumetric");
    }
    if (a.optimal_bound_rounds < 1) {
        throw InvalidArgumentError("--optimal-bound-rounds " +
                                   std::to_string(a.optimal_bound_rounds) + ": expected >= 1");
    }
    options.optimal_bound_rounds = a.optimal_bound_rounds;
    if (!(a.mu >= 0.0 && std::isfinite(a.mu)))
        throw InvalidArgumentError("--mu " + std::to_string(a.mu) + ": expected a number >= 0");
    options.mu = a.mu;
    options.initialization = parse_initialization(a.initialization);
    if (a.start_iterations < 0) {
        throw InvalidArgumentError("--start-iterations " + std::to_string(a.start_iterations) +
                                   ": expected >= 0");
    }
    options.start.max_iterations = a.start_iterations;
    if (!(a.start_tolerance >= 0.0)) {
        throw InvalidArgumentError("--start-tolerance " + std::to_string(a.start_tolerance) +
                                   ": expected >= 0");
    }
    options.start.tolerance = a.start_tolerance;
    if (!(a.max_time > 0.0))
        throw InvalidArgumentError("--max-time " + std::to_string(a.max_time) + ": expected > 0");
    options.max_time_seconds = a.max_time;
    options.start.max_time_seconds = a.max_time;
    if (a.threads < 0)
        throw InvalidArgumentError("--threads " + std::to_string(a.threads) + ": expected >= 0");
    options.num_threads = a.threads;
    options.validate();
    return options;
}

PictureOutput plan_deform_files(const DeformArguments& a, OutputPlan& plan) {
    PictureOutput picture(a.png, a.no_png, a.out, a.max_time);
    plan.input("--rest", a.rest);
    plan.input("--handles", a.handles);
    plan.input("--targets", a.targets);
    plan.file("--out", a.out);
    picture.plan(plan);
    plan.file("--report", a.report);
    plan.check();
    if (!a.report.empty() && extension(a.report) != ".json")
        throw InvalidArgumentError("--report " + a.report + ": expected a .json file name");
    return picture;
}

DeformInput read_deform_input(const DeformArguments& a) {
    set_activity("reading --rest " + a.rest);
    MeshFile rest = read_mesh_file(a.rest);
    DeformInput input;
    input.warnings = std::move(rest.warnings);
    input.mesh = std::move(rest.mesh);
    validate_mesh(input.mesh, a.rest);
    const int d = input.mesh.simplex_dimension();
    // Triangles in space with z = 0 at every vertex (an OBJ or OFF stores three coordinates) are
    // the planar mesh they are.
    if (d == 2 && input.mesh.ambient_dimension() == 3 &&
        (input.mesh.vertices.col(2).array() == 0.0).all()) {
        input.mesh.vertices.conservativeResize(Eigen::NoChange, 2);
    }
    if (input.mesh.ambient_dimension() != d) {
        throw InputError(a.rest +
                         ": triangles in space; deformation poses tetrahedra, or triangles in "
                         "the plane (z = 0 at every vertex)");
    }
    check_output_format(a.out, d);
    set_activity("reading the handles and --targets " + a.targets);
    input.handle_targets = read_handle_targets(a.handles, a.targets, input.mesh.num_vertices(), d);
    return input;
}

}  // namespace sa::cli

namespace sa::cli {

int run_deform_command(const DeformArguments& a) {
    // Options and output locations first: a typo should not cost a solve.
    const DeformOptions options = deform_options(a);
    OutputPlan plan(a.force);
    PictureOutput picture = plan_deform_files(a, plan);
    const DeformInput input = read_deform_input(a);
    for (const std::string& warning : input.warnings)
        std::cerr << "sa: warning: " << one_line(warning) << '\n';
    const int d = input.mesh.simplex_dimension();
    std::cout << "sa deform: " << input.mesh.num_simplices()
              << (d == 2 ? " triangles" : " tetrahedra") << ", " << input.mesh.num_vertices()
              << " vertices, " << input.handle_targets.handles.size() << " handles (" << a.rest
              << ")\n  handles and targets: " << input.handle_targets.reading << "\n";

    SimplexAssemblyObserver observer;
    observer.logger = stderr_logger(a.quiet);
    set_activity("posing (ARAP start and Simplex Assembly on " +
                 std::to_string(input.mesh.num_simplices()) +
                 (d == 2 ? " triangles)" : " tetrahedra)"));
    const DeformResult result = deform(input.mesh, input.handle_targets, options, observer);
    const SimplexAssemblyResult& solved = result.solve.solve;

    set_activity("writing the outputs");
    plan.write(a.out,
               [&](const std::string& path) { write_map_result(path, result.problem, solved); });
    if (!a.report.empty()) {
        const nlohmann::json report = deform_report(a, result);
        plan.write(a.report, [&](const std::string& path) { write_json(path, report); });
    }
    // The picture last, after the solve.
    if (!picture.path().empty()) {
        PosePicture pose;
        for (Index s = 0; s < result.start.quality.simplices; ++s)
            if (result.start.quality.per_simplex[s].inverted) pose.marked.push_back(s);
        pose.marked_label = "inverted by the ARAP start";
        picture.draw(plan, [&](const std::string& path) {
            write_pose_png(path, input.mesh, solved.positions, pose);
        });
    }
    std::ostringstream summary;
    summary << "  ARAP start:  " << format_quality(result.start.quality) << " ("
            << result.start.arap.iterations << " iterations, " << result.start.arap.stop << ", "
            << format_number(result.start.seconds) << " s)\n";
    for (std::size_t k = 0; k < result.solve.rounds.size(); ++k) {
        const BoundRound& round = result.solve.rounds[k];
        const RoundBounds b = round_bounds(round);
        summary << "  round " << k << ": bounds conformal " << format_number(b.conformal_bound)
                << ", volumetric " << format_number(b.volumetric_bound) << " -> reached "
                << format_number(b.conformal) << ", " << format_number(b.volumetric) << "; "
                << round.iterations << " iterations, " << format_number(round.time) << " s"
                << (round.success ? "" : " (not verified within its bounds)") << "\n";
    }
    summary << "  result:      " << format_quality(solved.final_quality) << "\n";
    if (const std::string warning = result.distortion_warning(); !warning.empty())
        summary << "  warning: " << warning << "\n";
    summary << "  " << solved.message << "\n"
            << "  total " << format_number(result.seconds) << " s; wrote " << a.out
            << picture.wrote() << (a.report.empty() ? "" : ", " + a.report) << "\n";
    plan.commit(summary.str());
    picture.warn(std::cerr);
    return result.success() ? kExitVerified : kExitNotVerified;
}

}  // namespace sa::cli
