#include "frontends/cli/polycube_command.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "frontends/cli/cli_support.h"
#include "frontends/cli/map_command.h"
#include "frontends/cli/out_of_memory.h"
#include "frontends/output/map_report.h"
#include "frontends/polycube/polycube_output.h"
#include "frontends/polycube/polycube_report.h"
#include "frontends/polycube/polycube_solve.h"
#include "geometry/io/medit_io.h"
#include "geometry/io/mesh_file.h"
#include "geometry/io/polycube_labels_io.h"
#include "optim/errors.h"
#include "optim/stopwatch.h"

namespace sa::cli {

namespace {

/// Throws InputError `OPTION PATH: ...` unless `path` is a file that can be opened.
void check_input_file(const char* option, const std::string& path) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
        throw InputError(std::string(option) + " " + path + ": no such file");
    }
    if (!std::ifstream(path)) throw InputError(std::string(option) + " " + path + ": cannot open");
}

/// The caption of the picture.
std::string polycube_picture_title(const PolycubeVerification& verification) {
    return std::string("PolyCube, ") + (verification.passed ? "verified" : "NOT verified");
}

}  // namespace

PolycubePlan check_polycube_arguments(const PolycubeArguments& a) {
    PolycubePlan plan;
    plan.mesh = a.mesh;
    check_input_file("--mesh", a.mesh);
    if (!a.label_surface.empty() && a.labels.empty()) {
        throw InvalidArgumentError("--label-surface " + a.label_surface +
                                   ": needs --labels, one label per triangle of that surface");
    }
    if (!a.labels.empty()) {
        check_input_file("--labels", a.labels);
        if (a.label_surface.empty()) {
            plan.labels.flags = a.labels;
        } else {
            check_input_file("--label-surface", a.label_surface);
            plan.labels.labels = a.labels;
            plan.labels.surface = a.label_surface;
        }
    }
    if (a.keep_orientation && !a.labels.empty()) {
        throw InvalidArgumentError("--keep-orientation: only for computed labels (--labels " +
                                   a.labels + " are in the input's own axes already)");
    }
    if (a.keep_turning_boundaries && !a.labels.empty()) {
        throw InvalidArgumentError(
            "--keep-turning-boundaries: only for computed labels (--labels " + a.labels +
            " are used as given)");
    }
    plan.labels.orient = !a.keep_orientation;
    plan.labels.repair = !a.keep_turning_boundaries;
    plan.bound = parse_bound(a.bound);
    if (a.optimal_bound && std::isfinite(plan.bound)) {
        throw InvalidArgumentError("--bound " + a.bound +
                                   " and --optimal-bound: give one or the other");
    }
    plan.optimal_bound = a.optimal_bound;
    if (!(a.max_time > 0.0)) {
        throw InvalidArgumentError("--max-time " + std::to_string(a.max_time) +
                                   ": expected a number of seconds > 0, or inf");
    }
    plan.max_time = a.max_time;
    if (a.threads < 0) {
        throw InvalidArgumentError("--threads " + std::to_string(a.threads) + ": expected >= 0");
    }
    plan.threads = a.threads;
    plan.quiet = a.quiet;

    if (extension(a.out) != ".mesh") {
        throw InvalidArgumentError("--out " + a.out + ": the PolyCube map is written as .mesh");
    }
    plan.out = a.out;
    plan.rest = polycube_rest_path(a.out);
    plan.flags = polycube_flags_path(a.out);
    if (!a.vtu.empty() && extension(a.vtu) != ".vtu" && extension(a.vtu) != ".vtk") {
        throw InvalidArgumentError("--vtu " + a.vtu + ": expected a .vtu or .vtk file");
    }
    if (!a.report.empty() && extension(a.report) != ".json") {
        throw InvalidArgumentError("--report " + a.report + ": expected a .json file");
    }
    plan.vtu = a.vtu;
    plan.png = PictureOutput(a.png, a.no_png, a.out, a.max_time).path();
    plan.report = a.report;
    return plan;
}

PictureOutput plan_polycube_files(const PolycubeArguments& a, const PolycubePlan& plan,
                                  OutputPlan& outputs) {
    outputs.input("--mesh", a.mesh);
    outputs.input("--labels", a.labels);
    outputs.input("--label-surface", a.label_surface);
    outputs.file("--out", plan.out);
    outputs.file("--out (rest mesh)", plan.rest);
    outputs.file("--out (flags)", plan.flags);
    outputs.file("--vtu", plan.vtu);
    PictureOutput picture(a.png, a.no_png, a.out, a.max_time);
    picture.plan(outputs);
    outputs.file("--report", plan.report);
    outputs.check();
    return picture;
}

PreparedPolycube read_polycube_input(const PolycubePlan& plan, const Logger& logger) {
    const MeshFile file = read_input_mesh("--mesh", plan.mesh);
    return prepare_polycube(file.mesh, plan.mesh, plan.labels, logger);
}

void write_polycube_outputs(const PolycubePlan& plan, const PreparedPolycube& prepared,
                            const Eigen::MatrixXd& positions,
                            const PolycubeVerification& verification, nlohmann::json report,
                            OutputPlan& outputs) {
    auto write = [&](const std::string& path, const auto& writer) {
        if (!path.empty()) outputs.write(path, writer);
    };
    if (positions.rows() != prepared.mesh.num_vertices() || positions.cols() != 3) {
        throw InvalidArgumentError("write_polycube_outputs: positions must be #V x 3 = " +
                                   std::to_string(prepared.mesh.num_vertices()) + " x 3");
    }
    write(plan.rest, [&](const std::string& path) {
        write_medit(path, prepared.rest_positions(), prepared.mesh.simplices);
    });
    write(plan.flags,
          [&](const std::string& path) { write_facet_flags(path, prepared.output_flags()); });
    write(plan.out,
          [&](const std::string& path) { write_polycube_map(path, prepared, positions); });
    write(plan.vtu, [&](const std::string& path) {
        write_polycube_vtu(path, prepared, positions, verification);
    });
    write(plan.png, [&](const std::string& path) {
        write_polycube_png(path, prepared, positions, verification,
                           polycube_picture_title(verification));
    });
    if (!plan.report.empty()) {
        report["preparation"] = polycube_preparation_json(prepared);
        report["verification"] = polycube_verification_json(verification);
        report["outputs"] = {{"mesh", plan.out}, {"rest", plan.rest}, {"flags", plan.flags}};
        write(plan.report, [&](const std::string& path) { write_json(path, report); });
    }
}

namespace {

nlohmann::json rounds_json(const std::vector<BoundRound>& rounds) {
    nlohmann::json out = nlohmann::json::array();
    for (const BoundRound& r : rounds) {
        out.push_back({{"bound", std::isfinite(r.bound) ? nlohmann::json(r.bound) : "inf"},
                       {"max_distortion", r.max_distortion},
                       {"success", r.success},
                       {"iterations", r.iterations},
                       {"time", r.time}});
    }
    return out;
}

}  // namespace

int run_polycube_command(const PolycubeArguments& arguments) {
    Stopwatch total;
    const PolycubePlan plan = check_polycube_arguments(arguments);
    OutputPlan outputs(arguments.force);
    PictureOutput picture = plan_polycube_files(arguments, plan, outputs);
    const Logger logger = stderr_logger(plan.quiet);

    set_activity("reading --mesh " + plan.mesh);
    const PreparedPolycube prepared = read_polycube_input(plan, logger);
    std::cout << "sa polycube: " << prepared.input.num_simplices() << " tetrahedra ("
              << prepared.mesh.num_simplices() << " after " << prepared.splits.edge_splits
              << " edge and " << prepared.splits.face_splits << " face splits), "
              << prepared.charts.size() << " charts, labels " << prepared.label_source << " ("
              << plan.mesh << ")\n";
    PolycubeSolveOptions options;
    options.bound = plan.bound;
    options.optimal_bound = plan.optimal_bound;
    options.max_time = plan.max_time;
    options.threads = plan.threads;
    set_activity("solving (a PolyCube map of " + std::to_string(prepared.mesh.num_simplices()) +
                 " tetrahedra)");
    const PolycubeSolve solve = solve_polycube(prepared, options, logger);

    nlohmann::json report;
    report["command"] = "polycube";
    report["success"] = solve.success;
    report["message"] = solve.message;
    report["start"] = {{"kind", "cube cover"},
                       {"quality", quality_json(solve.start_quality)},
                       {"untangled_on_planes", solve.start_untangled}};
    report["bound"] = std::isfinite(plan.bound) ? nlohmann::json(plan.bound) : "inf";
    report["optimal_bound"] = plan.optimal_bound;
    report["reached_bound"] =
        std::isfinite(solve.bound) ? nlohmann::json(solve.bound) : nlohmann::json("inf");
    report["rounds"] = rounds_json(solve.rounds);
    report["solve"] = {{"assembled", solve.solve.assembled},
                       {"final_assembly", solve.solve.final_assembly},
                       {"assembly_iterations", solve.solve.newton.num_steps()},
                       {"stages", stages_json(solve.solve.stages)},
                       {"vertex_stage_iterations", solve.solve.vertex_stage.num_steps()},
                       {"driver_message", solve.solve.message},
                       {"times", solve_times_json(solve.solve)},
                       {"iterations", assembly_iterations_json(solve.solve)}};
    report["times"] = {{"cube_cover", solve.cube_cover_seconds},
                       {"untangle", solve.untangle_seconds},
                       {"solve", solve.solve_seconds},
                       {"verify", solve.verify_seconds},
                       {"total", total.seconds()}};
    report["peak_memory_gb"] = peak_memory_gb();
    set_activity("writing the outputs");
    PolycubePlan files = plan;
    files.png.clear();  // drawn below: a picture that cannot be drawn costs the run nothing else
    write_polycube_outputs(files, prepared, solve.positions, solve.verification, report, outputs);
    picture.draw(outputs, [&](const std::string& path) {
        write_polycube_png(path, prepared, solve.positions, solve.verification,
                           polycube_picture_title(solve.verification));
    });
    std::ostringstream summary;
    summary << solve.message << "\n"
            << "conformal distortion max " << solve.verification.quality.conformal.max << ", mean "
            << solve.verification.quality.conformal.mean << "; isometric max "
            << solve.verification.quality.isometric.max << "; "
            << (solve.rounds.empty() ? std::string()
                                     : std::to_string(solve.rounds.size()) + " rounds, ")
            << "time " << total.seconds() << " s\n"
            << "wrote " << plan.out << ", " << plan.rest << ", " << plan.flags
            << (plan.vtu.empty() ? "" : ", " + plan.vtu) << picture.wrote()
            << (plan.report.empty() ? "" : ", " + plan.report) << "\n";
    outputs.commit(summary.str());
    picture.warn(std::cerr);
    return solve.success ? kExitVerified : kExitNotVerified;
}

}  // namespace sa::cli
