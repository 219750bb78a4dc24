// A user's program on the installed front-ends: a grid with folded triangles repaired by Simplex
// Assembly, written as VTU (through the installed VTK plugin) and PNG (the picture plugin).
// Exits 0 when the map is verified inversion-free, its stages are recorded and both files are
// written.
#include <filesystem>
#include <iostream>

#include "frontends/output/layout_picture.h"
#include "frontends/output/map_output.h"
#include "frontends/simplex_assembly/map_solve.h"
#include "geometry/mesh/mesh_generators.h"

int main(int argc, char** argv) {
    const std::filesystem::path out = argc > 1 ? argv[1] : "fold_repair_out";
    std::filesystem::create_directories(out);
    sa::MappingProblem problem;
    problem.source = "consumer";
    problem.mesh = sa::grid_triangles(6, 6);
    problem.initial = problem.mesh.vertices.leftCols(2);
    for (sa::Index v = 0; v < problem.mesh.num_vertices(); ++v) {
        const double px = problem.initial(v, 0), py = problem.initial(v, 1);
        if (px == 0.0 || px == 1.0 || py == 0.0 || py == 1.0) problem.handles.push_back(v);
    }
    problem.initial.row(3 * 7 + 3) << 0.9, 0.9;  // an interior vertex pulled across others

    const sa::SimplexAssemblyResult result = sa::run_simplex_assembly(problem, {});
    std::cout << "inverted before " << result.initial_quality.inverted << ", after "
              << result.final_quality.inverted << ": " << result.message << '\n';
    for (const sa::StageRecord& stage : result.stages.records)
        std::cout << "  " << sa::to_string(stage.stage) << ": " << sa::to_string(stage.outcome)
                  << '\n';
    const std::string vtu = (out / "map.vtu").string(), png = (out / "map.png").string();
    sa::write_map_result(vtu, problem, result);
    Eigen::VectorXd values(problem.mesh.num_simplices());
    for (sa::Index f = 0; f < values.size(); ++f)
        values[f] = result.final_quality.per_simplex[f].conformal;
    sa::write_layout_png(png, result.positions, problem.mesh.simplices, values, {});
    const bool written = std::filesystem::file_size(vtu) > 0 && std::filesystem::file_size(png) > 0;
    return result.success && result.initial_quality.inverted > 0 &&
                   !result.stages.records.empty() && written
               ? 0
               : 1;
}
