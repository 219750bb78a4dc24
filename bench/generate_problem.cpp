// Writes a generated mapping problem (tests/fixtures/generated_problems.h) in the plain-text
// problem format of ../shared/data/tlc/*/input (rest, initial map, simplices, handles), for `sa
// map` and bench/map_benchmarks.py:
//
//   bench_generate_problem --kind fixed-boundary --mesh ../shared/data/tet/hand.mesh
//       --deformation twist --amount 1.5 --noise 1.0 --seed 1 --out hand-twist.txt
//   bench_generate_problem --kind slabs --grid 24 24 64 --deformation twist --amount 3.14
//       --slab 0.05 --out bar-twist.txt
//   bench_generate_problem --grid 40 160 --deformation bend --amount 2 --noise 1 --out strip.txt
//       (two numbers: a planar rectangle of square cells, two triangles each; bend only)
//
// Prints one line: vertices, simplices, handles, inverted simplices of the initial map.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <type_traits>

#include "geometry/io/mesh_file.h"
#include "geometry/mesh/mesh_generators.h"
#include "geometry/mesh/rest_frames.h"
#include "geometry/quality/map_quality.h"
#include "optim/errors.h"
#include "tests/fixtures/generated_problems.h"

int main(int argc, char** argv) {
    CLI::App app("Generated mapping problems (tests/fixtures/generated_problems.h)");
    std::string kind = "fixed-boundary", mesh_path, deformation = "twist", out;
    std::vector<int> grid;
    double amount = 1.5, noise = 1.0, flatten = 1.0, slab = 0.05;
    std::uint64_t seed = 1;
    app.add_option("--kind", kind, "fixed-boundary or slabs")
        ->check(CLI::IsMember({"fixed-boundary", "slabs"}));
    app.add_option("--mesh", mesh_path, "a tetrahedral mesh (any format sa reads)");
    app.add_option("--grid", grid,
                   "nx ny nz: a box of Kuhn-cut cubes instead; nx ny: a planar rectangle")
        ->expected(2, 3);
    app.add_option("--deformation", deformation, "twist or bend")
        ->check(CLI::IsMember({"twist", "bend"}));
    app.add_option("--amount", amount, "radians");
    app.add_option("--noise", noise, "fixed-boundary: interior noise, in mean edge lengths");
    app.add_option("--seed", seed);
    app.add_option("--flatten", flatten, "fixed-boundary: scale of the shortest side (<= 1)");
    app.add_option("--slab", slab, "slabs: handle slab width, a fraction of the length");
    app.add_option("--out", out, "output problem file")->required();
    CLI11_PARSE(app, argc, argv);
    try {
        sa::SimplicialMesh rest;
        if (grid.size() == 3) {
            rest = sa::grid_tetrahedra(grid[0], grid[1], grid[2]);
        } else if (grid.size() == 2) {
            rest = sa::grid_triangles(grid[0], grid[1]);  // the unit square: make cells square
            const double n = std::max(grid[0], grid[1]);
            rest.vertices.col(0) *= grid[0] / n;
            rest.vertices.col(1) *= grid[1] / n;
        } else if (!mesh_path.empty()) {
            rest = sa::read_mesh_file(mesh_path).mesh;
        } else {
            throw sa::InvalidArgumentError("give --mesh or --grid");
        }
        const auto d = deformation == "twist" ? sa::GeneratedDeformation::kTwist
                                              : sa::GeneratedDeformation::kBend;
        const sa::GeneratedProblem p =
            kind == "slabs" ? sa::handle_slab_problem(rest, d, amount, slab)
                            : sa::fixed_boundary_problem(rest, d, amount, noise, seed, flatten);
        std::ofstream f(out);
        f << std::setprecision(17);
        auto block = [&](const Eigen::MatrixXd& m) {
            f << m.rows() << ' ' << m.cols() << '\n';
            for (sa::Index r = 0; r < m.rows(); ++r) {
                for (sa::Index c = 0; c < m.cols(); ++c) f << (c ? " " : "") << m(r, c);
                f << '\n';
            }
        };
        block(p.rest.vertices);
        block(p.initial);
        f << p.rest.simplices.rows() << ' ' << p.rest.simplices.cols() << '\n';
        for (sa::Index r = 0; r < p.rest.simplices.rows(); ++r) {
            for (sa::Index c = 0; c < p.rest.simplices.cols(); ++c)
                f << (c ? " " : "") << p.rest.simplices(r, c);
            f << '\n';
        }
        f << p.handles.size() << '\n';
        for (sa::Index h : p.handles) f << h << '\n';
        if (!f) throw sa::InputError(out + ": cannot write");
        auto quality = [&](auto dimension) {
            constexpr int D = decltype(dimension)::value;
            const sa::RestFrames<D> frames = sa::rest_frames<D>(p.rest);
            return sa::map_quality<D>(sa::linear_parts<D>(p.rest, frames, p.initial),
                                      frames.volume);
        };
        const sa::MapQuality q = p.rest.simplices.cols() == 3
                                     ? quality(std::integral_constant<int, 2>())
                                     : quality(std::integral_constant<int, 3>());
        std::printf("%ld vertices, %ld simplices, %zu handles, %ld inverted in the initial map\n",
                    long(p.rest.num_vertices()), long(p.rest.num_simplices()), p.handles.size(),
                    long(q.inverted));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_generate_problem: %s\n", e.what());
        return 2;
    }
    return 0;
}
