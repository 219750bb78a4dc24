#include "geometry/io/openmesh_io.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#include "io_test_util.h"

namespace sa {
namespace {

using test::TempFolder;
using test::throws_input_error;

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

TEST(OpenMeshIo, BadStlFilesAreErrorsAndNothingIsPrinted) {
    TempFolder folder;
    testing::internal::CaptureStderr();
    testing::internal::CaptureStdout();
    EXPECT_TRUE(throws_input_error(
        [&] { read_stl(folder.write("text.stl", "hello\n")); },
        {"text.stl: not an STL file: neither ASCII ('solid' on line 1, found 'hello')"}));
    EXPECT_TRUE(throws_input_error(
        [&] { read_stl(folder.write("garbage.stl", "solid x\nfacet normal oops\n")); },
        {"garbage.stl:", "dropped 1 of 1 face"}));
    const std::string printed =
        testing::internal::GetCapturedStdout() + testing::internal::GetCapturedStderr();
    EXPECT_EQ(printed, "");
    EXPECT_TRUE(throws_input_error([&] { read_stl(folder.path("absent.stl")); },
                                   {"absent.stl: cannot open (No such file or directory)"}));
}

}  // namespace
}  // namespace sa
