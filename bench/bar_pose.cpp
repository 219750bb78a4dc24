// Writes the paper's Figure 16 experiment (tests/fixtures/bar_deformation.h) as the files `sa
// deform` reads: the rest bar as PREFIX.mesh (Medit) and its handles' targets as PREFIX_targets.txt
// (rows `index x y z`); for ../shared/tools/check_map.py also the handles as PREFIX_handles.txt
// and the rest shape with the handles at their targets as PREFIX_posed_handles.mesh. For
// bench/deform_benchmarks.py:
//
//   bench_bar_pose --pose twist --prefix /tmp/bar-twist
//   sa deform --rest /tmp/bar-twist.mesh --targets /tmp/bar-twist_targets.txt --out posed.vtu
//
// Prints one line: the case's name, tetrahedra, vertices and handles.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <fstream>
#include <iomanip>

#include "geometry/io/mesh_file.h"
#include "optim/errors.h"
#include "tests/fixtures/bar_deformation.h"

int main(int argc, char** argv) {
    CLI::App app("The Figure 16 bar, posed by its handle slabs, as files for sa deform");
    std::string pose = "bend", prefix;
    sa::BarDeformationOptions options;
    app.add_option("--pose", pose, "bend, twist, translate or bend-twist")->capture_default_str();
    app.add_option("--prefix", prefix, "writes PREFIX.mesh and PREFIX_targets.txt")->required();
    app.add_option("--length-cells", options.length_cells)->capture_default_str();
    app.add_option("--cross-cells", options.cross_cells)->capture_default_str();
    app.add_option("--length", options.length, "the bar's length (its width is 1)")
        ->capture_default_str();
    app.add_option("--bend-degrees", options.bend_degrees)->capture_default_str();
    app.add_option("--twist-degrees", options.twist_degrees)->capture_default_str();
    app.add_option("--shift", options.shift, "the translation, in bar widths")
        ->capture_default_str();
    app.add_option("--slab", options.slab, "handles within slab * length of either end")
        ->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    try {
        const sa::BarDeformation bar = sa::bar_deformation(sa::parse_bar_pose(pose), options);
        sa::write_mesh_file(prefix + ".mesh", bar.mesh.vertices, bar.mesh.simplices);
        const std::string targets = prefix + "_targets.txt";
        std::ofstream f(targets);
        f << std::setprecision(17);
        for (std::size_t k = 0; k < bar.handles.size(); ++k) {
            f << bar.handles[k];
            for (int c = 0; c < 3; ++c) f << ' ' << bar.targets(sa::Index(k), c);
            f << '\n';
        }
        if (!f.flush()) throw sa::InputError(targets + ": cannot write");
        std::ofstream h(prefix + "_handles.txt");
        for (sa::Index v : bar.handles) h << v << '\n';
        if (!h.flush()) throw sa::InputError(prefix + "_handles.txt: cannot write");
        Eigen::MatrixXd moved = bar.mesh.vertices;
        for (std::size_t k = 0; k < bar.handles.size(); ++k)
            moved.row(bar.handles[k]) = bar.targets.row(sa::Index(k));
        sa::write_mesh_file(prefix + "_posed_handles.mesh", moved, bar.mesh.simplices);
        std::printf("%s: %ld tetrahedra, %ld vertices, %zu handles\n", bar.name.c_str(),
                    long(bar.mesh.num_simplices()), long(bar.mesh.num_vertices()),
                    bar.handles.size());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_bar_pose: %s\n", e.what());
        return 2;
    }
    return 0;
}
