// Runs the `sa` executable as a user would: exit codes, messages, outputs.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>

#include "geometry/io/mesh_file.h"
#include "geometry/mesh/mesh_generators.h"
#include "geometry/mesh/mesh_topology.h"
#include "geometry/quality/map_quality.h"

namespace sa {
namespace {

namespace fs = std::filesystem;

struct Outcome {
    int status;
    std::string out, err;
};

class SaCommand : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("sa_command_test_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    Outcome sa(const std::string& arguments) {
        const std::string out = (dir_ / "stdout.txt").string(),
                          err = (dir_ / "stderr.txt").string();
        const int code = std::system(
            (std::string(SA_EXECUTABLE) + " " + arguments + " > " + out + " 2> " + err).c_str());
        return {WEXITSTATUS(code), read(out), read(err)};
    }
    static std::string read(const std::string& path) {
        std::ifstream in(path);
        return std::string(std::istreambuf_iterator<char>(in), {});
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    // A plain-text problem: a grid with its boundary fixed and the interior scrambled; with
    // `mirror`, the boundary is mirrored as well, which inverts the triangles at the corners (all
    // three of their vertices are handles).
    // With `collapse`, handle 1 sits where handle 0 does: the rest edge 0-1 has zero length.
    std::string folded_problem(const std::string& name, bool mirror = false,
                               bool collapse = false) {
        const SimplicialMesh mesh = grid_triangles(8, 8);
        const MeshTopology t = mesh_topology(mesh, "grid");
        std::mt19937 rng(3);
        std::uniform_real_distribution<double> u(-0.15, 0.15);
        std::ofstream f(path(name));
        f.precision(17);
        f << mesh.num_vertices() << " 2\n"
          << mesh.vertices << "\n"
          << mesh.num_vertices() << " 2\n";
        std::vector<int> handles;
        for (Index v = 0; v < mesh.num_vertices(); ++v) {
            Eigen::RowVector2d p = mesh.vertices.row(v);
            if (t.boundary_vertex[v]) {
                handles.push_back(v);
                if (mirror) p.x() = 1.0 - p.x();
                if (collapse && v == 1) p = mesh.vertices.row(0);
            } else {
                p += Eigen::RowVector2d(u(rng), u(rng));
            }
            f << p << "\n";
        }
        f << mesh.num_simplices() << " 3\n" << mesh.simplices << "\n" << handles.size() << "\n";
        for (int h : handles) f << h << "\n";
        return path(name);
    }

    fs::path dir_;
};

TEST_F(SaCommand, MapWritesAVerifiedResultAndAReport) {
    const std::string problem = folded_problem("grid.txt");
    const Outcome r = sa("map --rest " + problem + " --out " + path("out.obj") + " --report " +
                         path("r.json") + " --record " + path("frames"));
    ASSERT_EQ(r.status, 0) << r.out << r.err;
    EXPECT_NE(
        r.out.find("success: verified from the output positions: 0 of 128 simplices inverted"),
        std::string::npos)
        << r.out;
    EXPECT_NE(r.err.find("iter"), std::string::npos);  // progress rows go to stderr

    // The output, read back and checked here: no inverted triangle, handles in place.
    const MeshFile out = read_mesh_file(path("out.obj"));
    const MeshFile in = read_mesh_file(problem);
    const Eigen::MatrixXd map = out.mesh.vertices.leftCols(2);
    const RestFrames<2> frames = rest_frames<2>(in.mesh);
    EXPECT_EQ(map_quality<2>(linear_parts<2>(in.mesh, frames, map), frames.volume).inverted, 0);
    for (Index h : in.handles) EXPECT_LT((map.row(h) - in.initial->row(h)).norm(), 1e-9);

    const nlohmann::json report = nlohmann::json::parse(read(path("r.json")));
    EXPECT_TRUE(report["verification"]["success"].get<bool>());
    EXPECT_EQ(report["verification"]["inverted"].get<int>(), 0);
    EXPECT_GT(report["initial_quality"]["inverted"].get<int>(), 0);
    EXPECT_GE(report["iterations"].size(), 2u);
    EXPECT_TRUE(report["times"].contains("optimization"));

    EXPECT_TRUE(fs::exists(path("frames/assembly.pvd")));
    EXPECT_TRUE(fs::exists(path("frames/iteration_0000.vtu")));
}

TEST_F(SaCommand, BadInputGetsOneLineExitTwoAndNoOutput) {
    std::ofstream(path("broken.txt")) << "4 2\n0 0\n1 0\n1 1\nnot-a-number 1\n";
    const Outcome r = sa("map --rest " + path("broken.txt") + " --out " + path("out.vtu"));
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("broken.txt:5:"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("out.vtu")));

    const std::string problem = folded_problem("grid.txt");
    const Outcome handles = sa("map --rest " + problem + " --handles " + path("missing.txt") +
                               " --out " + path("out.vtu"));
    EXPECT_EQ(handles.status, 2);
    EXPECT_NE(handles.err.find("missing.txt"), std::string::npos) << handles.err;
    EXPECT_EQ(sa("map --rest " + problem + " --out " + path("out.vtu") + " --bound 0.9").status, 2);
    EXPECT_EQ(sa("map --rest " + problem + " --out " + path("out.node")).status, 2);  // tets only
    EXPECT_EQ(sa("map --rest " + problem).status, 2);                                 // no --out
    EXPECT_FALSE(fs::exists(path("out.vtu")));
    EXPECT_FALSE(fs::exists(path("out.node")));
}

TEST_F(SaCommand, MapDiagnosesHandlesThatRuleOutASolution) {
    const std::string problem = folded_problem("mirrored.txt", true);
    const Outcome r = sa("map --rest " + problem + " --out " + path("out.vtu") + " --report " +
                         path("report.json"));
    EXPECT_EQ(r.status, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("infeasible"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("are inverted"), std::string::npos) << r.out;
    EXPECT_EQ(r.err, "") << "no progress row: nothing was optimized";
    EXPECT_FALSE(fs::exists(path("out.vtu")));
    const nlohmann::json report = nlohmann::json::parse(read(path("report.json")));
    EXPECT_FALSE(report["success"].get<bool>());
    // The two corner cells whose three vertices are boundary handles.
    EXPECT_EQ(report["infeasible"]["inverted"].get<int>(), 2) << report.dump();
    EXPECT_EQ(report["infeasible"]["inverted_simplices"].size(), 2u);
    EXPECT_FALSE(report.contains("iterations"));

    const Outcome collapsed = sa("map --rest " + folded_problem("collapsed.txt", false, true) +
                                 " --out " + path("out.vtu"));
    EXPECT_EQ(collapsed.status, 1) << collapsed.out << collapsed.err;
    EXPECT_NE(collapsed.out.find("1 rest edges have both ends at one target (edges 0-1)"),
              std::string::npos)
        << collapsed.out;
    EXPECT_EQ(collapsed.err, "");
    EXPECT_FALSE(fs::exists(path("out.vtu")));
}

TEST_F(SaCommand, ExistingOutputsAreKeptWithoutForce) {
    const std::string problem = folded_problem("grid.txt");
    std::ofstream(path("mine.vtu")) << "precious";
    const Outcome r = sa("map --rest " + problem + " --out " + path("mine.vtu"));
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--force"), std::string::npos);
    EXPECT_EQ(read(path("mine.vtu")), "precious");
    EXPECT_EQ(
        sa("map --rest " + problem + " --out " + path("mine.vtu") + " --force --quiet").status, 0);
    EXPECT_NE(read(path("mine.vtu")), "precious");
}

TEST_F(SaCommand, TetgenOutputWritesBothFilesOrNone) {
    const SimplicialMesh box = grid_tetrahedra(2, 2, 2);
    write_mesh_file(path("box.mesh"), box.vertices, box.simplices);
    const std::string box_problem = path("box.mesh") + " --init " + path("box.mesh");
    const Outcome r = sa("map --rest " + box_problem + " --out " + path("out.node") + " --quiet");
    ASSERT_EQ(r.status, 0) << r.out << r.err;
    // The .ele written next to the .node is renamed into place with it, nothing left hidden.
    EXPECT_TRUE(fs::exists(path("out.ele")));
    EXPECT_EQ(read_mesh_file(path("out.node")).mesh.num_simplices(), box.num_simplices());
    for (const auto& entry : fs::directory_iterator(dir_))
        EXPECT_NE(entry.path().filename().string().front(), '.') << entry.path();

    // An existing .ele is the other half of the output: kept without --force.
    fs::remove(path("out.node"));
    std::ofstream(path("out.ele"), std::ios::trunc) << "precious";
    EXPECT_EQ(sa("map --rest " + box_problem + " --out " + path("out.node")).status, 2);
    EXPECT_EQ(read(path("out.ele")), "precious");
    EXPECT_FALSE(fs::exists(path("out.node")));
}

TEST_F(SaCommand, DemoRepairsTheFoldedHarmonicMap) {
    const Outcome r = sa("demo --size 10 --quiet --out-dir " + path("demo"));
    ASSERT_EQ(r.status, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("| inf |"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("| 4 |"), std::string::npos) << r.out;
    for (const char* f : {"initial.vtu", "conformal_unbounded.vtu", "conformal_bound4.vtu"}) {
        EXPECT_TRUE(fs::exists(path(std::string("demo/") + f))) << f;
    }
    // A picture beside each, its path printed.
    for (const char* f : {"initial.png", "conformal_unbounded.png", "conformal_bound4.png"}) {
        const std::string png = path(std::string("demo/") + f);
        ASSERT_TRUE(fs::exists(png)) << f;
        EXPECT_GT(fs::file_size(png), 1000u) << f;
        EXPECT_NE(r.out.find(png), std::string::npos) << r.out;
    }
    const Outcome plain = sa("demo --size 6 --quiet --no-png --out-dir " + path("plain"));
    ASSERT_EQ(plain.status, 0) << plain.err;
    EXPECT_TRUE(fs::exists(path("plain/initial.vtu")));
    EXPECT_FALSE(fs::exists(path("plain/initial.png")));
}

TEST_F(SaCommand, EveryLongCommandTakesMaxTime) {
    // The same option with the same check everywhere: a number or inf > 0, in the help.
    for (const char* command : {"map", "param", "seamless", "deform", "polycube", "hex"}) {
        const Outcome help = sa(std::string(command) + " --help");
        EXPECT_NE(help.out.find("--max-time FLOAT:a number or inf > 0=inf"), std::string::npos)
            << command << ":\n"
            << help.out;
        for (const char* bad : {"0", "-1", "nan"}) {
            const Outcome r = sa(std::string(command) + " --max-time " + bad);
            EXPECT_EQ(r.status, 2) << command;
            EXPECT_EQ(r.err, std::string("sa: error: --max-time: must be a number or inf > 0, "
                                         "found '") +
                                 bad + "'\n")
                << command;
        }
    }
}

TEST_F(SaCommand, ParamWritesAVerifiedUvMapAndRejectsANonDisk) {
    // A bumpy square: a disk surface in space.
    SimplicialMesh mesh = grid_triangles(12, 12);
    Eigen::MatrixXd lifted(mesh.num_vertices(), 3);
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        const double x = mesh.vertices(v, 0), y = mesh.vertices(v, 1);
        lifted.row(v) << x, y, 0.2 * std::sin(4.0 * x) * y;
    }
    write_mesh_file(path("bump.off"), lifted, mesh.simplices);
    const Outcome r = sa("param --mesh " + path("bump.off") + " --bound 2 --out " + path("uv.obj") +
                         " --png " + path("uv.png") + " --report " + path("uv.json") + " --quiet");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("success: verified from the output positions"), std::string::npos)
        << r.out;
    std::ifstream obj(path("uv.obj"));
    int vt = 0;
    for (std::string line; std::getline(obj, line);) vt += line.rfind("vt ", 0) == 0;
    EXPECT_EQ(vt, mesh.num_vertices());
    EXPECT_GT(fs::file_size(path("uv.png")), 1000u);
    EXPECT_TRUE(
        nlohmann::json::parse(read(path("uv.json")))["parameterization"]["success"].get<bool>());

    // The same square without the two triangles of one middle cell: two boundary loops.
    const Eigen::RowVector2d cell_center(6.5 / 12.0, 6.5 / 12.0);
    std::vector<Index> kept;
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        Eigen::RowVector2d centroid = Eigen::RowVector2d::Zero();
        for (int k = 0; k < 3; ++k) centroid += mesh.vertices.row(mesh.simplices(s, k)) / 3.0;
        if ((centroid - cell_center).norm() > 0.03) kept.push_back(s);
    }
    ASSERT_EQ(kept.size(), std::size_t(mesh.num_simplices() - 2));
    Eigen::MatrixXi holed(kept.size(), 3);
    for (std::size_t k = 0; k < kept.size(); ++k) holed.row(k) = mesh.simplices.row(kept[k]);
    write_mesh_file(path("annulus.off"), lifted, holed);
    const Outcome annulus = sa("param --mesh " + path("annulus.off") + " --out " +
                               path("annulus-uv.obj") + " --report " + path("annulus.json"));
    EXPECT_EQ(annulus.status, 0) << annulus.err;
    EXPECT_NE(annulus.out.find("1 inner hole filled"), std::string::npos) << annulus.out;
    const nlohmann::json report = nlohmann::json::parse(read(path("annulus.json")));
    EXPECT_EQ(report["parameterization"]["filled_holes"].get<int>(), 1);
    EXPECT_TRUE(report["parameterization"]["success"].get<bool>());

    // A closed surface cannot lie in the plane.
    const SimplicialMesh sphere = sphere_triangles(3);
    write_mesh_file(path("sphere.off"), sphere.vertices, sphere.simplices);
    const Outcome bad =
        sa("param --mesh " + path("sphere.off") + " --out " + path("sphere-uv.obj"));
    EXPECT_EQ(bad.status, 2);
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
    EXPECT_NE(bad.err.find("sphere.off: the mesh is closed"), std::string::npos) << bad.err;
    EXPECT_FALSE(fs::exists(path("sphere-uv.obj")));
}

TEST_F(SaCommand, SeamlessWritesAVerifiedMapItsPictureAndRejectsABadField) {
    const SimplicialMesh sphere = sphere_triangles(6);
    write_mesh_file(path("sphere.off"), sphere.vertices, sphere.simplices);
    const Outcome r = sa("seamless --mesh " + path("sphere.off") + " --out " + path("s.obj") +
                         " --report " + path("s.json") + " --quiet");
    ASSERT_EQ(r.status, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("success: verified from the (u, v)"), std::string::npos) << r.out;
    const nlohmann::json report = nlohmann::json::parse(read(path("s.json")));
    EXPECT_TRUE(report["success"].get<bool>());
    EXPECT_EQ(report["singularities_after"], report["singularities_before"]);
    EXPECT_EQ(report["result"]["quality"]["inverted"].get<int>(), 0);
    // Per-corner texture coordinates: more vt lines than vertices (the seams are cut).
    std::ifstream obj(path("s.obj"));
    int vt = 0, faces_with_vt = 0;
    for (std::string line; std::getline(obj, line);) {
        vt += line.rfind("vt ", 0) == 0;
        faces_with_vt += line.rfind("f ", 0) == 0 && line.find('/') != std::string::npos;
    }
    EXPECT_GT(vt, sphere.num_vertices());
    EXPECT_EQ(faces_with_vt, sphere.num_simplices());
    EXPECT_GT(fs::file_size(path("s.vtu")), 1000u);
    EXPECT_GT(fs::file_size(path("s.png")), 10000u);  // rendered (under Xvfb without a display)

    // A field with one row too few: one line naming the file, exit 2, nothing written.
    std::ofstream field(path("short.dmat"));
    field << "3 " << sphere.num_simplices() - 1 << "\n";
    for (Index i = 0; i < 3 * (sphere.num_simplices() - 1); ++i) field << "1\n";
    field.close();
    const Outcome bad = sa("seamless --mesh " + path("sphere.off") + " --field " +
                           path("short.dmat") + " --out " + path("bad.obj"));
    EXPECT_EQ(bad.status, 2);
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
    EXPECT_NE(bad.err.find("short.dmat"), std::string::npos) << bad.err;
    EXPECT_FALSE(fs::exists(path("bad.obj")));
    EXPECT_FALSE(fs::exists(path("bad.png")));
}

TEST_F(SaCommand, ParamAndSeamlessTakeMaxTimeAsMapDoes) {
    const SimplicialMesh square = grid_triangles(10, 10);
    Eigen::MatrixXd lifted(square.num_vertices(), 3);
    for (Index v = 0; v < square.num_vertices(); ++v) {
        const double x = square.vertices(v, 0), y = square.vertices(v, 1);
        lifted.row(v) << x, y, 0.2 * std::sin(4.0 * x) * y;
    }
    write_mesh_file(path("bump.off"), lifted, square.simplices);
    const SimplicialMesh sphere = sphere_triangles(4);
    write_mesh_file(path("sphere.off"), sphere.vertices, sphere.simplices);

    // A generous limit changes nothing and is reported.
    const Outcome p = sa("param --mesh " + path("bump.off") + " --max-time 60 --out " +
                         path("uv.obj") + " --report " + path("uv.json") + " --quiet");
    ASSERT_EQ(p.status, 0) << p.err;
    EXPECT_EQ(nlohmann::json::parse(read(path("uv.json")))["options"]["max_time_seconds"], 60.0);
    const Outcome s = sa("seamless --mesh " + path("sphere.off") + " --max-time 60 --out " +
                         path("s.obj") + " --report " + path("s.json") + " --no-png --quiet");
    ASSERT_EQ(s.status, 0) << s.out << s.err;
    EXPECT_EQ(nlohmann::json::parse(read(path("s.json")))["options"]["max_time_seconds"], 60.0);

    // A limit that runs out: the map reached by then is verified, written and reported, whether
    // or not it passed (exit 0 or 1, never an error).
    const Outcome short_param =
        sa("param --mesh " + path("bump.off") + " --max-time 1e-6 --out " + path("uv-short.obj") +
           " --report " + path("uv-short.json") + " --quiet");
    EXPECT_TRUE(short_param.status == 0 || short_param.status == 1) << short_param.err;
    EXPECT_TRUE(fs::exists(path("uv-short.obj")));
    EXPECT_TRUE(fs::exists(path("uv-short.json")));
    // The limit bounds the command: the default picture is left out once it has run out, with a
    // warning (under --quiet too); a picture asked for with --png is drawn all the same.
    EXPECT_FALSE(fs::exists(path("uv-short.png")));
    EXPECT_NE(short_param.err.find("sa: warning: no picture " + path("uv-short.png") +
                                   ": --max-time 1e-06 had run out"),
              std::string::npos)
        << short_param.err;
    const Outcome asked = sa("param --mesh " + path("bump.off") + " --max-time 1e-6 --out " +
                             path("uv-asked.obj") + " --png " + path("uv-asked.png") + " --quiet");
    EXPECT_TRUE(asked.status == 0 || asked.status == 1) << asked.err;
    EXPECT_TRUE(fs::exists(path("uv-asked.png"))) << asked.err;
    const Outcome short_seamless =
        sa("seamless --mesh " + path("sphere.off") + " --max-time 1e-6 --out " +
           path("s-short.obj") + " --no-png --no-vtu --quiet");
    EXPECT_TRUE(short_seamless.status == 0 || short_seamless.status == 1) << short_seamless.err;
    EXPECT_TRUE(fs::exists(path("s-short.obj")));

    // Not a positive number: one line, exit 2, nothing written.
    for (const std::string& command :
         {"param --mesh " + path("bump.off") + " --max-time 0 --out " + path("bad.obj"),
          "seamless --mesh " + path("sphere.off") + " --max-time -1 --out " + path("bad.obj")}) {
        const Outcome bad = sa(command);
        EXPECT_EQ(bad.status, 2) << command;
        EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
        EXPECT_FALSE(fs::exists(path("bad.obj")));
    }
}

}  // namespace
}  // namespace sa
