#include "frontends/cli/param_command.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "frontends/cli/cli_support.h"
#include "frontends/cli/map_command.h"
#include "frontends/cli/out_of_memory.h"
#include "frontends/cli/output_plan.h"
#include "frontends/output/layout_picture.h"
#include "frontends/output/map_output.h"
#include "frontends/output/map_report.h"
#include "frontends/param/parameterization.h"
#include "geometry/io/mesh_file.h"
#include "geometry/io/obj_io.h"
#include "geometry/io/vtk_io.h"
#include "geometry/mesh/subdivision.h"
#include "optim/errors.h"
#include "optim/stopwatch.h"

namespace sa::cli {

namespace {

const std::vector<std::string> kInitialMaps = {"lscm", "tutte", "tutte-uniform", "harmonic"};

}  // namespace

int run_param_command(const ParamArguments& a) {
    Stopwatch total;
    ParameterizationOptions options;
    SimplexAssemblyOptions& solver = options.solver;
    solver.distortion = parse_distortion_among(
        "--distortion", a.distortion, {DistortionType::kConformal, DistortionType::kIsometric});
    solver.bound = parse_bound(a.bound);
    if (a.energy == "difference" || a.energy == "diff") {
        solver.mapping_distortion = DistortionType::kDifference;
    } else if (a.energy == "lscm") {
        solver.mapping_distortion = DistortionType::kLscm;
    } else if (a.energy != "none") {
        throw InvalidArgumentError("--energy " + a.energy + ": expected difference, lscm or none");
    }
    solver.mu = a.mu;
    solver.mode = parse_option("--mode", a.mode, parse_solve_mode);
    solver.num_threads = a.threads;
    solver.max_iterations = a.max_iterations;
    solver.max_time_seconds = a.max_time;
    solver.validate();
    if (a.optimal_bound)
        options.optimal_bound_rounds = a.optimal_bound_rounds > 0 ? a.optimal_bound_rounds : 20;
    options.optimal_bound_tolerance = a.optimal_bound_tolerance;
    options.free_boundary_injective = a.free_boundary_injective;
    options.fallback = !a.no_fallback;
    const std::string out_ext = extension(a.out);
    if (out_ext != ".obj" && out_ext != ".vtu" && out_ext != ".vtk") {
        throw InvalidArgumentError(a.out +
                                   ": the parameterized surface is written as .obj, .vtu or .vtk");
    }
    if (!a.layout.empty() && extension(a.layout) != ".vtu" && extension(a.layout) != ".vtk") {
        throw InvalidArgumentError(a.layout + ": the layout is written as .vtu or .vtk");
    }
    PictureOutput picture(a.png, a.no_png, a.out, a.max_time);
    const bool named =
        std::find(kInitialMaps.begin(), kInitialMaps.end(), a.init) != kInitialMaps.end();
    OutputPlan plan(a.force);
    plan.input("--mesh", a.mesh);
    if (!named) plan.input("--init", a.init);
    plan.file("--out", a.out);
    plan.file("--layout", a.layout);
    picture.plan(plan);
    plan.file("--report", a.report);
    plan.check();

    Stopwatch stage;
    const MeshFile file = read_input_mesh("--mesh", a.mesh, "a parameterization");
    const SimplicialMesh& mesh = file.mesh;
    const double read_time = stage.lap();
    Eigen::MatrixXd given;
    if (!named) {
        set_activity("reading --init " + a.init);
        if (extension(a.init) == ".obj") {
            const MeshFile init = read_mesh_file(a.init);
            if (!init.initial)
                throw InputError(a.init + ": no per-vertex texture coordinates (vt) to start from");
            given = *init.initial;
        } else {
            given = read_positions(a.init, mesh.num_vertices(), 2);
        }
        if (given.rows() != mesh.num_vertices()) {
            throw InputError(a.init + ": " + std::to_string(given.rows()) + " positions for " +
                             std::to_string(mesh.num_vertices()) + " vertices");
        }
    }
    SimplexAssemblyObserver observer;
    observer.logger = stderr_logger(a.quiet);
    std::cout << "sa param: " << mesh.num_simplices() << " triangles, " << mesh.num_vertices()
              << " vertices (" << a.mesh << "), initial map " << a.init << "\n";
    set_activity("solving (a parameterization of " + std::to_string(mesh.num_simplices()) +
                 " triangles)");
    const ParameterizationResult r =
        parameterize(mesh, a.mesh, named ? nullptr : &given,
                     named ? parse_initial_map(a.init) : InitialMap::kLscm, options, observer);
    const double solve_time = stage.lap();

    // Outputs: the surface with its map, the layout, the picture, the report.
    set_activity("writing the outputs");
    const MapQuality& q = r.solve.final_quality;
    const std::vector<DataArray> cells = quality_cell_data(q);
    if (out_ext == ".obj") {
        plan.write(a.out, [&](const std::string& path) {
            write_obj(path, mesh.vertices, mesh.simplices, &r.uv);
        });
    } else {
        Eigen::MatrixXd uv3 = Eigen::MatrixXd::Zero(r.uv.rows(), 3);
        uv3.leftCols(2) = r.uv;
        const std::vector<DataArray> points = {{"uv", uv3}};
        plan.write(a.out, [&](const std::string& path) {
            out_ext == ".vtu" ? write_vtu(path, mesh.vertices, mesh.simplices, points, cells)
                              : write_vtk(path, mesh.vertices, mesh.simplices, points, cells);
        });
    }
    if (!a.layout.empty()) {
        plan.write(a.layout, [&](const std::string& path) {
            extension(a.layout) == ".vtu" ? write_vtu(path, r.uv, mesh.simplices, {}, cells)
                                          : write_vtk(path, r.uv, mesh.simplices, {}, cells);
        });
    }
    if (!picture.path().empty()) {
        Eigen::VectorXd values(mesh.num_simplices());
        std::vector<unsigned char> inverted(mesh.num_simplices());
        for (Index f = 0; f < mesh.num_simplices(); ++f) {
            values[f] = q.per_simplex[f].conformal;
            inverted[f] = q.per_simplex[f].inverted || q.per_simplex[f].degenerate;
        }
        LayoutPicture layout;
        char title[256];
        std::snprintf(title, sizeof title,
                      "%s: %ld faces, %ld foldovers; conformal distortion max %.3g, mean %.4g",
                      std::filesystem::path(a.mesh).filename().c_str(), long(mesh.num_simplices()),
                      long(q.inverted), q.conformal.max, q.conformal.mean);
        layout.title = title;
        layout.value_name = "conformal distortion (sigma max / sigma min)";
        layout.low = 1.0;
        layout.high = std::max(1.1, std::min(q.conformal.max, 10.0));
        picture.draw(plan, [&](const std::string& path) {
            write_layout_png(path, r.uv, mesh.simplices, values, layout, inverted);
        });
    }
    const double output_time = stage.lap();
    if (!a.report.empty()) {
        MappingProblem problem;
        problem.mesh = mesh;
        problem.initial = r.initial_uv;
        problem.source = a.mesh;
        nlohmann::json report = map_report(problem, solver, r.solve);
        report["message"] = r.message;  // the command's, not its last solve's
        nlohmann::json rounds = nlohmann::json::array();
        for (const BoundRound& b : r.rounds) {
            rounds.push_back({{"bound", std::isfinite(b.bound) ? nlohmann::json(b.bound)
                                                               : nlohmann::json(nullptr)},
                              {"max_distortion", b.max_distortion},
                              {"success", b.success},
                              {"iterations", b.iterations},
                              {"time", b.time}});
        }
        nlohmann::json fallback = {{"used", r.fallback.used}};
        if (r.fallback.used) {
            nlohmann::json starts = nlohmann::json::array();
            for (const TriedStart& t : r.fallback.starts) {
                starts.push_back({{"start", start_name(t.weights)},
                                  {"valid", t.valid},
                                  {"verified", t.verified},
                                  {"max_distortion", std::isfinite(t.max_distortion)
                                                         ? nlohmann::json(t.max_distortion)
                                                         : nlohmann::json(nullptr)},
                                  {"outcome", to_string(t.outcome)},
                                  {"details", t.describe()}});
            }
            nlohmann::json descent = nlohmann::json::array();
            for (const ContinuationRound& d : r.fallback.rounds)
                descent.push_back(continuation_round_json(d));
            fallback["reason"] = r.fallback.describe_reason();
            fallback["reason_kind"] = to_string(r.fallback.reason);
            fallback["starts"] = starts;
            fallback["start"] = r.fallback.start ? nlohmann::json(start_name(*r.fallback.start))
                                                 : nlohmann::json(nullptr);
            fallback["descent_rounds"] = descent;
            fallback["time"] = r.fallback.time;
        }
        report["parameterization"] = {
            {"fallback", fallback},
            {"initial_map", a.init},
            {"initial_quality", quality_json(r.initial_quality)},
            {"bound_rounds", rounds},
            {"reached_bound", std::isfinite(r.reached_bound) ? nlohmann::json(r.reached_bound)
                                                             : nlohmann::json(nullptr)},
            {"filled_holes", r.filled_holes},
            {"unused_vertices", r.unused_vertices},
            {"boundary_violations_before", r.boundary_violations_before},
            {"boundary_violations_after", r.boundary_violations_after},
            {"success", r.success},
            {"message", r.message},
            {"times",
             {{"read", read_time},
              {"initial_map", r.initial_map_time},
              {"solve", solve_time - r.initial_map_time},
              {"output", output_time},
              {"total", total.seconds()}}},
            {"peak_memory_gb", peak_memory_gb()}};
        plan.write(a.report, [&](const std::string& path) { write_json(path, report); });
    }
    char line[512];
    std::snprintf(
        line, sizeof line,
        "  initial map (%s, %.2f s): %ld foldovers, conformal max %.4g mean %.4g\n"
        "  result: %ld foldovers, conformal max %.4g mean %.4g; isometric max %.4g mean %.4g\n",
        a.init.c_str(), r.initial_map_time, long(r.initial_quality.inverted),
        r.initial_quality.conformal.max, r.initial_quality.conformal.mean, long(q.inverted),
        q.conformal.max, q.conformal.mean, q.isometric.max, q.isometric.mean);
    std::ostringstream summary;
    summary << line;
    if (options.optimal_bound_rounds > 0) {
        summary << "  optimal bound: " << r.rounds.size() << " rounds, K reached "
                << r.reached_bound << "\n";
    }
    if (r.fallback.used) {
        summary << "  fallback: " << r.fallback.describe_reason() << "\n";
        for (const TriedStart& t : r.fallback.starts)
            summary << "    " << start_name(t.weights) << ": " << t.describe() << "\n";
    }
    std::snprintf(line, sizeof line,
                  "  time %.2f s (read %.2f, initial map %.2f, Simplex Assembly %.2f, output "
                  "%.2f); peak memory %.2f GB\n",
                  total.seconds(), read_time, r.initial_map_time, solve_time - r.initial_map_time,
                  output_time, peak_memory_gb());
    summary << line << "  " << r.message << "\n  wrote " << a.out
            << (a.layout.empty() ? "" : ", " + a.layout) << picture.wrote()
            << (a.report.empty() ? "" : ", " + a.report) << "\n";
    plan.commit(summary.str());
    picture.warn(std::cerr);
    return r.success ? kExitVerified : kExitNotVerified;
}

int run_subdivide_command(const SubdivideArguments& a) {
    OutputPlan plan(a.force);
    plan.input("--mesh", a.mesh);
    plan.file("--out", a.out);
    plan.check();
    check_output_format(a.out, 2);
    const MeshFile file = read_input_mesh("--mesh", a.mesh, "Loop subdivision");
    validate_mesh(file.mesh, a.mesh);
    set_activity("subdividing " + a.mesh + " " + std::to_string(a.levels) + " times");
    const SimplicialMesh out = loop_subdivide(file.mesh, a.levels);
    set_activity("writing --out " + a.out);
    plan.write(a.out, [&](const std::string& path) {
        write_mesh_file(path, out.vertices, out.simplices);
    });
    plan.commit("sa subdivide: " + std::to_string(file.mesh.num_simplices()) + " -> " +
                std::to_string(out.num_simplices()) + " triangles, " +
                std::to_string(out.num_vertices()) + " vertices; wrote " + a.out + "\n");
    return 0;
}

}  // namespace sa::cli
