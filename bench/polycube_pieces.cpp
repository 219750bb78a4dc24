// The pieces of `sa polycube` that exist before the solve (issue 21), on one mesh: the labels
// (read, transferred or computed and cleaned), the splits, the cube-cover start and its
// verification, with the time of each stage. Prints one JSON object on stdout; with --out, also
// writes the cube-cover start as the command will write its map (OUT.mesh, OUT.rest.mesh,
// OUT.flags, and --vtu / --png).
//
//   bench_polycube_pieces --mesh ../shared/data/polycube/robustPolycube/B0.mesh
//   bench_polycube_pieces --mesh S1.mesh --flags S1.flags --out /tmp/S1-start.mesh --png s.png

#include <CLI/CLI.hpp>
#include <iostream>
#include <nlohmann/json.hpp>

#include "frontends/polycube/cube_cover.h"
#include "frontends/polycube/polycube_output.h"
#include "frontends/polycube/polycube_preparation.h"
#include "geometry/io/mesh_file.h"
#include "optim/errors.h"
#include "optim/stopwatch.h"

int main(int argc, char** argv) {
    std::string mesh_path, out, vtu, png;
    sa::PolycubeLabelInput input;
    CLI::App app("PolyCube pieces before the solve: labels, splits, cube-cover start");
    app.add_option("--mesh", mesh_path, "tetrahedral mesh")->required();
    app.add_option("--flags", input.flags, "labels per tet facet (.flags)");
    app.add_option("--labels", input.labels, "labels per triangle of --surface");
    app.add_option("--surface", input.surface, "the boundary surface of --labels");
    app.add_option("--out", out, "write the cube-cover start as OUT.mesh (+ .rest.mesh, .flags)");
    app.add_option("--vtu", vtu, "write the cube-cover start's .vtu");
    app.add_option("--png", png, "write a picture of the cube-cover start");
    CLI11_PARSE(app, argc, argv);
    try {
        sa::Stopwatch stage;
        const sa::SimplicialMesh mesh = sa::read_mesh_file(mesh_path).mesh;
        const double read = stage.lap();
        const sa::PreparedPolycube p = sa::prepare_polycube(
            mesh, mesh_path, input, [](const std::string& line) { std::cerr << line << '\n'; });
        const double prepare = stage.lap();
        const sa::CubeCover cover = sa::cube_cover_map(p.mesh, p.boundary, p.charts);
        const double cube_cover = stage.lap();
        const sa::PolycubeVerification v =
            sa::verify_polycube(p.layout(), cover.positions, p.input_volume);
        const double verify = stage.lap();

        nlohmann::json j;
        j["mesh"] = mesh_path;
        j["tets"] = mesh.num_simplices();
        j["labels"] = p.label_source;
        if (p.convention) j["convention"] = p.convention->describe();
        if (p.cleanup) {
            j["cleanup"] = {{"charts_before", p.cleanup->charts_before},
                            {"charts_after", p.cleanup->charts_after},
                            {"triangles_changed", p.cleanup->triangles_changed},
                            {"small", p.cleanup->merged_small},
                            {"few_neighbours", p.cleanup->merged_few_neighbours},
                            {"opposite", p.cleanup->merged_opposite}};
        }
        j["charts"] = p.charts.size();
        j["non_monotone_boundaries"] = p.non_monotone.size();
        const sa::SquashedElements& s = p.splits.before;
        j["squashed"] = {{"tets", s.tets},
                         {"interior_edges", s.interior_edges},
                         {"boundary_edges", s.boundary_edges},
                         {"boundary_triangles", s.boundary_triangles},
                         {"flattened_tets", s.flattened_tets}};
        j["splits"] = {{"edge", p.splits.edge_splits},
                       {"face", p.splits.face_splits},
                       {"tets_after", p.mesh.num_simplices()}};
        j["cube_cover"] = {{"inverted", v.quality.inverted},
                           {"degenerate", v.quality.degenerate},
                           {"delta_con_max", v.quality.conformal.max},
                           {"delta_con_mean", v.quality.conformal.mean},
                           {"delta_iso_max", v.quality.isometric.max},
                           {"max_planarity", v.max_planarity},
                           {"zero_length_edges", v.zero_length_edges},
                           {"edge_angle_violations", v.edge_angle_violations},
                           {"vertex_angle_violations", v.vertex_angle_violations},
                           {"verified", v.passed}};
        j["seconds"] = {
            {"read", read},       {"labels", p.read_labels_seconds}, {"splits", p.splits_seconds},
            {"prepare", prepare}, {"cube_cover", cube_cover},        {"verify", verify}};
        if (!out.empty()) sa::write_polycube_meshes(out, p, cover.positions);
        if (!vtu.empty()) sa::write_polycube_vtu(vtu, p, cover.positions, v);
        if (!png.empty()) {
            sa::write_polycube_png(png, p, cover.positions, v, "cube-cover start");
        }
        std::cout << j.dump() << '\n';
    } catch (const sa::Error& e) {
        std::cerr << "bench_polycube_pieces: " << e.what() << '\n';
        return 2;
    }
    return 0;
}
