#include "frontends/cli/hex_command.h"

#include <cmath>
#include <iostream>
#include <sstream>

#include "frontends/cli/cli_support.h"
#include "frontends/cli/out_of_memory.h"
#include "frontends/hex/hex_meshing.h"
#include "frontends/hex/hex_output.h"
#include "frontends/output/map_report.h"
#include "frontends/polycube/polycube_report.h"
#include "geometry/io/medit_io.h"
#include "geometry/io/polycube_labels_io.h"
#include "optim/errors.h"
#include "optim/stopwatch.h"

namespace sa::cli {

namespace {

/// The checked arguments.
struct HexPlan {
    PolycubePlan polycube;  ///< its out, rest and flags: the PolyCube's files (empty: none)
    HexMeshingOptions meshing;
    std::string out, vtu, png, report;
    bool quiet = false;
};

HexPlan check_hex_arguments(const HexArguments& a) {
    HexPlan plan;
    if (extension(a.out) != ".mesh")
        throw InvalidArgumentError("--out " + a.out + ": the hex mesh is written as .mesh");
    if (!a.polycube_out.empty() && extension(a.polycube_out) != ".mesh") {
        throw InvalidArgumentError("--polycube " + a.polycube_out +
                                   ": the PolyCube map is written as .mesh");
    }
    PolycubeArguments p = a.polycube;
    p.out = a.polycube_out.empty() ? a.out : a.polycube_out;
    p.vtu.clear();
    p.png.clear();
    p.no_png = true;
    p.report.clear();
    plan.polycube = check_polycube_arguments(p);
    if (a.polycube_out.empty()) plan.polycube.out = plan.polycube.rest = plan.polycube.flags = "";
    if (plan.polycube.optimal_bound) {
        throw InvalidArgumentError(
            "--optimal-bound: not taken by `sa hex` (the PolyCube on the "
            "grid is solved once); give --bound or nothing");
    }
    if (!a.hexes.empty() && !a.hex_size.empty()) {
        throw InvalidArgumentError("--hexes " + a.hexes + " and --hex-size " + a.hex_size +
                                   ": give one or the other");
    }
    plan.meshing.hexes = kDefaultHexes;
    if (!a.hexes.empty()) {
        plan.meshing.hexes = parse_option("--hexes", a.hexes, [](const std::string& text) {
            std::size_t used = 0;
            long long n = -1;
            try {
                n = std::stoll(text, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            if (used != text.size() || n < 1 || n > 100000000)
                throw InvalidArgumentError("expected a whole number of hexes in [1, 1e8]");
            return static_cast<Index>(n);
        });
    }
    if (!a.hex_size.empty()) {
        plan.meshing.hex_size = parse_option("--hex-size", a.hex_size, [](const std::string& text) {
            std::size_t used = 0;
            double h = -1.0;
            try {
                h = std::stod(text, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            if (used != text.size() || !(h > 0.0) || !std::isfinite(h))
                throw InvalidArgumentError("expected a length > 0 in the input's units");
            return h;
        });
    }
    if (!(a.padding >= 0.0) || !std::isfinite(a.padding)) {
        throw InvalidArgumentError("--padding " + std::to_string(a.padding) +
                                   ": expected a depth >= 0 (a fraction of the boundary edge "
                                   "length; 0: no padding layer)");
    }
    plan.meshing.padding = a.padding;
    plan.meshing.polycube.bound = plan.polycube.bound;
    plan.meshing.polycube.max_time = plan.polycube.max_time;
    plan.meshing.polycube.threads = plan.polycube.threads;
    if (!a.vtu.empty() && extension(a.vtu) != ".vtu" && extension(a.vtu) != ".vtk")
        throw InvalidArgumentError("--vtu " + a.vtu + ": expected a .vtu or .vtk file");
    if (!a.report.empty() && extension(a.report) != ".json")
        throw InvalidArgumentError("--report " + a.report + ": expected a .json file");
    plan.out = a.out;
    plan.vtu = a.vtu;
    plan.report = a.report;
    plan.quiet = a.polycube.quiet;
    return plan;
}

nlohmann::json quantization_json(const PlaneQuantization& q) {
    return {{"cell", q.cell},
            {"planes_per_axis", q.planes},
            {"grid_positions_per_axis", q.distinct_positions},
            {"cells_per_axis", q.extent},
            {"raised_planes", q.raised}};
}

nlohmann::json hex_verification_json(const HexVerification& v) {
    return {{"passed", v.passed},
            {"hexes", v.hexes},
            {"vertices", v.vertices},
            {"inverted", v.quality.inverted},
            {"scaled_jacobian",
             {{"min", v.quality.min_scaled_jacobian},
              {"mean", v.quality.mean_scaled_jacobian},
              {"histogram_bins", "(-inf,0], (0,0.1], ..., (0.9,1]"},
              {"histogram", v.quality.histogram}}},
            {"boundary_faces", v.boundary_faces},
            {"boundary_closed", v.open_boundary_edges == 0 && v.faces_in_more_than_two_hexes == 0},
            {"open_boundary_edges", v.open_boundary_edges},
            {"distance_to_input", v.distance_to_input},
            {"distance_from_input", v.distance_from_input},
            {"distance_unit", "input bounding-box diagonal"},
            {"volume_ratio", v.volume_ratio},
            {"summary", v.summary}};
}

nlohmann::json polycube_solve_json(const PolycubeSolve& s) {
    return {{"success", s.success},
            {"message", s.message},
            {"verification", polycube_verification_json(s.verification)},
            {"times",
             {{"cube_cover", s.cube_cover_seconds},
              {"untangle", s.untangle_seconds},
              {"solve", s.solve_seconds},
              {"verify", s.verify_seconds}}}};
}

}  // namespace

int run_hex_command(const HexArguments& arguments) {
    Stopwatch total;
    const HexPlan plan = check_hex_arguments(arguments);
    OutputPlan outputs(arguments.polycube.force);
    outputs.input("--mesh", plan.polycube.mesh);
    outputs.input("--labels", arguments.polycube.labels);
    outputs.input("--label-surface", arguments.polycube.label_surface);
    outputs.file("--out", plan.out);
    outputs.file("--polycube", plan.polycube.out);
    outputs.file("--polycube (rest mesh)", plan.polycube.rest);
    outputs.file("--polycube (flags)", plan.polycube.flags);
    outputs.file("--vtu", plan.vtu);
    PictureOutput picture(arguments.png, arguments.no_png, plan.out, plan.polycube.max_time);
    picture.plan(outputs);
    outputs.file("--report", plan.report);
    outputs.check();
    const Logger logger = stderr_logger(plan.quiet);

    set_activity("reading --mesh " + plan.polycube.mesh);
    const PreparedPolycube prepared = read_polycube_input(plan.polycube, logger);
    std::cout << "sa hex: " << prepared.input.num_simplices() << " tetrahedra ("
              << prepared.mesh.num_simplices() << " after the splits), " << prepared.charts.size()
              << " charts, labels " << prepared.label_source << " (" << plan.polycube.mesh << ")\n";
    set_activity("hex meshing (" + std::to_string(prepared.mesh.num_simplices()) + " tetrahedra)");
    const HexMeshing result = hex_mesh_from_polycube(prepared, plan.meshing, logger);
    const bool extracted = result.outcome == HexOutcome::kVerified ||
                           result.outcome == HexOutcome::kHexMeshNotVerified;

    set_activity("writing the outputs");
    auto write = [&](const std::string& path, const auto& writer) {
        if (!path.empty()) outputs.write(path, writer);
    };
    if (extracted) {
        write(plan.out, [&](const std::string& path) { write_hex_medit(path, result.output()); });
        write(plan.vtu, [&](const std::string& path) {
            write_hex_vtu(path, result.output(), result.verification.quality);
        });
    }
    if (result.grid_polycube.success) {
        // The PolyCube on the grid, in grid units: its planes at integers.
        write(plan.polycube.out, [&](const std::string& path) {
            write_medit(path, result.grid_polycube.positions, prepared.mesh.simplices);
        });
        write(plan.polycube.rest, [&](const std::string& path) {
            write_medit(path, prepared.rest_positions(), prepared.mesh.simplices);
        });
        write(plan.polycube.flags,
              [&](const std::string& path) { write_facet_flags(path, prepared.output_flags()); });
    }
    if (!plan.report.empty()) {
        nlohmann::json report;
        report["command"] = "hex";
        report["success"] = result.success();
        report["outcome"] = to_string(result.outcome);
        report["message"] = result.message;
        report["preparation"] = polycube_preparation_json(prepared);
        report["polycube"] = polycube_solve_json(result.polycube);
        if (result.outcome != HexOutcome::kPolycubeFailed) {
            report["quantization"] = quantization_json(result.quantization);
            report["grid_polycube"] = polycube_solve_json(result.grid_polycube);
        }
        if (extracted) {
            report["extraction"] = {
                {"cells_with_missing_corners", result.extraction.cells_with_missing_corners},
                {"scaled_jacobian",
                 {{"min", result.extracted_quality.min_scaled_jacobian},
                  {"mean", result.extracted_quality.mean_scaled_jacobian}}}};
            report["padding"] = {{"locked_inverted_corners", result.locked_inverted_corners},
                                 {"added_hexes", result.padding_hexes}};
            report["optimization"] = {{"ran", result.optimization.ran},
                                      {"free_vertices", result.optimization.free_vertices},
                                      {"sliding_vertices", result.optimization.sliding_vertices},
                                      {"rounds", result.optimization.rounds},
                                      {"newton_steps", result.optimization.newton_steps},
                                      {"message", result.optimization.message}};
            report["verification"] = hex_verification_json(result.verification);
        }
        report["times"] = {{"polycube", result.polycube_seconds},
                           {"quantization", result.quantization_seconds},
                           {"grid_polycube", result.grid_polycube_seconds},
                           {"extraction", result.extraction_seconds},
                           {"padding", result.padding_seconds},
                           {"optimization", result.optimization_seconds},
                           {"verification", result.verification_seconds},
                           {"total", total.seconds()}};
        report["peak_memory_gb"] = peak_memory_gb();
        write(plan.report, [&](const std::string& path) { write_json(path, report); });
    }
    if (extracted) {
        picture.draw(outputs, [&](const std::string& path) {
            write_hex_png(
                path, result.output(), result.verification.quality,
                std::string("hex mesh, ") + (result.success() ? "verified" : "NOT verified"));
        });
    }
    std::ostringstream summary;
    summary << result.message << "\n"
            << "time " << total.seconds() << " s (PolyCube " << result.polycube_seconds
            << " s, on the grid " << result.grid_polycube_seconds << " s)\n";
    if (extracted || !plan.report.empty()) {
        summary << "wrote" << (extracted ? " " + plan.out : std::string())
                << (extracted && !plan.vtu.empty() ? ", " + plan.vtu : std::string())
                << (result.grid_polycube.success && !plan.polycube.out.empty()
                        ? ", " + plan.polycube.out + ", " + plan.polycube.rest + ", " +
                              plan.polycube.flags
                        : std::string())
                << picture.wrote() << (plan.report.empty() ? "" : ", " + plan.report) << "\n";
    }
    outputs.commit(summary.str());
    picture.warn(std::cerr);
    return result.success() ? kExitVerified : kExitNotVerified;
}

}  // namespace sa::cli
