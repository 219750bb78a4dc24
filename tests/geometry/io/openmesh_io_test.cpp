#include "geometry/io/openmesh_io.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#include "io_test_util.h"

namespace sa {
namespace {

using test::TempFolder;
using test::throws_input_error;

std::string ply(const std::string& vertices, int num_vertices, const std::string& faces,
                int num_faces) {
    return "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\nelement vertex " +
           std::to_string(num_vertices) +
           "\r\nproperty double x\r\nproperty double y\r\nproperty double z\r\n"
           "element face " +
           std::to_string(num_faces) +
           "\r\nproperty list uchar int vertex_indices\r\nend_header\r\n" + vertices + faces;
}

const char* kSquare = "0 0 0\n0.1 0 0.3333333333333333\n1 1 0\n0 1 0\n";

TEST(OpenMeshIo, ReadsAsciiPly) {
    TempFolder folder;
    const MeshFile file =
        read_ply(folder.write("square.ply", ply(kSquare, 4, "3 0 1 2\n3 0 2 3\n", 2)));
    ASSERT_EQ(file.mesh.vertices.rows(), 4);
    ASSERT_EQ(file.mesh.vertices.cols(), 3);
    // OpenMesh passes coordinates as floats.
    EXPECT_EQ(file.mesh.vertices(1, 0), static_cast<double>(0.1f));
    EXPECT_EQ(file.mesh.vertices(1, 2), static_cast<double>(1.0f / 3.0f));
    Eigen::MatrixXi expected(2, 3);
    expected << 0, 1, 2, 0, 2, 3;
    EXPECT_EQ(file.mesh.simplices, expected);
}

TEST(OpenMeshIo, ReadsBinaryPlyWhateverTheExtensionCase) {
    TempFolder folder;
    std::string content =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
        "property float y\nproperty float z\nelement face 1\n"
        "property list uchar int vertex_indices\nend_header\n";
    const float points[9] = {0, 0, 0, 1, 0, 0, 0, 2, 0};
    content.append(reinterpret_cast<const char*>(points), sizeof(points));
    content.push_back(3);
    const std::int32_t face[3] = {0, 1, 2};
    content.append(reinterpret_cast<const char*>(face), sizeof(face));
    const MeshFile file = read_ply(folder.write("tri.PLY", content));
    ASSERT_EQ(file.mesh.vertices.rows(), 3);
    EXPECT_EQ(file.mesh.vertices(2, 1), 2.0);
    EXPECT_EQ(file.mesh.simplices.rows(), 1);
}

TEST(OpenMeshIo, ReadsAsciiAndBinaryStlMergingCorners) {
    TempFolder folder;
    const std::string ascii =
        "solid square\n"
        "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 1 1 0\n"
        " endloop\nendfacet\n"
        "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 1 0\n  vertex 0 1 0\n"
        " endloop\nendfacet\n"
        "endsolid square\n";
    const MeshFile file = read_stl(folder.write("square.stl", ascii));
    EXPECT_EQ(file.mesh.vertices.rows(), 4);
    ASSERT_EQ(file.mesh.simplices.rows(), 2);
    EXPECT_EQ(file.mesh.simplices(1, 0), file.mesh.simplices(0, 0));

    std::string binary(80, ' ');
    const std::uint32_t count = 2;
    binary.append(reinterpret_cast<const char*>(&count), 4);
    const float triangles[2][12] = {{0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 1, 0},
                                    {0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 1, 0}};
    for (const auto& triangle : triangles) {
        binary.append(reinterpret_cast<const char*>(triangle), sizeof(triangle));
        binary.append(2, '\0');
    }
    const MeshFile from_binary = read_stl(folder.write("square_b.stl", binary));
    EXPECT_EQ(from_binary.mesh.vertices.rows(), 4);
    EXPECT_EQ(from_binary.mesh.simplices.rows(), 2);
}

TEST(OpenMeshIo, RefusedFacesAndBadFilesAreErrorsAndNothingIsPrinted) {
    TempFolder folder;
    auto read = [&](const std::string& name, const std::string& content) {
        const std::string path = folder.write(name, content);
        return [path] { read_ply(path); };
    };
    testing::internal::CaptureStderr();
    testing::internal::CaptureStdout();
    // Three triangles on one edge: OpenMesh refuses the third ("complex edge").
    EXPECT_TRUE(throws_input_error(read("fan.ply", ply("0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n", 5,
                                                       "3 0 1 2\n3 1 0 3\n3 0 1 4\n", 3)),
                                   {"fan.ply:", "refused 1 of 3 faces as non-manifold"}));
    EXPECT_TRUE(throws_input_error(read("equal.ply", ply(kSquare, 4, "3 0 1 2\n3 0 0 3\n", 2)),
                                   {"equal.ply:", "dropped 1 of 2 faces"}));
    EXPECT_TRUE(throws_input_error(read("range.ply", ply(kSquare, 4, "3 0 1 4\n3 0 2 3\n", 2)),
                                   {"range.ply:", "dropped 1 of 2 faces"}));
    EXPECT_TRUE(throws_input_error(read("quad.ply", ply(kSquare, 4, "4 0 1 2 3\n", 1)),
                                   {"quad.ply:", "face 0 with 4 vertices"}));
    EXPECT_TRUE(throws_input_error(read("garbage.ply", "this is not a ply file\n"),
                                   {"garbage.ply:1: not a PLY file: expected 'ply', found "
                                    "'this is not a ply file'"}));
    EXPECT_TRUE(throws_input_error(read("header.ply", "ply\nformat ascii 1.0\n"),
                                   {"header.ply: the PLY header has no 'end_header' line"}));
    EXPECT_TRUE(throws_input_error(read("header.ply", "ply\nformat ascii 1.0\nend_header\n"),
                                   {"header.ply:", "cannot read as PLY"}));
    // A format line OpenMesh's reader looped on for ever (its version not a number; found by
    // fuzz_ply_stl), a version of 150 digits (its warnings grew past 2 GB; likewise), and other
    // malformed ones.
    for (const std::string format :
         {std::string("format ascii float z"), std::string("format nonsense"),
          std::string("format ascii"), std::string("format ascii 1.0 x"),
          std::string("format binary 1.0"), std::string("format ascii 2.0"),
          "format binary_little_endian " + std::string(150, '3') + "1.0"}) {
        EXPECT_TRUE(throws_input_error(
            read("format.ply", "ply\n" + format + "\nend_header\n"),
            {"format.ply:2: expected 'format ascii|binary_little_endian|binary_big_endian 1.0'"}))
            << format;
    }
    EXPECT_TRUE(throws_input_error(
        read("twice.ply", "ply\nformat ascii 1.0\nformat ascii 1.0\nend_header\n"),
        {"twice.ply:3: a second 'format' line"}));
    // A property before any element made OpenMesh's reader write through a missing element.
    EXPECT_TRUE(throws_input_error(
        read("order.ply", "ply\nformat ascii 1.0\nproperty float x\nend_header\n"),
        {"order.ply:3: a PLY property before any element"}));
    EXPECT_TRUE(throws_input_error(
        [&] { read_stl(folder.write("text.stl", "hello\n")); },
        {"text.stl: not an STL file: neither ASCII ('solid' on line 1, found 'hello')"}));
    EXPECT_TRUE(throws_input_error(read("short.ply", ply("0 0 0\n", 4, "", 0)),
                                   {"short.ply:", "PLY body", "is cut short"}));
    EXPECT_TRUE(throws_input_error(
        [&] { read_stl(folder.write("garbage.stl", "solid x\nfacet normal oops\n")); },
        {"garbage.stl:", "dropped 1 of 1 face"}));
    const std::string printed =
        testing::internal::GetCapturedStdout() + testing::internal::GetCapturedStderr();
    EXPECT_EQ(printed, "");
    EXPECT_TRUE(throws_input_error([&] { read_ply(folder.path("absent.ply")); },
                                   {"absent.ply: cannot open (No such file or directory)"}));
    EXPECT_TRUE(throws_input_error([&] { read_stl(folder.path("absent.stl")); },
                                   {"absent.stl: cannot open (No such file or directory)"}));
}

}  // namespace
}  // namespace sa
