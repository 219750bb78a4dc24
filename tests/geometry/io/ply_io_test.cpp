#include "geometry/io/ply_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

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

TEST(PlyIo, ReadsAsciiPlyInDoublePrecision) {
    TempFolder folder;
    const MeshFile file =
        read_ply(folder.write("square.ply", ply(kSquare, 4, "3 0 1 2\n3 0 2 3\n", 2)));
    ASSERT_EQ(file.mesh.vertices.rows(), 4);
    ASSERT_EQ(file.mesh.vertices.cols(), 3);
    EXPECT_EQ(file.mesh.vertices(1, 0), 0.1);
    EXPECT_EQ(file.mesh.vertices(1, 2), 0.3333333333333333);
    Eigen::MatrixXi expected(2, 3);
    expected << 0, 1, 2, 0, 2, 3;
    EXPECT_EQ(file.mesh.simplices, expected);
}

/// `values` as `T` in the byte order of `big_endian`.
template <class T>
std::string binary(std::initializer_list<T> values, bool big_endian) {
    std::string bytes;
    for (const T value : values) {
        char raw[sizeof(T)];
        std::memcpy(raw, &value, sizeof(T));
        if (big_endian) std::reverse(raw, raw + sizeof(T));
        bytes.append(raw, sizeof(T));
    }
    return bytes;
}

// Both byte orders, extra vertex properties (normals, colours), another element, a face list
// named vertex_index with an unsigned index type, and the extension in capitals.
TEST(PlyIo, ReadsBinaryPlyInBothByteOrders) {
    TempFolder folder;
    for (const bool big : {false, true}) {
        SCOPED_TRACE(big ? "big-endian" : "little-endian");
        std::string content = std::string("ply\nformat ") +
                              (big ? "binary_big_endian" : "binary_little_endian") +
                              " 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                              "property double z\nproperty uchar red\nelement material 1\n"
                              "property list uchar float values\nelement face 1\n"
                              "property list uint8 uint32 vertex_index\nend_header\n";
        for (int v = 0; v < 3; ++v) {
            content += binary<float>({float(v == 1), 2.0f * (v == 2)}, big);
            content += binary<double>({0.1 * v}, big);
            content += binary<std::uint8_t>({255}, big);
        }
        content += binary<std::uint8_t>({2}, big) + binary<float>({1, 2}, big);
        content += binary<std::uint8_t>({3}, big) + binary<std::uint32_t>({0, 1, 2}, big);
        const MeshFile file = read_ply(folder.write("tri.PLY", content));
        ASSERT_EQ(file.mesh.vertices.rows(), 3);
        EXPECT_EQ(file.mesh.vertices(2, 1), 2.0);
        EXPECT_EQ(file.mesh.vertices(2, 2), 0.2);
        Eigen::MatrixXi expected(1, 3);
        expected << 0, 1, 2;
        EXPECT_EQ(file.mesh.simplices, expected);
    }
}

// A binary body with one face more than its header declares is refused at the first byte past
// the declared rows; a final newline after them is not data.
TEST(PlyIo, BinaryRowsBeyondTheHeadersCountAreRefused) {
    TempFolder folder;
    const std::string header =
        "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
        "property float y\nproperty float z\nelement face 1\n"
        "property list uchar int vertex_indices\nend_header\n";
    std::string body;
    for (int v = 0; v < 4; ++v) body += binary<float>({float(v % 2), float(v / 2), 0.0f}, false);
    const std::string face =
        binary<std::uint8_t>({3}, false) + binary<std::int32_t>({0, 1, 2}, false);
    const std::string extra =
        binary<std::uint8_t>({3}, false) + binary<std::int32_t>({1, 3, 2}, false);
    EXPECT_EQ(read_ply(folder.write("one.ply", header + body + face + "\n")).mesh.simplices.rows(),
              1);
    const std::string offset = std::to_string(header.size() + body.size() + face.size());
    EXPECT_TRUE(throws_input_error(
        [&] { read_ply(folder.write("two.ply", header + body + face + extra)); },
        {"two.ply: byte " + offset +
         ": unexpected data after the PLY body (element 'face' declares 1 row): 13 more bytes"}));
}

// Faces are kept as the file lists them (three triangles on one edge included: the front-ends
// check the topology they need).
TEST(PlyIo, KeepsFacesAsListed) {
    TempFolder folder;
    const MeshFile file =
        read_ply(folder.write("fan.ply", ply("0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n", 5,
                                             "3 0 1 2\n3 1 0 3\n3 0 1 4\n", 3)));
    EXPECT_EQ(file.mesh.simplices.rows(), 3);
}

TEST(PlyIo, MalformedFilesAreNamedWithTheirLineAndNothingIsPrinted) {
    TempFolder folder;
    auto read = [&](const std::string& name, const std::string& content) {
        const std::string path = folder.write(name, content);
        return [path] { read_ply(path); };
    };
    const std::string header =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
        "property float y\nproperty float z\n";
    const std::string tri = header +
                            "element face 1\nproperty list uchar int vertex_indices\n"
                            "end_header\n0 0 0\n1 0 0\n0 1 0\n";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {ply(kSquare, 4, "3 0 1 2\n3 0 0 3\n", 2), "16: face 1 repeats vertex 0"},
        {ply(kSquare, 4, "3 0 1 4\n3 0 2 3\n", 2),
         "15: face 0 refers to vertex 4, out of range [0, 3]"},
        {ply(kSquare, 4, "4 0 1 2 3\n", 1), "15: face 0 with 4 vertices; only triangles"},
        {"this is not a ply file\n",
         "1: not a PLY file: expected 'ply', found "
         "'this is not a ply file'"},
        {std::string("\x1f\x8b\x08\0\0\0", 6),
         "1: not a PLY file: expected 'ply', found binary "
         "data"},
        {"ply\nformat ascii 1.0\nend_header\n", " no 'vertex' element in the PLY header"},
        {"ply\nend_header\n", "2: the PLY header has no 'format' line"},
        {"ply\nformat ascii 1.0\nformat ascii 1.0\nend_header\n",
         "3: a second 'format' line in the PLY header"},
        {"ply\nformat ascii 1.0\nproperty float x\nend_header\n",
         "3: a PLY property before any element"},
        {"ply\nformat ascii 1.0\nelemXnt vertex 3\nend_header\n",
         "3: not a PLY header line: 'elemXnt'"},
        // What OpenMesh's reader looped on for ever (fuzz_ply_stl).
        {"ply\nend_header binary_little_endian 1.0\nelement vertex 3r\nee",
         "2: 'end_header' with more on its line"},
        {"ply\nformat ascii 1.0\nelement vertex 3r\nend_header\n",
         "3: expected 'element NAME COUNT' in the PLY header"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nelement vertex 1\nend_header\n",
         "4: a second PLY element 'vertex'"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nproperty list float int x\nend_header\n",
         "4: expected 'property TYPE NAME' or 'property list TYPE TYPE NAME'"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nproperty\nend_header\n",  // fuzz_ply_stl
         "4: expected 'property TYPE NAME' or 'property list TYPE TYPE NAME'"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n",
         "3: the vertex element has no property y"},
        {header +
             "element face 1\nproperty int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n0\n",
         "7: the face element has no list property vertex_indices"},
        {tri, "12: the PLY body's element 'face' (a list length): the PLY body is cut short"},
        {tri + "3 0 1 x\n", "13: the PLY body's element 'face' holds 'x' where a whole number"},
        {tri + "300 0 1 2\n", "13: face 0 with 300 vertices"},
        {header + "end_header\n0 0 0\n1 0 0\n0 1 x\n",
         "10: the PLY body's element 'vertex' holds "
         "'x' where a number belongs"},
        {header + "end_header\n0 0 0\n",
         "8: the PLY body is cut short: element 'vertex' declares "
         "3 rows"},
        {header + "element face 2000000000\nproperty list uchar int vertex_indices\nend_header\n"
                  "0 0 0\n1 0 0\n0 1 0\n",
         "12: the PLY body is cut short: element 'face' declares 2000000000 rows"},
        {ply("0 0 0\n", 4, "", 0), "11: the PLY body is cut short: element 'vertex' declares 4"},
        // More rows than the header declares, or text after the last one: not a smaller mesh.
        {ply(kSquare, 4, "3 0 1 2\n3 0 2 3\n", 1),
         "16: unexpected data after the PLY body (element 'face' declares 1 row): '3'"},
        {ply(kSquare, 4, "3 0 1 2\n3 0 2 3\n", 2) + "\n  made by hand\n",
         "18: unexpected data after the PLY body (element 'face' declares 2 rows): 'made'"},
    };
    testing::internal::CaptureStderr();
    testing::internal::CaptureStdout();
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const std::string name = "case" + std::to_string(i) + ".ply";
        SCOPED_TRACE(name);
        EXPECT_TRUE(throws_input_error(read(name, cases[i].first), {name + ":" + cases[i].second}));
    }
    EXPECT_TRUE(throws_input_error(read("header.ply", "ply\nformat ascii 1.0\n"),
                                   {"header.ply: the PLY header has no 'end_header' line"}));
    const std::string printed =
        testing::internal::GetCapturedStdout() + testing::internal::GetCapturedStderr();
    EXPECT_EQ(printed, "");
    EXPECT_TRUE(throws_input_error([&] { read_ply(folder.path("absent.ply")); },
                                   {"absent.ply: cannot open (No such file or directory)"}));
}

}  // namespace
}  // namespace sa
