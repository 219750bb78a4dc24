#include "geometry/io/off_io.h"

#include <gtest/gtest.h>

#include "io_test_util.h"

namespace sa {
namespace {

using test::TempFolder;
using test::throws_input_error;
using test::throws_invalid_argument;

TEST(OffIo, ReadsVerticesAndFaces) {
    TempFolder folder;
    const std::string path = folder.write("mesh.off",
                                          "OFF\r\n"
                                          "# comment\r\n"
                                          "4 2 0\r\n"
                                          "0 0 0\r\n"
                                          "1 0 0 # the second vertex\r\n"
                                          "\r\n"
                                          "1 1 0.5\r\n"
                                          "  0 1 0  \r\n"
                                          "3 0 1 2\r\n"
                                          "3 0 2 3 255 0 0\r\n");
    const MeshFile file = read_off(path);
    ASSERT_EQ(file.mesh.vertices.rows(), 4);
    ASSERT_EQ(file.mesh.vertices.cols(), 3);
    EXPECT_EQ(file.mesh.vertices(2, 2), 0.5);
    Eigen::MatrixXi expected(2, 3);
    expected << 0, 1, 2, 0, 2, 3;
    EXPECT_EQ(file.mesh.simplices, expected);
}

TEST(OffIo, AcceptsCountsOnTheHeaderLineAndColouredVariants) {
    TempFolder folder;
    const MeshFile file = read_off(folder.write(
        "c.off", "COFF 3 1 3\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2\n"));
    EXPECT_EQ(file.mesh.vertices.rows(), 3);
    EXPECT_EQ(file.mesh.vertices(1, 0), 1.0);
    EXPECT_EQ(file.mesh.simplices.rows(), 1);
    const MeshFile normals = read_off(
        folder.write("n.off", "NOFF\n3 1\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 2 1 0\n"));
    EXPECT_EQ(normals.mesh.simplices(0, 0), 2);
}

TEST(OffIo, RoundTrip) {
    TempFolder folder;
    Eigen::MatrixXd positions(4, 3);
    positions << 0.1, 0.2, 0.3, 1.0 / 3.0, 0, 0, 1, 1e-300, 0, 0, 1, -2.5e10;
    Eigen::MatrixXi triangles(2, 3);
    triangles << 0, 1, 2, 0, 2, 3;
    const std::string path = folder.path("out.off");
    write_off(path, positions, triangles);
    const MeshFile file = read_off(path);
    EXPECT_EQ(file.mesh.vertices, positions);
    EXPECT_EQ(file.mesh.simplices, triangles);

    write_off(path, positions.leftCols(2), triangles);
    const MeshFile flat = read_off(path);
    EXPECT_EQ(flat.mesh.vertices.leftCols(2), positions.leftCols(2));
    EXPECT_TRUE((flat.mesh.vertices.col(2).array() == 0).all());
}

TEST(OffIo, MalformedFilesNameTheFileAndLine) {
    TempFolder folder;
    auto read = [&](const std::string& name, const std::string& content) {
        const std::string path = folder.write(name, content);
        return [path] { read_off(path); };
    };
    const std::string head = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
    EXPECT_TRUE(throws_input_error(read("header.off", "PLY\n"), {"header.off:1:", "'PLY'"}));
    EXPECT_TRUE(throws_input_error(read("binary.off", "OFF BINARY\n"), {"binary OFF"}));
    EXPECT_TRUE(throws_input_error(read("counts.off", "OFF\n3\n"), {"counts.off:2:", "counts"}));
    EXPECT_TRUE(throws_input_error(read("number.off", "OFF\n3 1 0\n0 0 0\n1 0 zero\n"),
                                   {"number.off:4:", "'zero'"}));
    EXPECT_TRUE(throws_input_error(read("short.off", "OFF\n3 1 0\n0 0 0\n1 0\n"),
                                   {"short.off:4:", "expected 3 numbers (x y z)", "found 2"}));
    EXPECT_TRUE(throws_input_error(read("long.off", "OFF\n3 1 0\n0 0 0\n1 0 0 1\n"),
                                   {"long.off:4:", "found 4"}));
    EXPECT_TRUE(throws_input_error(read("quad.off", head + "4 0 1 2 0\n"),
                                   {"quad.off:6:", "face with 4 vertices"}));
    EXPECT_TRUE(throws_input_error(read("range.off", head + "3 0 1 3\n"),
                                   {"range.off:6:", "vertex 3 out of range [0, 2]"}));
    EXPECT_TRUE(throws_input_error(read("negative.off", head + "3 0 -1 2\n"),
                                   {"negative.off:6:", "vertex -1 out of range"}));
    EXPECT_TRUE(throws_input_error(read("few.off", head), {"few.off:", "0 of 1 faces"}));
    EXPECT_TRUE(throws_input_error(read("many.off", head + "3 0 1 2\n3 0 1 2\n"),
                                   {"many.off:7:", "after the 1 faces"}));
    EXPECT_TRUE(throws_input_error(read("empty.off", "# nothing\n"), {"empty.off:", "empty"}));
    EXPECT_TRUE(throws_input_error([&] { read_off(folder.path("absent.off")); },
                                   {"absent.off: cannot open (No such file or directory)"}));
}

TEST(OffIo, WriterChecksArgumentsAndWritesAtomically) {
    TempFolder folder;
    Eigen::MatrixXd positions(3, 3);
    positions << 0, 0, 0, 1, 0, 0, 0, 1, 0;
    Eigen::MatrixXi triangles(1, 3);
    triangles << 0, 1, 2;
    Eigen::MatrixXi bad = triangles;
    bad(0, 0) = -1;
    test::check_atomic_writes(
        folder, "mesh.off", [&](const std::string& p) { write_off(p, positions, triangles); },
        [&](const std::string& p) { write_off(p, positions, bad); });
    EXPECT_TRUE(throws_invalid_argument([&] { write_off(folder.path("x.off"), positions, bad); },
                                        "refers to vertex -1"));
    EXPECT_TRUE(throws_invalid_argument(
        [&] { write_off(folder.path("x.off"), Eigen::MatrixXd(3, 1), triangles); }, "1 columns"));
}

}  // namespace
}  // namespace sa
