// `sa deform`'s arguments and input checks, in process (the run itself: sa_command_test.cpp and
// bad_input_catalogue_test.cpp).
#include "frontends/cli/deform_command.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "frontends/cli/command_options.h"
#include "geometry/io/mesh_file.h"
#include "geometry/mesh/mesh_generators.h"
#include "optim/errors.h"
#include "tests/geometry/io/io_test_util.h"

namespace sa::cli {
namespace {

using test::TempFolder;
using test::throws_input_error;
using test::throws_invalid_argument;

// Parses `arguments` (after "deform") into a fresh DeformArguments.
DeformArguments parse(std::vector<std::string> arguments) {
    DeformArguments a;
    parse_command_line(arguments, a);
    return a;
}

const std::vector<std::string> kRequired = {"--rest", "r.mesh", "--targets",
                                            "t.txt",  "--out",  "o.vtu"};

std::vector<std::string> with(std::vector<std::string> extra) {
    std::vector<std::string> all = kRequired;
    all.insert(all.end(), extra.begin(), extra.end());
    return all;
}

TEST(DeformCommand, ParsesItsOptions) {
    const DeformArguments a =
        parse(with({"--handles", "h.txt", "--bound-conformal", "3", "--bound-volumetric", "inf",
                    "--mu", "10", "--initialization", "bounded:5", "--png", "p.png"}));
    EXPECT_EQ(a.handles, "h.txt");
    EXPECT_EQ(a.png, "p.png");
    const DeformOptions o = deform_options(a);
    EXPECT_EQ(o.conformal_bound, 3.0);
    EXPECT_EQ(o.volumetric_bound, kInfinity);
    EXPECT_EQ(o.mu, 10.0);
    EXPECT_EQ(o.initialization, Initialization::bounded_distortion(5.0));
    EXPECT_FALSE(o.optimal_bound);
    const DeformOptions d = deform_options(parse(with({"--optimal-bound"})));
    EXPECT_TRUE(d.optimal_bound);
    EXPECT_EQ(d.initialization, Initialization::kClosestRotation);
    EXPECT_EQ(d.mu, 1000.0);
    EXPECT_EQ(d.max_time_seconds, kInfinity);
    // --max-time reaches the start and the solve (which takes what the start left).
    const DeformOptions timed = deform_options(parse(with({"--max-time", "60"})));
    EXPECT_EQ(timed.max_time_seconds, 60.0);
    EXPECT_EQ(timed.start.max_time_seconds, 60.0);
}

TEST(DeformCommand, BadOptionsAreNamed) {
    EXPECT_THROW(parse({"--rest", "r.mesh", "--out", "o.vtu"}), CommandLineError);  // no targets
    EXPECT_TRUE(throws_invalid_argument(
        [] {
            deform_options(parse(with({"--optimal-bound", "--bound-conformal", "3"})));
        },
        "--optimal-bound"));
    EXPECT_TRUE(throws_invalid_argument(
        [] {
            deform_options(parse(with({"--bound-volumetric", "0.5"})));
        },
        "--bound-volumetric 0.5"));
    EXPECT_TRUE(throws_invalid_argument(
        [] {
            deform_options(parse(with({"--bound-conformal", "x"})));
        },
        "--bound-conformal x"));
    EXPECT_TRUE(throws_invalid_argument(
        [] {
            deform_options(parse(with({"--initialization", "bounded"})));
        },
        "bounded:K"));
    EXPECT_TRUE(throws_invalid_argument(
        [] {
            deform_options(parse(with({"--mu", "-1"})));
        },
        "--mu"));
    EXPECT_TRUE(throws_invalid_argument(
        [] {
            deform_options(parse(with({"--start-iterations", "-3"})));
        },
        "--start-iterations"));
}

// A 4 x 1 x 1 bar of tetrahedra in Medit format, its two end faces as handles (rows
// `index x y z`, the right end moved up).
struct Files {
    std::string rest, targets, handles;
};

Files bar_files(const TempFolder& folder) {
    const SimplicialMesh mesh = grid_tetrahedra(4, 1, 1);
    Files f;
    f.rest = folder.path("bar.mesh");
    write_mesh_file(f.rest, mesh.vertices, mesh.simplices);
    std::string rows, list;
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        const double x = mesh.vertices(v, 0);
        if (x > 0.01 && x < 0.99) continue;
        const double lift = x > 0.5 ? 0.3 : 0.0;
        rows += std::to_string(v) + " " + std::to_string(x) + " " +
                std::to_string(mesh.vertices(v, 1) + lift) + " " +
                std::to_string(mesh.vertices(v, 2)) + "\n";
        list += std::to_string(v) + "\n";
    }
    f.targets = folder.write("targets.txt", rows);
    f.handles = folder.write("handles.txt", list);
    return f;
}

TEST(DeformCommand, ReadsAndChecksTheInput) {
    TempFolder folder;
    const Files f = bar_files(folder);
    DeformArguments a;
    a.rest = f.rest;
    a.targets = f.targets;
    a.out = folder.path("posed.vtu");
    DeformInput input = read_deform_input(a);
    EXPECT_EQ(input.mesh.num_simplices(), 4 * 6);
    EXPECT_EQ(input.handle_targets.handles.size(), 8u);
    a.handles = f.handles;
    input = read_deform_input(a);
    EXPECT_EQ(input.handle_targets.targets.rows(), 8);
    EXPECT_FALSE(std::filesystem::exists(a.out));  // reading writes nothing
}

TEST(DeformCommand, BadInputIsOneLineBeforeAnySolve) {
    TempFolder folder;
    const Files f = bar_files(folder);
    DeformArguments a;
    a.rest = f.rest;
    a.targets = f.targets;
    a.out = folder.path("posed.vtu");
    // A handle out of range, named with its file and line.
    a.handles = folder.write("far.txt", "0\n1\n999\n");
    EXPECT_TRUE(throws_input_error([&] { read_deform_input(a); },
                                   {"far.txt:3:", "handle vertex 999 outside [0, 20)"}));
    a.handles.clear();
    // An existing output without --force (the output plan); an output that cannot hold
    // tetrahedra.
    const std::string existing = folder.write("exists.vtu", "old");
    a.out = existing;
    EXPECT_TRUE(throws_input_error(
        [&] {
            OutputPlan plan(a.force);
            plan_deform_files(a, plan);
        },
        {"exists.vtu exists"}));
    EXPECT_EQ(test::read_all(existing), "old");
    a.out = folder.path("posed.obj");
    EXPECT_TRUE(throws_invalid_argument([&] { read_deform_input(a); }, "holds triangles"));
    a.out = folder.path("posed.vtu");
    a.png = folder.path("pose.jpg");
    EXPECT_TRUE(throws_invalid_argument(
        [&] {
            OutputPlan plan(a.force);
            plan_deform_files(a, plan);
        },
        "--png"));
    a.png.clear();
    // A surface in space has no deformation of this kind.
    const SimplicialMesh torus = torus_triangles(8, 6);
    a.rest = folder.path("torus.obj");
    write_mesh_file(a.rest, torus.vertices, torus.simplices);
    EXPECT_TRUE(throws_input_error([&] { read_deform_input(a); }, {"torus.obj", "in space"}));
}

}  // namespace
}  // namespace sa::cli
