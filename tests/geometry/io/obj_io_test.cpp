#include "geometry/io/obj_io.h"

#include <gtest/gtest.h>

#include "io_test_util.h"

namespace sa {
namespace {

using test::TempFolder;
using test::throws_input_error;
using test::throws_invalid_argument;

TEST(ObjIo, ReadsVerticesFacesAndIgnoresOtherKeywords) {
    TempFolder folder;
    const std::string path = folder.write("mesh.obj",
                                          "# a comment\r\n"
                                          "mtllib m.mtl\r\n"
                                          "o square\r\n"
                                          "  v 0 0 0  \r\n"
                                          "v 1 0 0.5 1.0\r\n"
                                          "v 1 1 0 # trailing comment\r\n"
                                          "v 0 1 0 0.2 0.3 0.4\r\n"
                                          "vn 0 0 1\r\n"
                                          "g group\r\n"
                                          "s off\r\n"
                                          "usemtl m\r\n"
                                          "f 1 2 3\r\n"
                                          "f 1//1 3//1 -1//1\r\n"
                                          "l 1 2\r\n"
                                          "unknown 1 2 3\r\n");
    const MeshFile file = read_obj(path);
    ASSERT_EQ(file.mesh.vertices.rows(), 4);
    ASSERT_EQ(file.mesh.vertices.cols(), 3);
    EXPECT_EQ(file.mesh.vertices(1, 2), 0.5);
    EXPECT_EQ(file.mesh.vertices(3, 1), 1.0);
    Eigen::MatrixXi expected(2, 3);
    expected << 0, 1, 2, 0, 2, 3;
    EXPECT_EQ(file.mesh.simplices, expected);
    EXPECT_FALSE(file.initial.has_value());
    EXPECT_EQ(file.texture_coordinates.size(), 0);
    EXPECT_EQ(file.face_texture_indices.size(), 0);
    EXPECT_TRUE(file.warnings.empty());
}

TEST(ObjIo, TwoCoordinatesPerVertexIsTwoDimensional) {
    TempFolder folder;
    const MeshFile flat = read_obj(folder.write("flat.obj", "v 0 0\nv 1 0\nv 0 1\nf 1 2 3\n"));
    EXPECT_EQ(flat.mesh.vertices.cols(), 2);
    EXPECT_EQ(flat.mesh.vertices(1, 0), 1.0);

    const MeshFile mixed = read_obj(folder.write("mixed.obj", "v 0 0\nv 1 0 2\nv 0 1 0\n"));
    EXPECT_EQ(mixed.mesh.vertices.cols(), 3);
    EXPECT_EQ(mixed.mesh.vertices(0, 2), 0.0);
    ASSERT_EQ(mixed.warnings.size(), 1u);
    EXPECT_NE(mixed.warnings[0].find("mixed.obj:1:"), std::string::npos);
}

TEST(ObjIo, TextureCoordinatesGivePerVertexInitialMap) {
    TempFolder folder;
    const std::string path =
        folder.write("uv.obj",
                     "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                     "vt 0.5 0.5\nvt 0.25 0.75 0\nvt 0 0\nvt 1 0\nvt 0.25 0.75\n"
                     "f 1/3 2/4 3/1\n"
                     "f 1/3/1 3/1/1 4/2/1\n"
                     "f 4/5 1/-3 3/-5\n");  // same values, other vt rows
    const MeshFile file = read_obj(path);
    ASSERT_EQ(file.texture_coordinates.rows(), 5);
    ASSERT_EQ(file.texture_coordinates.cols(), 2);
    EXPECT_EQ(file.texture_coordinates(1, 1), 0.75);
    Eigen::MatrixXi expected(3, 3);
    expected << 2, 3, 0, 2, 0, 1, 4, 2, 0;
    EXPECT_EQ(file.face_texture_indices, expected);
    ASSERT_TRUE(file.initial.has_value());
    Eigen::MatrixXd uv(4, 2);
    uv << 0, 0, 1, 0, 0.5, 0.5, 0.25, 0.75;
    EXPECT_EQ(*file.initial, uv);
    EXPECT_TRUE(file.warnings.empty());
}

TEST(ObjIo, VertexWithTwoTextureCoordinatesHasNoInitialMap) {
    TempFolder folder;
    const std::string path = folder.write("seam.obj",
                                          "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                          "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 2 2\n"
                                          "f 1/1 2/2 3/3\n"
                                          "f 1/1 3/5 4/4\n");
    const MeshFile file = read_obj(path);
    EXPECT_FALSE(file.initial.has_value());
    EXPECT_EQ(file.face_texture_indices.rows(), 2);
    ASSERT_EQ(file.warnings.size(), 1u);
    EXPECT_NE(file.warnings[0].find("vertex 3"), std::string::npos) << file.warnings[0];
    EXPECT_NE(file.warnings[0].find("line 10"), std::string::npos) << file.warnings[0];
    EXPECT_NE(file.warnings[0].find("line 11"), std::string::npos) << file.warnings[0];

    const MeshFile lonely =
        read_obj(folder.write("lonely.obj", "v 0 0\nv 1 0\nv 0 1\nv 5 5\nvt 0 0\nf 1/1 2/1 3/1\n"));
    EXPECT_FALSE(lonely.initial.has_value());
    ASSERT_EQ(lonely.warnings.size(), 1u);
    EXPECT_NE(lonely.warnings[0].find("vertex 4"), std::string::npos);
}

TEST(ObjIo, RoundTrip) {
    TempFolder folder;
    Eigen::MatrixXd positions(4, 3);
    positions << 0.1, 0.2, 0.3, 1.0 / 3.0, 0, 0, 1, 1e-300, 0, 0, 1, -2.5e10;
    Eigen::MatrixXi triangles(2, 3);
    triangles << 0, 1, 2, 0, 2, 3;
    const std::string path = folder.path("out.obj");
    write_obj(path, positions, triangles);
    const MeshFile plain = read_obj(path);
    EXPECT_EQ(plain.mesh.vertices, positions);  // 17 significant digits: exact
    EXPECT_EQ(plain.mesh.simplices, triangles);

    Eigen::MatrixXd uv(4, 2);
    uv << 0, 0, 0.1, 0.7, 1, 1, 2.0 / 3.0, 1;
    write_obj(path, positions, triangles, &uv);
    const MeshFile per_vertex = read_obj(path);
    ASSERT_TRUE(per_vertex.initial.has_value());
    EXPECT_EQ(*per_vertex.initial, uv);
    EXPECT_EQ(per_vertex.face_texture_indices, triangles);

    Eigen::MatrixXd seams(3, 2);
    seams << 0, 0, 1, 0, 1, 1;
    Eigen::MatrixXi corners(2, 3);
    corners << 0, 1, 2, 2, 1, 0;
    write_obj(path, positions, triangles, &seams, &corners);
    const MeshFile with_seams = read_obj(path);
    EXPECT_EQ(with_seams.texture_coordinates, seams);
    EXPECT_EQ(with_seams.face_texture_indices, corners);
    EXPECT_FALSE(with_seams.initial.has_value());

    // 2D positions are written with z = 0 (OBJ vertices have 3 coordinates).
    write_obj(path, positions.leftCols(2), triangles);
    const MeshFile flat = read_obj(path);
    ASSERT_EQ(flat.mesh.vertices.cols(), 3);
    EXPECT_EQ(flat.mesh.vertices.leftCols(2), positions.leftCols(2));
    EXPECT_TRUE((flat.mesh.vertices.col(2).array() == 0).all());
}

TEST(ObjIo, MalformedFilesNameTheFileAndLine) {
    TempFolder folder;
    auto read = [&](const std::string& name, const std::string& content) {
        const std::string path = folder.write(name, content);
        return [path] { read_obj(path); };
    };
    const std::string v3 = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    EXPECT_TRUE(
        throws_input_error(read("number.obj", "v 0 0 0\nv 1 x 0\n"), {"number.obj:2:", "'x'"}));
    EXPECT_TRUE(throws_input_error(read("nan.obj", "v 0 0 nan\n"), {"nan.obj:1:", "not finite"}));
    EXPECT_TRUE(throws_input_error(read("short.obj", "v 1\n"), {"short.obj:1:", "1 coordinates"}));
    EXPECT_TRUE(throws_input_error(read("quad.obj", v3 + "v 1 1 0\n\nf 1 2 3 4\n"),
                                   {"quad.obj:6:", "face with 4 vertices", "only triangles"}));
    EXPECT_TRUE(throws_input_error(read("segment.obj", v3 + "f 1 2\n"), {"face with 2 vertices"}));
    EXPECT_TRUE(throws_input_error(read("range.obj", v3 + "f 1 2 4\n"),
                                   {"range.obj:4:", "vertex 4 out of range [1, 3]"}));
    EXPECT_TRUE(throws_input_error(read("relative.obj", v3 + "f 1 2 -4\n"),
                                   {"relative.obj:4:", "vertex -4 out of range [-3, -1]"}));
    EXPECT_TRUE(throws_input_error(read("zero.obj", v3 + "f 0 1 2\n"), {"zero.obj:4:", "index 0"}));
    EXPECT_TRUE(
        throws_input_error(read("float.obj", v3 + "f 1 2.5 3\n"), {"float.obj:4:", "'2.5'"}));
    EXPECT_TRUE(throws_input_error(read("vt.obj", v3 + "vt 0 0\nf 1/1 2/2 3/1\n"),
                                   {"vt.obj:5:", "texture coordinate 2 out of range [1, 1]"}));
    EXPECT_TRUE(throws_input_error(read("corners.obj", v3 + "vt 0 0\nf 1/1 2 3/1\n"),
                                   {"corners.obj:5:", "mixes corners"}));
    EXPECT_TRUE(throws_input_error(read("faces.obj", v3 + "vt 0 0\nf 1/1 2/1 3/1\nf 1 2 3\n"),
                                   {"faces.obj:6:", "line 5", "all faces need them or none"}));
    EXPECT_TRUE(throws_input_error(read("badvt.obj", "vt 0\n"), {"badvt.obj:1:", "u v"}));
    EXPECT_TRUE(throws_input_error([&] { read_obj(folder.path("absent.obj")); },
                                   {"absent.obj: cannot open (No such file or directory)"}));
}

TEST(ObjIo, WriterChecksArgumentsAndWritesAtomically) {
    TempFolder folder;
    Eigen::MatrixXd positions(3, 3);
    positions << 0, 0, 0, 1, 0, 0, 0, 1, 0;
    Eigen::MatrixXi triangles(1, 3);
    triangles << 0, 1, 2;
    Eigen::MatrixXi bad = triangles;
    bad(0, 2) = 3;
    test::check_atomic_writes(
        folder, "mesh.obj", [&](const std::string& p) { write_obj(p, positions, triangles); },
        [&](const std::string& p) { write_obj(p, positions, bad); });
    const std::string path = folder.path("x.obj");
    EXPECT_TRUE(throws_invalid_argument([&] { write_obj(path, positions, bad); },
                                        "triangles row 0 refers to vertex 3"));
    Eigen::MatrixXi tets(1, 4);
    tets << 0, 1, 2, 0;
    EXPECT_TRUE(throws_invalid_argument([&] { write_obj(path, positions, tets); }, "4 columns"));
    Eigen::MatrixXd uv(2, 2);
    uv.setZero();
    EXPECT_TRUE(throws_invalid_argument([&] { write_obj(path, positions, triangles, &uv); },
                                        "texture_coordinates has 2 rows"));
    Eigen::MatrixXd nan = positions;
    nan(1, 1) = std::nan("");
    EXPECT_TRUE(throws_invalid_argument([&] { write_obj(path, nan, triangles); }, "not finite"));
    EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace sa
