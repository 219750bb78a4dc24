#include "geometry/io/mesh_file.h"

#include <gtest/gtest.h>

#include <fstream>

#include "geometry/io/problem_io.h"
#include "io_test_util.h"

namespace sa {
namespace {

using test::TempFolder;
using test::throws_input_error;
using test::throws_invalid_argument;

struct Tet {
    Eigen::MatrixXd positions{5, 3};
    Eigen::MatrixXi tets{2, 4};
    Eigen::MatrixXi triangles{2, 3};
    Tet() {
        positions << 0, 0, 0, 1.0 / 3.0, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1;
        tets << 0, 1, 2, 3, 1, 2, 3, 4;
        triangles << 0, 1, 2, 2, 1, 3;
    }
};

TEST(MeshFile, RoundTripsEveryWritableFormatByExtension) {
    TempFolder folder;
    const Tet mesh;
    for (const char* name : {"a.vtu", "a.VTK", "a.mesh", "a.node", "b.ele"}) {
        SCOPED_TRACE(name);
        const std::string path = folder.path(name);
        write_mesh_file(path, mesh.positions, mesh.tets);
        const MeshFile file = read_mesh_file(path);
        EXPECT_EQ(file.mesh.vertices, mesh.positions);
        EXPECT_EQ(file.mesh.simplices, mesh.tets);
    }
    for (const char* name : {"a.obj", "a.OFF", "t.vtu", "t.mesh"}) {
        SCOPED_TRACE(name);
        const std::string path = folder.path(name);
        write_mesh_file(path, mesh.positions, mesh.triangles);
        const MeshFile file = read_mesh_file(path);
        EXPECT_EQ(file.mesh.vertices, mesh.positions);
        EXPECT_EQ(file.mesh.simplices, mesh.triangles);
    }
}

TEST(MeshFile, OtherExtensionsAreResultRecordsAndProblems) {
    TempFolder folder;
    const Tet mesh;
    const std::string result = folder.path("result.txt");
    write_mesh_file(result, mesh.positions, mesh.tets);
    EXPECT_EQ(read_result_positions(result), mesh.positions);
    EXPECT_EQ(test::read_all(result).substr(0, 9), "resV 5 3\n");

    const std::string problem =
        folder.write("input", "3 2\n0 0\n1 0\n0 1\n3 2\n0 0\n1 0\n0 1\n1 3\n0 1 2\n1\n2\n");
    const MeshFile file = read_mesh_file(problem);
    EXPECT_EQ(file.mesh.simplices.rows(), 1);
    EXPECT_TRUE(file.initial.has_value());
    EXPECT_EQ(file.handles, std::vector<Index>{2});
}

TEST(MeshFile, ReadOnlyFormatsAndBadArgumentsAreRejected) {
    TempFolder folder;
    const Tet mesh;
    EXPECT_TRUE(throws_invalid_argument(
        [&] { write_mesh_file(folder.path("a.ply"), mesh.positions, mesh.triangles); },
        "cannot write .ply"));
    EXPECT_TRUE(throws_invalid_argument(
        [&] { write_mesh_file(folder.path("a.obj"), mesh.positions, mesh.tets); }, "4 columns"));
    EXPECT_TRUE(throws_invalid_argument(
        [&] { write_mesh_file(folder.path("a.node"), mesh.positions, mesh.triangles); },
        "3 columns"));
    EXPECT_EQ(folder.entries(), 0u);
    EXPECT_TRUE(throws_input_error([&] { read_mesh_file(folder.path("absent.stl")); },
                                   {"absent.stl: cannot open (No such file or directory)"}));
    EXPECT_TRUE(throws_input_error([&] { read_mesh_file(folder.path("absent")); },
                                   {"absent: cannot open (No such file or directory)"}));
    EXPECT_TRUE(throws_input_error([&] { read_mesh_file(folder.root().string()); },
                                   {"cannot open (Is a directory)"}));
}

TEST(MeshFile, EveryWriterLeavesNothingOnFailure) {
    TempFolder folder;
    const Tet mesh;
    Eigen::MatrixXi bad = mesh.tets;
    bad(0, 0) = 99;
    for (const char* name : {"a.vtu", "a.vtk", "a.mesh", "result"}) {
        SCOPED_TRACE(name);
        test::check_atomic_writes(
            folder, name,
            [&](const std::string& p) { write_mesh_file(p, mesh.positions, mesh.tets); },
            [&](const std::string& p) {
                if (std::string(name) == "result")
                    write_mesh_file(p, Eigen::MatrixXd::Constant(2, 2, std::nan("")), bad);
                else
                    write_mesh_file(p, mesh.positions, bad);
            });
    }
}

TEST(MeshFile, AByteOrderMarkIsSkippedInEveryTextFormat) {
    TempFolder folder;
    const Tet mesh;
    const std::string bom = "\xEF\xBB\xBF";
    for (const char* name : {"a.obj", "a.off", "a.mesh", "a.problem"}) {
        SCOPED_TRACE(name);
        const std::string path = folder.path(name);
        if (std::string(name) == "a.problem") {
            std::ofstream(path) << "3 2\n0 0\n1 0\n0 1\n3 2\n0 0\n1 0\n0 1\n1 3\n0 1 2\n";
        } else {
            write_mesh_file(path, mesh.positions, mesh.triangles);
        }
        const MeshFile plain = read_mesh_file(path);
        const std::string text = test::read_all(path);
        folder.write(name, bom + text);
        const MeshFile marked = read_mesh_file(path);
        EXPECT_EQ(marked.mesh.vertices, plain.mesh.vertices);
        EXPECT_EQ(marked.mesh.simplices, plain.mesh.simplices);
    }
}

TEST(MeshFile, ABinaryFileIsNotATextFile) {
    TempFolder folder;
    const std::string gzip("\x1f\x8b\x08\x00\x00\x00\x00\x00\x00\x03v 0 0 0\n", 18);
    for (const char* name : {"a.obj", "a.off", "a.mesh", "a.node", "problem", "a.vtk", "a.vtu"}) {
        SCOPED_TRACE(name);
        const std::string path = folder.write(name, gzip);
        EXPECT_TRUE(throws_input_error([&] { read_mesh_file(path); },
                                       {path, "not a text file (byte 0x1f"}));
    }
    // NUL bytes after a line of text: found on their line.
    const std::string path = folder.write("late.obj", std::string("v 0 0 0\nv 1\0 0\n", 14));
    EXPECT_TRUE(throws_input_error([&] { read_mesh_file(path); },
                                   {"late.obj:2: not a text file (byte 0x00 in column 4)"}));
}

TEST(MeshFile, ACountLargerThanTheFileFailsWithoutAllocatingIt) {
    TempFolder folder;
    const std::vector<std::pair<const char*, std::string>> files = {
        {"huge.off", "OFF\n2000000000 2000000000 0\n0 0 0\n"},
        {"huge", "2000000000 3\n0 0 0\n"},
        {"huge.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n2000000000\n0 0 0 0\n"},
        {"huge.node", "2000000000 3 0 0\n0 0 0 0\n"},
    };
    for (const auto& [name, content] : files) {
        SCOPED_TRACE(name);
        const std::string path = folder.write(name, content);
        EXPECT_TRUE(throws_input_error([&] { read_mesh_file(path); }, {name, "2000000000"}));
    }
}

}  // namespace
}  // namespace sa
