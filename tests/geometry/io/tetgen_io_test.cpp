#include "geometry/io/tetgen_io.h"

#include <gtest/gtest.h>

#include "io_test_util.h"

namespace sa {
namespace {

using test::TempFolder;
using test::throws_input_error;
using test::throws_invalid_argument;

const char* kNode1 =
    "5 3 0 0\n"
    "1 0 0 0\n"
    "2 1 0 0\n"
    "3 0 1 0\n"
    "4 0 0 1\n"
    "5 1 1 1\n";

TEST(TetgenIo, ReadsOneBasedFilesFromEitherName) {
    TempFolder folder;
    folder.write("a.node", kNode1);
    folder.write("a.ele",
                 "# two tets\r\n"
                 "2 4 0\r\n"
                 "  1 1 2 3 4\r\n"
                 "\t2 2 3 4 5 # last\r\n");
    for (const char* name : {"a.node", "a.ele"}) {
        const MeshFile file = read_tetgen(folder.path(name));
        ASSERT_EQ(file.mesh.vertices.rows(), 5);
        ASSERT_EQ(file.mesh.vertices.cols(), 3);
        EXPECT_EQ(file.mesh.vertices(4, 2), 1.0);
        Eigen::MatrixXi expected(2, 4);
        expected << 0, 1, 2, 3, 1, 2, 3, 4;
        EXPECT_EQ(file.mesh.simplices, expected);
    }
}

TEST(TetgenIo, ElementsUseTheNodeNumbering) {
    TempFolder folder;
    // 0-based .node with attributes and markers, 1-based .ele rows with an attribute: the vertex
    // references follow the .node.
    folder.write("b.node",
                 "4 3 2 1\n"
                 "0 0 0 0 7 8 1\n"
                 "1 1 0 0 7 8 1\n"
                 "2 0 1 0 7 8 0\n"
                 "3 0 0 1 7 8 0\n");
    folder.write("b.ele", "1 4 1\n1 0 1 2 3 5\n");
    const MeshFile file = read_tetgen(folder.path("b.node"));
    Eigen::MatrixXi expected(1, 4);
    expected << 0, 1, 2, 3;
    EXPECT_EQ(file.mesh.simplices, expected);
    EXPECT_EQ(file.mesh.vertices(1, 0), 1.0);
}

TEST(TetgenIo, RoundTripWritesBothFilesZeroBased) {
    TempFolder folder;
    Eigen::MatrixXd positions(5, 3);
    positions << 0, 0, 0, 1.0 / 3.0, 0, 0, 0, 1, 0, 0, 0, 1, 1e-17, 1, -1e300;
    Eigen::MatrixXi tets(2, 4);
    tets << 0, 1, 2, 3, 1, 2, 3, 4;
    write_tetgen(folder.path("out.ele"), positions, tets);
    EXPECT_EQ(test::read_all(folder.path("out.ele")).substr(0, 14), "2 4 0\n0 0 1 2 ");
    const MeshFile file = read_tetgen(folder.path("out.node"));
    EXPECT_EQ(file.mesh.vertices, positions);
    EXPECT_EQ(file.mesh.simplices, tets);
    EXPECT_EQ(folder.entries(), 2u);

    // A failed write leaves the existing pair alone.
    Eigen::MatrixXi bad = tets;
    bad(1, 3) = 5;
    const std::string before = test::read_all(folder.path("out.node"));
    EXPECT_TRUE(
        throws_invalid_argument([&] { write_tetgen(folder.path("out.node"), positions, bad); },
                                "tets row 1 refers to vertex 5"));
    EXPECT_EQ(test::read_all(folder.path("out.node")), before);
    EXPECT_THROW(write_tetgen(folder.path("missing/out.node"), positions, tets), InputError);
    EXPECT_EQ(folder.entries(), 2u);
    EXPECT_TRUE(throws_invalid_argument(
        [&] { write_tetgen(folder.path("out.txt"), positions, tets); }, ".node or .ele"));
    EXPECT_TRUE(throws_invalid_argument(
        [&] { write_tetgen(folder.path("out.node"), positions.leftCols(2), tets); }, "2 columns"));
}

TEST(TetgenIo, MalformedFilesNameTheFileAndLine) {
    TempFolder folder;
    auto read = [&](const std::string& stem, const std::string& node, const std::string& ele) {
        folder.write(stem + ".node", node);
        folder.write(stem + ".ele", ele);
        const std::string path = folder.path(stem + ".node");
        return [path] { read_tetgen(path); };
    };
    const std::string ele = "1 4 0\n1 1 2 3 4\n";
    EXPECT_TRUE(throws_input_error(
        read("rest", "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 1\n5 1 1 1\n", ele),
        {"rest.node:5: expected 4 numbers (index x y z), found 3"}));
    EXPECT_TRUE(throws_input_error(read("attr", "1 3 2 1\n1 0 0 0 1 1\n", ele),
                                   {"attr.node:2:", "expected 7 numbers", "2 attributes, marker"}));
    EXPECT_TRUE(
        throws_input_error(read("number", "1 3 0 0\n1 0 0 O\n", ele), {"number.node:2:", "'O'"}));
    EXPECT_TRUE(throws_input_error(read("header", "5 3 0\n", ele), {"header.node:1:", "header"}));
    EXPECT_TRUE(throws_input_error(read("dim", "5 2 0 0\n", ele), {"dim.node:1:", "dimension 2"}));
    EXPECT_TRUE(throws_input_error(read("first", "1 3 0 0\n2 0 0 0\n", ele),
                                   {"first.node:2:", "first row index is 2"}));
    EXPECT_TRUE(
        throws_input_error(read("sequence", "2 3 0 0\n0 0 0 0\n2 0 0 0\n", ele),
                           {"sequence.node:3:", "row index 2 out of sequence; expected 1"}));
    EXPECT_TRUE(throws_input_error(read("few", "3 3 0 0\n0 0 0 0\n", ele),
                                   {"few.node:", "1 of 3 vertex rows"}));
    EXPECT_TRUE(throws_input_error(read("range", kNode1, "1 4 0\n# c\n1 1 2 3 6\n"),
                                   {"range.ele:3: vertex 6 out of range [1, 5]"}));
    EXPECT_TRUE(throws_input_error(read("zero", kNode1, "1 4 0\n1 0 1 2 3\n"),
                                   {"zero.ele:2: vertex 0 out of range [1, 5]"}));
    EXPECT_TRUE(throws_input_error(read("quadratic", kNode1, "1 10 0\n"),
                                   {"quadratic.ele:1:", "10 nodes per element"}));
    EXPECT_TRUE(throws_input_error(read("elems", kNode1, "2 4 0\n1 1 2 3 4\n"),
                                   {"elems.ele:", "1 of 2 tetrahedra"}));
    EXPECT_TRUE(throws_input_error(read("extra", kNode1, "1 4 0\n1 1 2 3 4\n2 1 2 3 5\n"),
                                   {"extra.ele:3:", "after the 1 tetrahedra"}));
    EXPECT_TRUE(throws_input_error(read("index", kNode1, "1 4 0\n1 1 2 3.0 4\n"),
                                   {"index.ele:2:", "'3.0'"}));
    folder.write("lonely.node", kNode1);
    EXPECT_TRUE(throws_input_error([&] { read_tetgen(folder.path("lonely.node")); },
                                   {"lonely.ele: cannot open (No such file or directory)"}));
}

}  // namespace
}  // namespace sa
