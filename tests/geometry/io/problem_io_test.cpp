#include "geometry/io/problem_io.h"

#include <gtest/gtest.h>

#include "io_test_util.h"

namespace sa {
namespace {

using test::TempFolder;
using test::throws_input_error;

// A 3D surface (two triangles) mapped to the plane, with two handles.
const char* kProblem =
    "4\t3\r\n"
    "0\t0\t0\r\n"
    "1.\t0\t0\r\n"
    "1\t1\t0.5\r\n"
    "0\t1\t0\r\n"
    "4 2\r\n"
    "0 0\r\n"
    "1 0\r\n"
    "1 1\r\n"
    "0 -1e-3\r\n"
    "2 3\r\n"
    "0 1 2\r\n"
    "0 2 3\r\n"
    "2\r\n"
    "0\r\n"
    "3\r\n";

TEST(ProblemIo, ReadsRestInitialSimplicesAndHandles) {
    TempFolder folder;
    const MeshFile file = read_problem(folder.write("input", kProblem));
    ASSERT_EQ(file.mesh.vertices.rows(), 4);
    ASSERT_EQ(file.mesh.vertices.cols(), 3);
    EXPECT_EQ(file.mesh.vertices(2, 2), 0.5);
    ASSERT_TRUE(file.initial.has_value());
    ASSERT_EQ(file.initial->rows(), 4);
    ASSERT_EQ(file.initial->cols(), 2);
    EXPECT_EQ((*file.initial)(3, 1), -1e-3);
    Eigen::MatrixXi expected(2, 3);
    expected << 0, 1, 2, 0, 2, 3;
    EXPECT_EQ(file.mesh.simplices, expected);
    EXPECT_EQ(file.handles, (std::vector<Index>{0, 3}));
}

TEST(ProblemIo, HandlesAreOptionalAndMayShareALine) {
    TempFolder folder;
    const std::string base = "3 2\n0 0\n1 0\n0 1\n3 2\n0 0\n1 0\n0 1\n1 3\n0 1 2\n";
    EXPECT_TRUE(read_problem(folder.write("none", base)).handles.empty());
    EXPECT_EQ(read_problem(folder.write("inline", base + "3 2 1 0\n")).handles,
              (std::vector<Index>{2, 1, 0}));
}

TEST(ProblemIo, MalformedFilesNameTheFileAndLine) {
    TempFolder folder;
    auto read = [&](const std::string& name, const std::string& content) {
        const std::string path = folder.write(name, content);
        return [path] { read_problem(path); };
    };
    const std::string rest = "3 2\n0 0\n1 0\n0 1\n";  // lines 1-4
    const std::string init = "3 2\n0 0\n1 0\n0 1\n";  // lines 5-8
    const std::string tris = "1 3\n0 1 2\n";          // lines 9-10
    EXPECT_TRUE(
        throws_input_error(read("number", "3 2\n0 0\n1 0\n0 one\n"), {"number:4:", "'one'"}));
    EXPECT_TRUE(throws_input_error(read("row", "3 2\n0 0\n1 0 0\n"),
                                   {"row:3:", "expected 2 coordinates for vertex 1, found 3"}));
    EXPECT_TRUE(throws_input_error(read("header", "3\n"), {"header:1:", "'#V dim'"}));
    EXPECT_TRUE(throws_input_error(read("dim", "3 4\n"), {"dim:1:", "dimension 4"}));
    EXPECT_TRUE(throws_input_error(read("counts", rest + "2 2\n0 0\n1 0\n"),
                                   {"counts:5:", "2 initial positions for 3 rest vertices"}));
    EXPECT_TRUE(throws_input_error(read("range", rest + init + "1 3\n0 1 3\n"),
                                   {"range:10:", "vertex 3 out of range [0, 2]"}));
    EXPECT_TRUE(
        throws_input_error(read("arity", rest + init + "1 5\n"), {"arity:9:", "5 vertices"}));
    EXPECT_TRUE(throws_input_error(read("simplex", rest + init + "1 3\n0 1\n"),
                                   {"simplex:10:", "expected 3 vertex indices", "found 2"}));
    EXPECT_TRUE(throws_input_error(read("few", rest + init + "2 3\n0 1 2\n"),
                                   {"few:", "1 of 2 simplices"}));
    EXPECT_TRUE(throws_input_error(read("handle", rest + init + tris + "2\n0\n3\n"),
                                   {"handle:13:", "handle 3 out of range [0, 2]"}));
    EXPECT_TRUE(throws_input_error(read("repeat", rest + init + tris + "2\n1\n1\n"),
                                   {"repeat:13:", "handle 1 repeated (first on line 12)"}));
    EXPECT_TRUE(throws_input_error(read("handles", rest + init + tris + "3\n0\n1\n"),
                                   {"handles:", "2 of 3 handles"}));
    EXPECT_TRUE(throws_input_error(read("extra", rest + init + tris + "1\n0\n1\n"),
                                   {"extra:13:", "unexpected data '1'"}));
    EXPECT_TRUE(throws_input_error([&] { read_problem(folder.path("absent")); },
                                   {"absent: cannot open (No such file or directory)"}));
}

TEST(ResultRecords, ReadsTheResVRecordAmongOthers) {
    TempFolder folder;
    const std::string path = folder.write("result",
                                          "energy 2\n1.5 2.5 \n"
                                          "vert 2 2 3\n0 0 0 0 0 0 1 1 1 1 1 1\n"
                                          "resV 2 3\r\n0 0.1 0.2 1 1.1 1.2 \r\n"
                                          "minArea 1\n-1\n");
    Eigen::MatrixXd expected(2, 3);
    expected << 0, 0.1, 0.2, 1, 1.1, 1.2;
    EXPECT_EQ(read_result_positions(path), expected);
}

TEST(ResultRecords, RoundTrip) {
    TempFolder folder;
    Eigen::MatrixXd positions(3, 2);
    positions << 1.0 / 3.0, -2e-300, 5, 6, 1e300, -0.0;
    const std::string path = folder.path("result");
    write_result_records(path, positions);
    EXPECT_EQ(read_result_positions(path), positions);
    EXPECT_EQ(test::read_all(path).substr(0, 9), "resV 3 2\n");
}

TEST(ResultRecords, MalformedFiles) {
    TempFolder folder;
    auto read = [&](const std::string& name, const std::string& content) {
        const std::string path = folder.write(name, content);
        return [path] { read_result_positions(path); };
    };
    EXPECT_TRUE(throws_input_error(read("absent_record", "energy 2\n1 2\n"),
                                   {"absent_record: no 'resV n d' record"}));
    EXPECT_TRUE(throws_input_error(read("count", "resV 2 2\n1 2 3\n"),
                                   {"count:2:", "expected 4 values", "found 3"}));
    EXPECT_TRUE(throws_input_error(read("value", "resV 1 2\n1 two\n"), {"value:2:", "'two'"}));
    EXPECT_TRUE(throws_input_error(read("dims", "resV 4\n1 2 3 4\n"), {"dims:1:", "'resV n d'"}));
    EXPECT_TRUE(throws_input_error(read("header", "energy\n"), {"header:1:", "record header"}));
    EXPECT_TRUE(throws_input_error(read("header2", "energy x\n"), {"header2:1:", "'x'"}));
    EXPECT_TRUE(throws_input_error(read("eof", "resV 1 2\n"), {"eof:", "before the values"}));
    EXPECT_TRUE(throws_input_error([&] { read_result_positions(folder.path("absent")); },
                                   {"absent: cannot open"}));
}

TEST(ResultRecords, WriterWritesAtomically) {
    TempFolder folder;
    Eigen::MatrixXd positions = Eigen::MatrixXd::Ones(2, 3);
    Eigen::MatrixXd bad = positions;
    bad(1, 2) = std::numeric_limits<double>::infinity();
    test::check_atomic_writes(
        folder, "result", [&](const std::string& p) { write_result_records(p, positions); },
        [&](const std::string& p) { write_result_records(p, bad); });
}

TEST(ProblemIo, APlanarRestShapeTakesAPlanarInitialMap) {
    TempFolder folder;
    const std::string rest = "3 2\n0 0\n1 0\n0 1\n";
    const std::string tris = "1 3\n0 1 2\n";
    // z = 0 everywhere: nothing is lost, the map is planar.
    const MeshFile flat =
        read_problem(folder.write("flat", rest + "3 3\n0 0 0\n2 0 0\n0 2 0\n" + tris));
    ASSERT_TRUE(flat.initial.has_value());
    EXPECT_EQ(flat.initial->cols(), 2);
    EXPECT_EQ((*flat.initial)(1, 0), 2.0);
    // A z that is not 0 would be dropped: an error naming the vertex, its line and the header's.
    EXPECT_TRUE(throws_input_error(
        [&] { read_problem(folder.write("lifted", rest + "3 3\n0 0 0\n1 0 0.5\n0 1 0\n" + tris)); },
        {"lifted:7:", "vertex 1 has z = 0.5", "the rest shape is 2D (header on line 5)"}));
}

}  // namespace
}  // namespace sa
