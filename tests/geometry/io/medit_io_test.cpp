#include "geometry/io/medit_io.h"

#include <gtest/gtest.h>

#include <fstream>

#include "io_test_util.h"

namespace sa {
namespace {

using test::TempFolder;
using test::throws_input_error;
using test::throws_invalid_argument;

const char* kVertices =
    "MeshVersionFormatted 2\r\n"
    "\r\n"
    "Dimension\r\n"
    "3\r\n"
    "Vertices\r\n"
    "5\r\n"
    "0 0 0 1\r\n"
    "1 0 0 1\r\n"
    "0 1 0 1\r\n"
    "0 0 1 0\r\n"
    " 1 1 1 0 \r\n";

TEST(MeditIo, TetrahedraWinOverTrianglesAndKnownSectionsAreSkipped) {
    TempFolder folder;
    const std::string path = folder.write("a.mesh", std::string(kVertices) +
                                                        "# a comment\r\n"
                                                        "Edges\r\n1\r\n1 2 0\r\n"
                                                        " Triangles\r\n1\r\n1 2 3 0\r\n"
                                                        "Corners 2\r\n1\r\n2\r\n"
                                                        "Tetrahedra\r\n2\r\n"
                                                        "1 2 3 4 0\r\n2 3 4 5 1\r\n"
                                                        "NormalAtVertices\r\n1\r\n1 1\r\n"
                                                        "RequiredTetrahedra\r\n1\r\n2\r\n"
                                                        "Pyramids\r\n1\r\n1 2 3 4 5 0\r\n"
                                                        "End\r\n"
                                                        "anything after End is ignored\r\n");
    const MeshFile file = read_medit(path);
    ASSERT_EQ(file.mesh.vertices.rows(), 5);
    ASSERT_EQ(file.mesh.vertices.cols(), 3);
    EXPECT_EQ(file.mesh.vertices(3, 2), 1.0);
    Eigen::MatrixXi expected(2, 4);
    expected << 0, 1, 2, 3, 1, 2, 3, 4;
    EXPECT_EQ(file.mesh.simplices, expected);
    ASSERT_EQ(file.warnings.size(), 1u);  // the pyramid is not a simplex
    EXPECT_NE(file.warnings[0].find("skipped 1 Pyramids"), std::string::npos) << file.warnings[0];
}

TEST(MeditIo, TrianglesWhenNoTetrahedraAndTwoDimensions) {
    TempFolder folder;
    const MeshFile file = read_medit(folder.write(
        "t.mesh", std::string(kVertices) + "Triangles 2\n1 2 3 0\n3 2 5 0\nQuadrilaterals 1\n"
                                           "1 2 3 4 0\nTetrahedra\n0\n"));
    Eigen::MatrixXi expected(2, 3);
    expected << 0, 1, 2, 2, 1, 4;
    EXPECT_EQ(file.mesh.simplices, expected);
    ASSERT_EQ(file.warnings.size(), 1u);
    EXPECT_NE(file.warnings[0].find("skipped 1 Quadrilaterals"), std::string::npos);

    const MeshFile flat = read_medit(
        folder.write("flat.mesh",
                     "MeshVersionFormatted 1 Dimension 2\nVertices 3\n0 0 1\n1 0 1\n0 1 1\n"
                     "Triangles 1\n1 2 3 7\nEnd\n"));
    ASSERT_EQ(flat.mesh.vertices.cols(), 2);
    EXPECT_EQ(flat.mesh.vertices(1, 0), 1.0);
    EXPECT_EQ(flat.mesh.simplices.rows(), 1);
}

TEST(MeditIo, RoundTrip) {
    TempFolder folder;
    Eigen::MatrixXd positions(5, 3);
    positions << 0, 0, 0, 1.0 / 3.0, 0, 0, 0, 1, 0, 0, 0, 1, 1e-17, 1, -1e300;
    Eigen::MatrixXi tets(2, 4);
    tets << 0, 1, 2, 3, 1, 2, 3, 4;
    const std::string path = folder.path("out.mesh");
    write_medit(path, positions, tets);
    const MeshFile file = read_medit(path);
    EXPECT_EQ(file.mesh.vertices, positions);
    EXPECT_EQ(file.mesh.simplices, tets);

    Eigen::MatrixXi triangles(2, 3);
    triangles << 0, 1, 2, 2, 1, 3;
    write_medit(path, positions.leftCols(2), triangles);
    const MeshFile flat = read_medit(path);
    EXPECT_EQ(flat.mesh.vertices, positions.leftCols(2));
    EXPECT_EQ(flat.mesh.simplices, triangles);
}

// Hexahedra (geometry/mesh/hex_mesh.h) are written in their own section, which the reader of
// simplicial meshes skips by its row size with a warning.
TEST(MeditIo, HexahedraAreWrittenAndSkippedOnReading) {
    TempFolder folder;
    Eigen::MatrixXd positions(8, 3);
    positions << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1;
    Eigen::MatrixXi hexes(1, 8);
    hexes << 0, 1, 2, 3, 4, 5, 6, 7;
    const std::string path = folder.path("hex.mesh");
    write_medit(path, positions, hexes);
    std::ifstream in(path);
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    EXPECT_NE(text.find("Hexahedra\n1\n1 2 3 4 5 6 7 8 0\n"), std::string::npos) << text;
    const MeshFile file = read_medit(path);
    EXPECT_EQ(file.mesh.vertices, positions);
    ASSERT_EQ(file.warnings.size(), 1u);
    EXPECT_NE(file.warnings[0].find("skipped 1 Hexahedra"), std::string::npos) << file.warnings[0];
    EXPECT_TRUE(throws_invalid_argument(
        [&] { write_medit(folder.path("x.mesh"), positions.leftCols(2), hexes); }, "3D"));
    hexes(0, 7) = 8;
    EXPECT_TRUE(
        throws_invalid_argument([&] { write_medit(folder.path("x.mesh"), positions, hexes); },
                                "hexahedra row 0 refers to vertex 8"));
}

TEST(MeditIo, MalformedFilesNameTheFileAndLine) {
    TempFolder folder;
    auto read = [&](const std::string& name, const std::string& content) {
        const std::string path = folder.write(name, content);
        return [path] { read_medit(path); };
    };
    const std::string v =
        "MeshVersionFormatted 1\nDimension 3\nVertices\n3\n0 0 0 0\n1 0 0 0\n"
        "0 1 0 0\n";  // lines 1-7
    EXPECT_TRUE(throws_input_error(read("keyword.mesh", v + "Octahedra\n0\n"),
                                   {"keyword.mesh:8:", "unknown keyword 'Octahedra'"}));
    EXPECT_TRUE(throws_input_error(read("number.mesh", v + "Triangles\n1\n1 2 x 0\n"),
                                   {"number.mesh:10:", "'x'"}));
    EXPECT_TRUE(throws_input_error(read("row.mesh", v + "Triangles\n1\n1 2 3\n"),
                                   {"row.mesh:10:", "expected 4 numbers (a b c ref)", "found 3"}));
    EXPECT_TRUE(
        throws_input_error(read("vertex.mesh", "Dimension 3\nVertices\n1\n0 0 0\n"),
                           {"vertex.mesh:4:", "expected 4 numbers (x y z ref)", "found 3"}));
    EXPECT_TRUE(throws_input_error(read("range.mesh", v + "Tetrahedra\n1\n1 2 3 4 0\n"),
                                   {"range.mesh:10: vertex 4 out of range [1, 3]"}));
    // The boundary Triangles beside tets are not kept, and checked all the same.
    EXPECT_TRUE(throws_input_error(
        read("boundary.mesh", v + "Tetrahedra\n1\n1 2 3 1 0\nTriangles\n1\n1 2 999 0\n"),
        {"boundary.mesh:13: vertex 999 out of range [1, 3]"}));
    EXPECT_TRUE(throws_input_error(read("zero.mesh", v + "Triangles\n1\n0 1 2 0\n"),
                                   {"zero.mesh:10:", "vertex 0"}));
    EXPECT_TRUE(throws_input_error(read("count.mesh", v + "Triangles\n2\n1 2 3 0\nEnd\n"),
                                   {"count.mesh:11:", "found 1"}));
    EXPECT_TRUE(throws_input_error(read("eof.mesh", v + "Triangles\n2\n1 2 3 0\n"),
                                   {"eof.mesh:", "1 of 2 Triangles"}));
    EXPECT_TRUE(throws_input_error(read("skip.mesh", v + "Edges\n2\n1 2 0\n"),
                                   {"skip.mesh:", "inside Edges"}));
    EXPECT_TRUE(throws_input_error(read("dim.mesh", "Dimension 4\n"), {"dim.mesh:1:", "4"}));
    EXPECT_TRUE(throws_input_error(read("nodim.mesh", "Vertices\n0\n"),
                                   {"nodim.mesh:1:", "Vertices before Dimension"}));
    EXPECT_TRUE(throws_input_error(read("tets2d.mesh", "Dimension 2\nTetrahedra\n0\n"),
                                   {"tets2d.mesh:2:", "2D"}));
    EXPECT_TRUE(throws_input_error(read("negative.mesh", v + "Triangles\n-1\n"),
                                   {"negative.mesh:9:", "negative"}));
    EXPECT_TRUE(throws_input_error([&] { read_medit(folder.path("absent.mesh")); },
                                   {"absent.mesh: cannot open (No such file or directory)"}));
}

TEST(MeditIo, WriterChecksArgumentsAndWritesAtomically) {
    TempFolder folder;
    Eigen::MatrixXd positions(4, 3);
    positions << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
    Eigen::MatrixXi tets(1, 4);
    tets << 0, 1, 2, 3;
    Eigen::MatrixXi bad = tets;
    bad(0, 1) = 4;
    test::check_atomic_writes(
        folder, "mesh.mesh", [&](const std::string& p) { write_medit(p, positions, tets); },
        [&](const std::string& p) { write_medit(p, positions, bad); });
    EXPECT_TRUE(throws_invalid_argument(
        [&] { write_medit(folder.path("x.mesh"), positions.leftCols(2), tets); }, "3D"));
}

}  // namespace
}  // namespace sa
