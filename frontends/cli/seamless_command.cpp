#include "frontends/cli/seamless_command.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "frontends/cli/cli_support.h"
#include "frontends/cli/out_of_memory.h"
#include "frontends/cli/output_plan.h"
#include "frontends/output/checkerboard_picture.h"
#include "frontends/output/map_output.h"
#include "frontends/output/map_report.h"
#include "frontends/seamless/frame_field.h"
#include "frontends/seamless/seamless_parameterization.h"
#include "geometry/io/frame_field_io.h"
#include "geometry/io/mesh_file.h"
#include "geometry/io/obj_io.h"
#include "geometry/io/vtk_io.h"
#include "geometry/mesh/mesh_topology.h"
#include "optim/errors.h"
#include "optim/stopwatch.h"

namespace sa {
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SeamlessResult::Times, field, cut, plain_poisson, integrable,
                                   poisson, verification, total)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(FieldRepairAttempt, rings, smoothing_steps, region_faces,
                                   vertices_moved, largest_move, inverted, degenerate, assembled,
                                   singularities_kept, success, time)
}  // namespace sa

namespace sa::cli {

namespace {

/// The cut mesh in space with (u, v), the fields, curls and distortion: for ParaView.
void write_seamless_vtu(const std::string& path, const SimplicialMesh& mesh,
                        const SeamlessResult& r) {
    const CutMesh& cut = r.result.map.cut;
    const Index nc = cut.mesh.num_vertices(), nf = mesh.num_simplices();
    Eigen::MatrixXd positions(nc, 3), uv = Eigen::MatrixXd::Zero(nc, 3),
                                      singularity = Eigen::MatrixXd::Zero(nc, 1);
    for (Index c = 0; c < nc; ++c) {
        positions.row(c) = mesh.point(cut.original_vertex[c]).transpose();
        uv.row(c).head<2>() = r.result.map.uv.row(c);
    }
    std::vector<double> index(mesh.num_vertices(), 0.0);
    for (const Singularity& s : r.singularities_after) index[s.vertex] = s.index;
    for (Index c = 0; c < nc; ++c) singularity(c, 0) = index[cut.original_vertex[c]];
    const RestFrames<2> frames = rest_frames<2>(r.surface);
    const auto [u_before, v_before] = frame_vectors(frames, r.field_before);
    const auto [u_after, v_after] = frame_vectors(frames, r.field_after);
    std::vector<DataArray> cells = quality_cell_data(r.result.quality);
    cells.push_back({"field_u", u_after});
    cells.push_back({"field_v", v_after});
    cells.push_back({"input_field_u", u_before});
    cells.push_back({"input_field_v", v_before});
    cells.push_back({"curl_before", r.face_curl_before});
    cells.push_back({"curl_after", r.face_curl_after});
    Eigen::MatrixXd turns(nf, 1);
    for (Index f = 0; f < nf; ++f) turns(f, 0) = r.result.map.chart_turns[f];
    cells.push_back({"chart_quarter_turns", turns, true});
    write_vtu(path, positions, cut.mesh.simplices, {{"uv", uv}, {"singularity_index", singularity}},
              cells);
}

nlohmann::json singularities_json(const std::vector<Singularity>& list) {
    nlohmann::json out = nlohmann::json::array();
    for (const Singularity& s : list) out.push_back({{"vertex", s.vertex}, {"index", s.index}});
    return out;
}

nlohmann::json verified_json(const VerifiedSeamlessMap& m) {
    return {{"quality", quality_json(m.quality)},
            {"max_seam_mismatch", m.map.max_seam_mismatch},
            {"cut_vertices", m.map.cut.mesh.num_vertices()}};
}

}  // namespace

int run_seamless_command(const SeamlessArguments& a) {
    Stopwatch total, stage;
    if (extension(a.out) != ".obj")
        throw InvalidArgumentError(a.out + ": the seamless map is written as .obj (vt per corner)");
    if (!a.field.empty() && !a.constraints.empty())
        throw InvalidArgumentError("give --field or --constraints, not both");
    const std::string vtu = a.no_vtu ? "" : a.vtu.empty() ? with_extension(a.out, ".vtu") : a.vtu;
    PictureOutput picture(a.png, a.no_png, a.out, a.max_time);
    if (!vtu.empty() && extension(vtu) != ".vtu")
        throw InvalidArgumentError(vtu + ": --vtu takes a .vtu file");
    OutputPlan plan(a.force);
    plan.input("--mesh", a.mesh);
    plan.input("--field", a.field);
    for (const std::string& constraint : a.constraints) plan.input("--constraints", constraint);
    plan.file("--out", a.out);
    plan.file(a.vtu.empty() ? "--vtu (from --out)" : "--vtu", vtu);
    picture.plan(plan);
    plan.file("--report", a.report);
    plan.check();
    SeamlessOptions options;
    options.scale = a.scale;
    options.integrable.mu = a.mu;
    options.integrable.num_threads = a.threads;
    options.integrable.max_iterations = a.max_iterations;
    if (!(a.max_time > 0.0))
        throw InvalidArgumentError("--max-time " + std::to_string(a.max_time) + ": expected > 0");
    options.integrable.max_time_seconds = a.max_time;

    const MeshFile file = read_input_mesh("--mesh", a.mesh, "seamless parameterization");
    const SimplicialMesh& mesh = file.mesh;
    // The checks the pipeline makes, here with the file's name: a valid, manifold, unpinched and
    // consistently oriented surface.
    validate_mesh(mesh, a.mesh);
    require_no_pinched_vertex(mesh, mesh_topology(mesh, a.mesh), a.mesh, kSeamlessSurface);
    std::optional<FrameFieldInput> field;
    std::string field_layout;
    if (!a.field.empty() || !a.constraints.empty()) {
        set_activity("reading the field");
        const FrameFieldFile f = a.field.empty()
                                     ? read_frame_field_constraints(
                                           a.constraints[0], a.constraints[1], mesh.num_simplices())
                                     : read_frame_field(a.field, mesh.num_simplices());
        field_layout = f.layout;
        field = FrameFieldInput{f.u, f.v, f.given};
        if (std::find(f.given.begin(), f.given.end(), 0) == f.given.end()) field->given.clear();
    }
    const double read_time = stage.lap();
    std::cout << "sa seamless: " << mesh.num_simplices() << " triangles, " << mesh.num_vertices()
              << " vertices (" << a.mesh << ")"
              << (field_layout.empty() ? "" : ", field: " + field_layout) << "\n";
    set_activity("solving (a seamless parameterization of " + std::to_string(mesh.num_simplices()) +
                 " triangles)");
    const SeamlessResult r =
        seamless_parameterization(mesh, field, options, stderr_logger(a.quiet));
    stage.lap();
    // What every report says of the input and its field.
    nlohmann::json report = {
        {"command", "seamless"},
        {"mesh", a.mesh},
        {"faces", mesh.num_simplices()},
        {"vertices", mesh.num_vertices()},
        {"field", a.field.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.field)},
        {"field_source", r.field_source},
        {"field_layout", field_layout},
        {"singularities_before", singularities_json(r.singularities_before)}};
    if (!r.infeasible.empty()) {
        // Diagnosed before optimizing: no map is written.
        if (!a.report.empty()) {
            report.update({{"infeasible", {{"description", r.infeasible}}},
                           {"success", false},
                           {"message", r.message},
                           {"times", {{"read", read_time}, {"total", total.seconds()}}}});
            plan.write(a.report, [&](const std::string& path) { write_json(path, report); });
        }
        plan.commit("  " + r.message + (a.report.empty() ? "" : "\n  wrote " + a.report) + "\n");
        return kExitNotVerified;
    }

    set_activity("writing the outputs");
    const CutMesh& cut = r.result.map.cut;
    Eigen::MatrixXd positions = mesh.vertices;
    plan.write(a.out, [&](const std::string& path) {
        write_obj(path, positions, mesh.simplices, &r.result.map.uv, &cut.mesh.simplices);
    });
    if (!vtu.empty())
        plan.write(vtu, [&](const std::string& path) { write_seamless_vtu(path, mesh, r); });
    if (!picture.path().empty()) {
        Eigen::MatrixXd cut_positions(cut.mesh.num_vertices(), mesh.vertices.cols());
        for (Index c = 0; c < cut.mesh.num_vertices(); ++c)
            cut_positions.row(c) = mesh.vertices.row(cut.original_vertex[c]);
        CheckerboardPicture checkerboard;
        char title[256];
        std::snprintf(title, sizeof title, "%s: %ld faces, %zu singularities, %ld foldovers%s",
                      std::filesystem::path(a.mesh).filename().c_str(), long(mesh.num_simplices()),
                      r.singularities_after.size(), long(r.result.quality.inverted),
                      r.success ? "" : " (FAILED)");
        checkerboard.title = title;
        picture.draw(plan, [&](const std::string& path) {
            write_checkerboard_png(path, cut_positions, cut.mesh.simplices, r.result.map.uv,
                                   checkerboard);
        });
    }
    const double output_time = stage.lap();
    if (!a.report.empty()) {
        const IntegrableField& in = r.integrable;
        nlohmann::json iterations = nlohmann::json::array();
        for (const IterationRecord& it : in.newton.iterations) {
            iterations.push_back({{"iteration", it.iteration},
                                  {"energy", it.energy},
                                  {"step", it.step_length},
                                  {"time", it.cumulative_time}});
        }
        const nlohmann::json repair = {{"ran", r.repair.ran},
                                       {"success", r.repair.success},
                                       {"folded_faces", r.repair.folded_faces},
                                       {"description", r.repair.describe()},
                                       {"attempts", r.repair.attempts}};
        report.update(
            {{"local_repair", repair},
             {"options",
              {{"scale", r.scale},
               {"mu", options.integrable.mu},
               {"assembly_tolerance", options.integrable.assembly_tolerance},
               {"seam_tolerance", options.seam_tolerance},
               {"max_iterations", options.integrable.max_iterations},
               {"max_time_seconds", std::isfinite(options.integrable.max_time_seconds)
                                        ? nlohmann::json(options.integrable.max_time_seconds)
                                        : nlohmann::json(nullptr)}}},
             {"singularities_after", singularities_json(r.singularities_after)},
             {"singularities_kept", r.singularities_kept},
             {"matchings_kept", r.matchings_kept},
             {"cut_edges", r.cut_edges},
             {"curl_before",
              {{"max", r.curl_stats_before.max}, {"mean", r.curl_stats_before.mean}}},
             {"curl_after", {{"max", r.curl_stats_after.max}, {"mean", r.curl_stats_after.mean}}},
             {"integrable",
              {{"assembled", in.assembled},
               {"sum_curl_squared", in.assembly},
               {"termination", to_string(in.newton.termination)},
               {"iterations", iterations}}},
             {"plain_poisson", verified_json(r.plain)},
             {"result", verified_json(r.result)},
             {"success", r.success},
             {"message", r.message},
             {"peak_memory_gb", peak_memory_gb()}});
        nlohmann::json& times = report["times"] = r.times;  // the pipeline's, then the command's
        times["read"] = read_time;
        times["output"] = output_time;
        times["total"] = total.seconds();
        plan.write(a.report, [&](const std::string& path) { write_json(path, report); });
    }
    std::ostringstream singular;  // the first few, "vertex (index)"
    for (std::size_t i = 0; i < r.singularities_before.size() && i < 8; ++i) {
        singular << (i ? ", " : " at vertices ") << r.singularities_before[i].vertex << " ("
                 << r.singularities_before[i].index << ")";
    }
    if (r.singularities_before.size() > 8) singular << ", ...";
    char line[768];
    std::snprintf(line, sizeof line,
                  "  field: %s; %zu singularities%s, %ld cut edges\n"
                  "  edge curl (relative): max %.3g mean %.3g -> max %.3g mean %.3g "
                  "(%d Simplex Assembly iterations)\n"
                  "  Poisson map of the input field: %ld foldovers; ours: %ld foldovers, seam "
                  "mismatch %.3g, conformal distortion max %.4g mean %.4g\n"
                  "  time %.2f s (read %.2f, field %.2f, Simplex Assembly %.2f, Poisson %.2f, "
                  "output %.2f); peak memory %.2f GB\n",
                  r.field_source.c_str(), r.singularities_before.size(), singular.str().c_str(),
                  long(r.cut_edges), r.curl_stats_before.max, r.curl_stats_before.mean,
                  r.curl_stats_after.max, r.curl_stats_after.mean, r.integrable.newton.num_steps(),
                  long(r.plain.quality.inverted), long(r.result.quality.inverted),
                  r.result.map.max_seam_mismatch, r.result.quality.conformal.max,
                  r.result.quality.conformal.mean, total.seconds(), read_time, r.times.field,
                  r.times.integrable, r.times.poisson, output_time, peak_memory_gb());
    plan.commit(line + ("  " + r.message) + "\n  wrote " + a.out + (vtu.empty() ? "" : ", " + vtu) +
                picture.wrote() + (a.report.empty() ? "" : ", " + a.report) + "\n");
    picture.warn(std::cerr);
    return r.success ? kExitVerified : kExitNotVerified;
}

}  // namespace sa::cli
