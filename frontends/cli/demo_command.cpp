#include "frontends/cli/demo_command.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "frontends/cli/cli_support.h"
#include "frontends/cli/output_plan.h"
#include "frontends/output/layout_picture.h"
#include "frontends/output/map_output.h"
#include "frontends/simplex_assembly/map_solve.h"
#include "geometry/io/vtk_io.h"
#include "geometry/maps/harmonic_map.h"
#include "geometry/mesh/mesh_generators.h"
#include "geometry/quality/map_quality.h"
#include "optim/errors.h"

namespace sa::cli {

namespace {

/// An eight-pointed star (outer radius 1, inner 0.5), counter-clockwise from the tip at -135
/// degrees. By arc length the square's corners land on every other tip: a triangle with all three
/// vertices on the boundary (the grid has two, at corners) can only keep its orientation at a
/// convex corner of the polygon.
Eigen::MatrixXd star() {
    const int points = 8;
    Eigen::MatrixXd p(2 * points, 2);
    for (int k = 0; k < 2 * points; ++k) {
        const double r = k % 2 == 0 ? 1.0 : 0.5, angle = -0.75 * M_PI + M_PI * k / points;
        p.row(k) << r * std::cos(angle), r * std::sin(angle);
    }
    return p;
}

/// The point at arc-length fraction t in [0, 1) along the closed polygon.
Eigen::RowVector2d along(const Eigen::MatrixXd& polygon, double t) {
    const Index n = polygon.rows();
    std::vector<double> length(n + 1, 0.0);
    for (Index k = 0; k < n; ++k)
        length[k + 1] = length[k] + (polygon.row((k + 1) % n) - polygon.row(k)).norm();
    double s = t * length[n];
    for (Index k = 0; k < n; ++k) {
        if (s <= length[k + 1]) {
            const double u = (s - length[k]) / (length[k + 1] - length[k]);
            return (1 - u) * polygon.row(k) + u * polygon.row((k + 1) % n);
        }
    }
    return polygon.row(0);
}

}  // namespace

int run_demo_command(const DemoArguments& a) {
    std::optional<Initialization> initialization;
    if (!a.initialization.empty())
        initialization = parse_option("--initialization", a.initialization, parse_initialization);
    const int n = a.size;
    const std::string initial_path = (std::filesystem::path(a.out_dir) / "initial.vtu").string();
    const std::string unbounded_path =
        (std::filesystem::path(a.out_dir) / "conformal_unbounded.vtu").string();
    const std::string bounded_path =
        (std::filesystem::path(a.out_dir) / "conformal_bound4.vtu").string();
    const std::vector<std::string> vtus = {initial_path, unbounded_path, bounded_path};
    std::vector<std::string> pngs;
    if (!a.no_png)
        for (const std::string& vtu : vtus) pngs.push_back(with_extension(vtu, ".png"));
    OutputPlan plan(a.force);
    plan.folder("--out-dir", a.out_dir);
    for (const std::string& path : vtus) plan.file("--out-dir", path);
    for (const std::string& path : pngs) plan.file("--out-dir", path);
    plan.check();
    plan.open_folders();

    // The square's boundary, counter-clockwise from (0, 0), onto the star by arc length.
    MappingProblem problem;
    problem.source = "demo";
    problem.mesh = grid_triangles(n, n);
    std::vector<Index> loop;
    for (int i = 0; i < n; ++i) loop.push_back(i);                // bottom
    for (int j = 0; j < n; ++j) loop.push_back(j * (n + 1) + n);  // right
    for (int i = n; i > 0; --i) loop.push_back(n * (n + 1) + i);  // top
    for (int j = n; j > 0; --j) loop.push_back(j * (n + 1));      // left
    const Eigen::MatrixXd polygon = star();
    Eigen::MatrixXd boundary(loop.size(), 2);
    for (std::size_t k = 0; k < loop.size(); ++k)
        boundary.row(k) = along(polygon, double(k) / loop.size());
    problem.handles = loop;
    problem.initial = harmonic_map(problem.mesh, loop, boundary, LaplacianWeights::kCotangent);

    const RestFrames<2> frames = rest_frames<2>(problem.mesh);
    const MapQuality initial =
        map_quality<2>(linear_parts<2>(problem.mesh, frames, problem.initial), frames.volume);
    plan.write(initial_path, [&](const std::string& path) {
        write_vtu(path, problem.initial, problem.mesh.simplices, {}, quality_cell_data(initial));
    });

    std::cout << "sa demo: a " << n << "x" << n << " square grid (" << problem.mesh.num_simplices()
              << " triangles) mapped onto an eight-pointed star; harmonic initial map with "
              << initial.inverted << " foldovers\n";
    SimplexAssemblyOptions options;
    options.num_threads = a.threads;
    options.initialization = initialization;
    SimplexAssemblyObserver observer;
    observer.logger = stderr_logger(a.quiet);
    std::printf(
        "\n| K_conf | foldovers before | foldovers after | conformal max | conformal avg | "
        "iterations | time (s) | verified |\n"
        "|---:|---:|---:|---:|---:|---:|---:|:---|\n");
    std::fflush(stdout);
    bool all = true;
    std::vector<MapQuality> qualities = {initial};
    std::vector<Eigen::MatrixXd> layouts = {problem.initial};
    for (const auto& [bound, path] :
         {std::pair{kInfinity, unbounded_path}, std::pair{4.0, bounded_path}}) {
        options.bound = bound;
        const SimplexAssemblyResult r = run_simplex_assembly(problem, options, observer);
        plan.write(path, [&](const std::string& staged) { write_map_result(staged, problem, r); });
        std::printf("| %s | %ld | %ld | %.3f | %.3f | %d | %.2f | %s |\n",
                    bound < kInfinity ? "4" : "inf", long(r.initial_quality.inverted),
                    long(r.final_quality.inverted), r.final_quality.conformal.max,
                    r.final_quality.conformal.mean,
                    r.newton.num_steps() + r.vertex_stage.num_steps(), r.times.total,
                    r.success ? "yes" : "NO");
        std::fflush(stdout);
        if (!r.success) std::cerr << "sa demo: " << r.message << '\n';
        all = all && r.success;
        qualities.push_back(r.final_quality);
        layouts.push_back(r.positions);
    }
    // The pictures, in one colour range: the largest conformal distortion of the results.
    std::string pictures;
    if (!pngs.empty()) {
        LayoutPicture picture;
        picture.size = 800;
        picture.value_name = "conformal distortion (sigma max / sigma min)";
        picture.high = std::max(
            1.1, std::min(10.0, std::max(qualities[1].conformal.max, qualities[2].conformal.max)));
        const char* names[3] = {"harmonic initial map", "K_conf = inf", "K_conf = 4"};
        try {
            for (std::size_t k = 0; k < pngs.size(); ++k) {
                const MapQuality& q = qualities[k];
                Eigen::VectorXd values(q.simplices);
                std::vector<unsigned char> red(q.simplices);
                for (Index f = 0; f < q.simplices; ++f) {
                    values[f] = q.per_simplex[f].conformal;
                    red[f] = q.per_simplex[f].inverted || q.per_simplex[f].degenerate;
                }
                char title[200];
                std::snprintf(title, sizeof title, "%s: %ld foldovers; conformal max %.3g",
                              names[k], long(q.inverted), q.conformal.max);
                picture.title = title;
                plan.write(pngs[k], [&](const std::string& path) {
                    write_layout_png(path, layouts[k], problem.mesh.simplices, values, picture,
                                     red);
                });
                pictures += (k ? ", " : "") + pngs[k];
            }
        } catch (const Error& e) {
            std::cerr << "sa: warning: a picture was not drawn: " << one_line(e.what()) << '\n';
        }
    }
    plan.commit(
        "\nconformal = sigma_max / sigma_min per triangle; verified = no inverted or degenerate "
        "triangle, every boundary vertex on the star and, for K_conf = 4, the bounded distortion "
        "(sigma_max / sigma_min + sigma_min / sigma_max) / 2 at most 4 on every triangle, "
        "measured on the output positions.\nwrote " +
        initial_path + ", " + unbounded_path + ", " + bounded_path +
        " (cell data: det_J, conformal, isometric, volumetric, inverted)\n" +
        (pictures.empty() ? "" : "wrote " + pictures + "\n"));
    return all ? kExitVerified : kExitNotVerified;
}

}  // namespace sa::cli
