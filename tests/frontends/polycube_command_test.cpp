#include "frontends/cli/polycube_command.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "frontends/cli/cli_support.h"
#include "frontends/cli/command_options.h"
#include "frontends/polycube/cube_cover.h"
#include "frontends/polycube/polycube_output.h"
#include "geometry/io/medit_io.h"
#include "geometry/io/mesh_file.h"
#include "geometry/io/polycube_labels_io.h"
#include "optim/errors.h"
#include "tests/fixtures/polycube_fixtures.h"

namespace sa::cli {
namespace {

namespace fs = std::filesystem;

class PolycubeCommand : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("sa_polycube_command_" + std::to_string(getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        const SimplicialMesh mesh = testing::voxel_tetrahedra(testing::l_shape(), 2);
        write_medit(path("L.mesh"), mesh.vertices, mesh.simplices);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    /// Parses `args` after `sa polycube` and checks them and the output locations; the
    /// exception's message, or "". The arguments are kept in `arguments_`.
    std::string check(std::vector<std::string> args, PolycubePlan* plan = nullptr) {
        arguments_ = {};
        try {
            parse_command_line(args, arguments_);
            const PolycubePlan p = check_polycube_arguments(arguments_);
            OutputPlan outputs(arguments_.force);
            plan_polycube_files(arguments_, p, outputs);
            if (plan != nullptr) *plan = p;
        } catch (const CommandLineError& e) {
            return std::string("parse: ") + e.what();
        } catch (const Error& e) {
            return e.what();
        }
        return "";
    }
    fs::path dir_;
    PolycubeArguments arguments_;
};

TEST_F(PolycubeCommand, ArgumentsAreChecked) {
    PolycubePlan plan;
    EXPECT_EQ(check({"--mesh", path("L.mesh"), "--out", path("out.mesh"), "--bound", "3", "--png",
                     path("p.png"), "--report", path("r.json"), "--max-time", "20"},
                    &plan),
              "");
    EXPECT_EQ(plan.bound, 3.0);
    EXPECT_EQ(plan.rest, path("out.rest.mesh"));
    EXPECT_EQ(plan.flags, path("out.flags"));
    EXPECT_EQ(plan.max_time, 20.0);
    EXPECT_TRUE(plan.labels.flags.empty() && plan.labels.labels.empty());
    EXPECT_TRUE(plan.labels.orient);
    EXPECT_EQ(
        check({"--mesh", path("L.mesh"), "--out", path("out.mesh"), "--keep-orientation"}, &plan),
        "");
    EXPECT_FALSE(plan.labels.orient);
    EXPECT_TRUE(plan.labels.repair);
    EXPECT_EQ(
        check({"--mesh", path("L.mesh"), "--out", path("out.mesh"), "--keep-turning-boundaries"},
              &plan),
        "");
    EXPECT_FALSE(plan.labels.repair);

    std::ofstream(path("L.flags")) << "0\n";
    std::ofstream(path("l.txt")) << "0\n";
    std::ofstream(path("b.obj")) << "v 0 0 0\n";
    EXPECT_EQ(
        check({"--mesh", path("L.mesh"), "--labels", path("L.flags"), "--out", path("o.mesh")},
              &plan),
        "");
    EXPECT_EQ(plan.labels.flags, path("L.flags"));
    EXPECT_EQ(check({"--mesh", path("L.mesh"), "--labels", path("l.txt"), "--label-surface",
                     path("b.obj"), "--out", path("o.mesh"), "--optimal-bound"},
                    &plan),
              "");
    EXPECT_EQ(plan.labels.labels, path("l.txt"));
    EXPECT_EQ(plan.labels.surface, path("b.obj"));
    EXPECT_TRUE(plan.optimal_bound);

    auto fails = [&](std::vector<std::string> args, const std::string& part) {
        const std::string message = check(std::move(args));
        EXPECT_NE(message.find(part), std::string::npos) << message;
    };
    fails({"--mesh", path("none.mesh"), "--out", path("o.mesh")}, "--mesh " + path("none.mesh"));
    fails({"--mesh", path("L.mesh"), "--out", path("o.vtu")}, "written as .mesh");
    fails({"--mesh", path("L.mesh"), "--out", path("o.mesh"), "--bound", "3", "--optimal-bound"},
          "one or the other");
    fails({"--mesh", path("L.mesh"), "--out", path("o.mesh"), "--bound", "0.5"}, "--bound 0.5");
    fails({"--mesh", path("L.mesh"), "--label-surface", path("b.obj"), "--out", path("o.mesh")},
          "needs --labels");
    fails({"--mesh", path("L.mesh"), "--labels", path("L.flags"), "--keep-orientation", "--out",
           path("o.mesh")},
          "only for computed labels");
    fails({"--mesh", path("L.mesh"), "--labels", path("L.flags"), "--keep-turning-boundaries",
           "--out", path("o.mesh")},
          "--keep-turning-boundaries: only for computed labels");
    fails({"--mesh", path("L.mesh"), "--out", path("o.mesh"), "--png", path("p.jpg")}, ".png");
    fails({"--mesh", path("L.mesh"), "--out", path("o.mesh"), "--max-time", "-1"}, "--max-time");
    fails({"--mesh", path("L.mesh"), "--out", path("o.mesh"), "--report", path("o.flags")},
          ".json");
    fails({"--mesh", path("L.mesh"), "--out", path("L.mesh")}, "is the input of --mesh");
    fails({"--out", path("o.mesh")}, "parse:");
    std::ofstream(path("o.rest.mesh")) << "";
    fails({"--mesh", path("L.mesh"), "--out", path("o.mesh")}, "exists; pass --force");
    EXPECT_EQ(check({"--mesh", path("L.mesh"), "--out", path("o.mesh"), "--force"}), "");
}

// The steps around the solve, on the cube-cover start of a generated L (itself a PolyCube, so
// the start is the identity and verified): every output is written and reads back.
TEST_F(PolycubeCommand, InputAndOutputsAroundTheSolve) {
    PolycubePlan plan;
    ASSERT_EQ(check({"--mesh", path("L.mesh"), "--out", path("o.mesh"), "--vtu", path("o.vtu"),
                     "--report", path("o.json")},
                    &plan),
              "");
    std::vector<std::string> lines;
    const PreparedPolycube prepared =
        read_polycube_input(plan, [&](const std::string& l) { lines.push_back(l); });
    EXPECT_EQ(lines.size(), 2u);
    const Eigen::MatrixXd start =
        cube_cover_map(prepared.mesh, prepared.boundary, prepared.charts).positions;
    const PolycubeVerification v = verify_polycube(prepared.layout(), start, prepared.input_volume);
    EXPECT_TRUE(v.passed);
    OutputPlan outputs(false);
    plan_polycube_files(arguments_, plan, outputs);
    write_polycube_outputs(plan, prepared, start, v, {{"command", "test"}}, outputs);
    EXPECT_FALSE(fs::exists(path("o.mesh")));  // staged until the commit
    outputs.commit("");
    for (const char* name : {"o.mesh", "o.rest.mesh", "o.flags", "o.vtu", "o.json"}) {
        EXPECT_TRUE(fs::exists(path(name))) << name;
    }
    EXPECT_EQ(read_facet_flags(path("o.flags"), prepared.mesh.num_simplices()),
              prepared.output_flags());
    std::ifstream in(path("o.json"));
    const nlohmann::json report = nlohmann::json::parse(in);
    EXPECT_EQ(report["command"], "test");
    EXPECT_EQ(report["preparation"]["labels"]["charts"], 8);
    EXPECT_EQ(report["preparation"]["labels"]["source"], "computed");
    EXPECT_EQ(report["verification"]["passed"], true);
    EXPECT_EQ(report["verification"]["quality"]["inverted"], 0);
    EXPECT_EQ(report["outputs"]["flags"], path("o.flags"));
}

// `sa polycube` end to end on a generated bent L (its cube-cover start is not the rest shape):
// exit 0, and every output file says the same as the verification of what it holds.
TEST_F(PolycubeCommand, EndToEndOnAGeneratedMesh) {
    const SimplicialMesh mesh =
        testing::bent(testing::voxel_tetrahedra(testing::l_shape(), 2), 0.12);
    write_medit(path("bent.mesh"), mesh.vertices, mesh.simplices);
    {  // a section the reader skips, with a warning that --quiet keeps
        std::ifstream in(path("bent.mesh"));
        std::string text((std::istreambuf_iterator<char>(in)), {});
        text.insert(text.rfind("End"), "Quadrilaterals\n1\n1 2 3 4 0\n");
        std::ofstream(path("bent.mesh")) << text;
    }
    PolycubeArguments arguments;
    parse_command_line({"--mesh", path("bent.mesh"), "--out", path("o.mesh"), "--report",
                        path("o.json"), "--vtu", path("o.vtu"), "--optimal-bound", "--quiet"},
                       arguments);
    ::testing::internal::CaptureStderr();
    const int status = run_polycube_command(arguments);
    const std::string errors = ::testing::internal::GetCapturedStderr();
    ASSERT_EQ(status, kExitVerified) << errors;
    EXPECT_NE(errors.find("sa: warning: " + path("bent.mesh") + ": skipped 1 Quadrilaterals"),
              std::string::npos)
        << errors;
    for (const char* name : {"o.mesh", "o.rest.mesh", "o.flags", "o.vtu", "o.json"})
        EXPECT_TRUE(fs::exists(path(name))) << name;
    // The written map, read back, passes verify_polycube against the written rest mesh.
    const MeshFile rest = read_mesh_file(path("o.rest.mesh"));
    const MeshFile out = read_mesh_file(path("o.mesh"));
    ASSERT_EQ(rest.mesh.simplices, out.mesh.simplices);
    // In the input's frame, though the labels were computed on it turned (report).
    std::ifstream report_file(path("o.json"));
    const nlohmann::json labels_report =
        nlohmann::json::parse(report_file)["preparation"]["labels"];
    EXPECT_GT(labels_report["orientation"]["angle_degrees"].get<double>(), 0.0);
    EXPECT_EQ(rest.mesh.vertices.topRows(mesh.num_vertices()), mesh.vertices);
    PolycubeLabelInput labels;
    labels.flags = path("o.flags");
    const PreparedPolycube again = prepare_polycube(rest.mesh, path("o.rest.mesh"), labels);
    ASSERT_EQ(again.mesh.num_vertices(), rest.mesh.num_vertices());  // nothing left to split
    const PolycubeVerification v =
        verify_polycube(again.layout(), out.mesh.vertices, again.input_volume);
    EXPECT_TRUE(v.passed) << (v.failures.empty() ? "" : v.failures.front());
    std::ifstream in(path("o.json"));
    const nlohmann::json report = nlohmann::json::parse(in);
    EXPECT_EQ(report["success"], true);
    EXPECT_EQ(report["verification"]["passed"], true);
    EXPECT_FALSE(report["rounds"].empty());
    // Where the time went: one row per assembly iteration, and Newton's phases.
    ASSERT_TRUE(report["solve"]["iterations"].is_array());
    EXPECT_FALSE(report["solve"]["iterations"].empty());
    EXPECT_GT(report["solve"]["times"]["newton_phases"]["total"].get<double>(), 0.0);
    // What the labels force (polycube_angle_bound.h) holds on the verified map.
    const double floor =
        report["preparation"]["labels"]["distortion_lower_bound"]["bound"].get<double>();
    EXPECT_GT(floor, 1.0);
    EXPECT_LE(floor, report["verification"]["quality"]["conformal"]["max"].get<double>());
    // Existing outputs without --force: exit 2 by exception, nothing rewritten.
    EXPECT_THROW(run_polycube_command(arguments), InputError);
}

// A --bound below the distortion the labels force has no solution: refused before the solve
// (NoSolutionError: the sa command exits 1), nothing written.
TEST_F(PolycubeCommand, ABoundBelowWhatTheLabelsForceIsRefused) {
    const SimplicialMesh mesh =
        testing::bent(testing::voxel_tetrahedra(testing::l_shape(), 2), 0.12);
    write_medit(path("bent.mesh"), mesh.vertices, mesh.simplices);
    const PreparedPolycube prepared = prepare_polycube(mesh, "bent.mesh", PolycubeLabelInput{});
    const double floor = prepared.angle_bound.bound;
    ASSERT_GT(floor, 1.0);
    ASSERT_LT(floor, 2.0);
    PolycubeArguments arguments;
    parse_command_line({"--mesh", path("bent.mesh"), "--out", path("o.mesh"), "--report",
                        path("o.json"), "--bound", std::to_string(0.5 + 0.5 * floor), "--quiet"},
                       arguments);
    try {
        run_polycube_command(arguments);
        ADD_FAILURE() << "not refused";
    } catch (const NoSolutionError& e) {
        EXPECT_NE(std::string(e.what()).find("no valid PolyCube map of these labels"),
                  std::string::npos)
            << e.what();
    }
    for (const char* name : {"o.mesh", "o.rest.mesh", "o.flags", "o.json", "o.png"})
        EXPECT_FALSE(fs::exists(path(name))) << name;
}

}  // namespace
}  // namespace sa::cli
