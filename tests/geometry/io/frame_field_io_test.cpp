#include "geometry/io/frame_field_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "geometry/io/dmat_io.h"
#include "io_test_util.h"

namespace sa {
namespace {

using test::binary_dmat;
using test::TempFolder;
using test::throws_input_error;
using Flags = std::vector<unsigned char>;

// Writes `matrix` as an ASCII .dmat named `name` and returns its path.
std::string write_ascii(const TempFolder& folder, const std::string& name,
                        const Eigen::MatrixXd& matrix) {
    const std::string path = folder.path(name);
    write_dmat(path, matrix);
    return path;
}

Eigen::RowVector3d row(double x, double y, double z) {
    return Eigen::RowVector3d(x, y, z);
}

// Three faces: face 0 and 2 given, face 1 free.
const Eigen::RowVector3d kU0 = row(1, 0, 0), kV0 = row(0, 1, 0);
const Eigen::RowVector3d kU2 = row(0, 0, 2), kV2 = row(-3, 0, 0);

TEST(FrameFieldIo, DenseUV) {
    TempFolder folder;
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(3, 6);
    m.row(0) << kU0, kV0;
    m.row(2) << kU2, kV2;
    const FrameFieldFile field = read_frame_field(write_ascii(folder, "uv.dmat", m), 3);
    EXPECT_EQ(field.u, m.leftCols(3));
    EXPECT_EQ(field.v, m.rightCols(3));
    EXPECT_EQ(field.vectors, m);
    EXPECT_EQ(field.given, Flags({1, 0, 1}));
    EXPECT_EQ(field.constrained, Flags({0, 0, 0}));
    EXPECT_EQ(field.layout, "u, v per face");
}

TEST(FrameFieldIo, DenseOneDirection) {
    TempFolder folder;
    Eigen::MatrixXd m(3, 3);
    m << kU0, row(0, 0, 0), kU2;
    const FrameFieldFile field = read_frame_field(write_ascii(folder, "dir.dmat", m), 3);
    EXPECT_EQ(field.u, m);
    EXPECT_EQ(field.v.rows(), 0);
    EXPECT_EQ(field.v.cols(), 3);
    EXPECT_EQ(field.given, Flags({1, 0, 1}));
    EXPECT_EQ(field.constrained, Flags({0, 0, 0}));
}

TEST(FrameFieldIo, FlagThenTwoVectors) {
    // Like inspired_mesh.dmat: every face given, some flagged as constraints.
    TempFolder folder;
    Eigen::MatrixXd m(3, 7);
    m.row(0) << 1, kU0, kV0;
    m.row(1) << 0, kV0, kU0;
    m.row(2) << 0, kU2, kV2;
    const FrameFieldFile field = read_frame_field(write_ascii(folder, "flag.dmat", m), 3);
    EXPECT_EQ(field.u, m.middleCols(1, 3));
    EXPECT_EQ(field.v, m.rightCols(3));
    EXPECT_EQ(field.given, Flags({1, 1, 1}));
    EXPECT_EQ(field.constrained, Flags({1, 0, 0}));
    EXPECT_EQ(field.layout, "flag + 2 vectors per face");
}

TEST(FrameFieldIo, FlagThenOneThreeOrFourVectors) {
    // Like snail1/3/4.dmat: only the flagged faces carry vectors.
    TempFolder folder;
    for (int k : {1, 3, 4}) {
        SCOPED_TRACE(k);
        Eigen::MatrixXd m = Eigen::MatrixXd::Zero(4, 1 + 3 * k);
        for (int j = 0; j < k; ++j) m.block<1, 3>(2, 1 + 3 * j) = row(j + 1, 1, 0);
        m(2, 0) = 1;
        const FrameFieldFile field =
            read_frame_field(write_ascii(folder, std::to_string(k) + ".dmat", m), 4);
        EXPECT_EQ(field.vectors, m.rightCols(3 * k));
        EXPECT_EQ(field.u, m.middleCols(1, 3));
        EXPECT_EQ(field.v.rows(), 0) << "not a frame: one direction per face";
        EXPECT_EQ(field.given, Flags({0, 0, 1, 0}));
        EXPECT_EQ(field.constrained, Flags({0, 0, 1, 0}));
    }
    // u, v, -u, -v: a frame written as a symmetric 4-PolyVector.
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(2, 13);
    m.row(1) << 1, kU2, kV2, -kU2, -kV2;
    const FrameFieldFile field = read_frame_field(write_ascii(folder, "sym.dmat", m), 2);
    EXPECT_EQ(field.u.row(1), kU2);
    ASSERT_EQ(field.v.rows(), 2);
    EXPECT_EQ(field.v.row(1), kV2);
    EXPECT_EQ(field.v.row(0), row(0, 0, 0));
}

TEST(FrameFieldIo, FaceIndexList) {
    // Like bumpy-cube.dmat: face index, u, v for some faces, in any order.
    TempFolder folder;
    Eigen::MatrixXd m(2, 7);
    m.row(0) << 4, kU2, kV2;
    m.row(1) << 1, kU0, kV0;
    const FrameFieldFile field = read_frame_field(write_ascii(folder, "list.dmat", m), 5);
    EXPECT_EQ(field.u.rows(), 5);
    EXPECT_EQ(field.u.row(4), kU2);
    EXPECT_EQ(field.v.row(4), kV2);
    EXPECT_EQ(field.u.row(1), kU0);
    EXPECT_EQ(field.v.row(1), kV0);
    EXPECT_EQ(field.u.row(0), row(0, 0, 0));
    EXPECT_EQ(field.given, Flags({0, 1, 0, 0, 1}));
    EXPECT_EQ(field.constrained, Flags({0, 1, 0, 0, 1}));
    EXPECT_EQ(field.layout, "face-index list: face, u, v");

    // Every face listed: column 0 is a permutation, not flags.
    Eigen::MatrixXd all(3, 7);
    all.row(0) << 2, kU2, kV2;
    all.row(1) << 0, kU0, kV0;
    all.row(2) << 1, kV0, kU0;
    const FrameFieldFile full = read_frame_field(write_ascii(folder, "all.dmat", all), 3);
    EXPECT_EQ(full.u.row(2), kU2);
    EXPECT_EQ(full.u.row(0), kU0);
    EXPECT_EQ(full.constrained, Flags({1, 1, 1}));
}

TEST(FrameFieldIo, BinaryDmat) {
    TempFolder folder;
    Eigen::MatrixXd m(3, 7);
    m.row(0) << 1, kU0, kV0;
    m.row(1) << 0, 0, 0, 0, 0, 0, 0;
    m.row(2) << 0, row(1.0 / 3.0, -1e-300, 7), kV2;
    const FrameFieldFile field = read_frame_field(folder.write("bin.dmat", binary_dmat(m)), 3);
    EXPECT_EQ(field.vectors, m.rightCols(6));
    EXPECT_EQ(field.given, Flags({1, 0, 1}));
    EXPECT_EQ(field.constrained, Flags({1, 0, 0}));

    Eigen::MatrixXd list(1, 7);
    list << 2, kU2, kV2;
    const FrameFieldFile sparse =
        read_frame_field(folder.write("binlist.dmat", binary_dmat(list)), 6);
    EXPECT_EQ(sparse.given, Flags({0, 0, 1, 0, 0, 0}));
}

TEST(FrameFieldIo, Crossfield) {
    // lilium.crossfield: `k #F`, then per face the flag and k vectors.
    TempFolder folder;
    const std::string path = folder.write("f.crossfield",
                                          "2 3\r\n"
                                          "0 1 0 0 0 1 0 \r\n"
                                          "1 0 0 2 -3 0 0\r\n"
                                          "0 0 0 0 0 0 0\n");
    const FrameFieldFile field = read_frame_field(path, 3);
    EXPECT_EQ(field.u.row(0), kU0);
    EXPECT_EQ(field.v.row(0), kV0);
    EXPECT_EQ(field.u.row(1), kU2);
    EXPECT_EQ(field.v.row(1), kV2);
    EXPECT_EQ(field.given, Flags({1, 1, 0}));
    EXPECT_EQ(field.constrained, Flags({0, 1, 0}));
    EXPECT_EQ(field.layout, ".crossfield: flag + 2 vectors per face");

    const FrameFieldFile one =
        read_frame_field(folder.write("one.CROSSFIELD", "1 2\n0 1 2 3\n0 0 0 0\n"), 2);
    EXPECT_EQ(one.u.row(0), row(1, 2, 3));
    EXPECT_EQ(one.v.rows(), 0);
}

TEST(FrameFieldIo, ConstraintPair) {
    // libigl's _b.dmat (face indices) and _bc.dmat (u, v per listed face).
    TempFolder folder;
    Eigen::MatrixXd b(2, 1);
    b << 3, 0;
    Eigen::MatrixXd bc(2, 6);
    bc << kU2, kV2, kU0, kV0;
    const FrameFieldFile field = read_frame_field_constraints(
        write_ascii(folder, "m_b.dmat", b), write_ascii(folder, "m_bc.dmat", bc), 4);
    EXPECT_EQ(field.u.row(3), kU2);
    EXPECT_EQ(field.v.row(0), kV0);
    EXPECT_EQ(field.given, Flags({1, 0, 0, 1}));
    EXPECT_EQ(field.constrained, Flags({1, 0, 0, 1}));

    const FrameFieldFile one = read_frame_field_constraints(
        folder.path("m_b.dmat"), write_ascii(folder, "dir_bc.dmat", bc.leftCols(3)), 4);
    EXPECT_EQ(one.v.rows(), 0);
    EXPECT_EQ(one.u.row(0), kU0);
    EXPECT_EQ(one.u.row(3), kU2);

    EXPECT_TRUE(throws_input_error(
        [&] {
            read_frame_field_constraints(folder.path("m_b.dmat"),
                                         write_ascii(folder, "short_bc.dmat", bc.topRows(1)), 4);
        },
        {"short_bc.dmat: 1 rows x 6 columns", "expected 2 rows", "m_b.dmat"}));
    EXPECT_TRUE(throws_input_error(
        [&] { read_frame_field_constraints(folder.path("m_b.dmat"), folder.path("m_bc.dmat"), 3); },
        {"m_b.dmat: row 0: face index 3 is out of range (the mesh has 3 faces)"}));
}

TEST(FrameFieldIo, ShapeErrors) {
    TempFolder folder;
    const Eigen::MatrixXd six = Eigen::MatrixXd::Ones(3, 6);
    EXPECT_TRUE(throws_input_error(
        [&] { read_frame_field(write_ascii(folder, "rows.dmat", six), 4); },
        {"rows.dmat: 3 rows x 6 columns; expected 4 rows (one per face of the mesh) with 3, 6 or "
         "1+3k columns (k = 1 to 4), or a face-index list of at most 4 rows with 7 columns"}));
    EXPECT_TRUE(throws_input_error(
        [&] { read_frame_field(write_ascii(folder, "cols.dmat", Eigen::MatrixXd::Ones(3, 5)), 3); },
        {"cols.dmat: 3 rows x 5 columns", "expected 3 rows"}));
    EXPECT_TRUE(throws_input_error(
        [&] { read_frame_field(write_ascii(folder, "k5.dmat", Eigen::MatrixXd::Ones(3, 16)), 3); },
        {"k5.dmat: 3 rows x 16 columns"}));
    EXPECT_TRUE(throws_input_error(  // a list longer than the mesh
        [&] { read_frame_field(write_ascii(folder, "long.dmat", Eigen::MatrixXd::Ones(5, 7)), 4); },
        {"long.dmat: 5 rows x 7 columns"}));
    EXPECT_TRUE(throws_input_error([&] { read_frame_field(folder.write("e.dmat", "0 0\n"), 4); },
                                   {"e.dmat: 0 rows x 0 columns"}));
    EXPECT_TRUE(throws_input_error([&] { read_frame_field(folder.path("absent.dmat"), 4); },
                                   {"absent.dmat: cannot open"}));
    EXPECT_TRUE(test::throws_invalid_argument(
        [&] { read_frame_field(folder.path("absent.dmat"), -1); }, "num_faces is -1"));
}

TEST(FrameFieldIo, ValueErrors) {
    TempFolder folder;
    auto read = [&](const std::string& name, const Eigen::MatrixXd& m, Index faces) {
        const std::string path = write_ascii(folder, name, m);
        return [path, faces] { read_frame_field(path, faces); };
    };
    // (With 3 faces, flags 1, 0, 2 would be a face-index list: each of 0, 1, 2 once.)
    Eigen::MatrixXd flags = Eigen::MatrixXd::Zero(4, 7);
    flags.row(0) << 1, kU0, kV0;
    flags(2, 0) = 2;
    EXPECT_TRUE(throws_input_error(read("flag.dmat", flags, 4),
                                   {"flag.dmat: row 2: flag (column 0) is 2; expected 0 or 1"}));
    flags(2, 0) = 1;
    EXPECT_TRUE(throws_input_error(
        read("free.dmat", flags, 4),
        {"free.dmat: row 2: flagged as constrained but its vectors are all zero"}));

    Eigen::MatrixXd uv = Eigen::MatrixXd::Zero(2, 6);
    uv.row(0) << kU0, kV0;
    uv.row(1) << kU2, 0, 0, 0;
    EXPECT_TRUE(
        throws_input_error(read("zero_v.dmat", uv, 2),
                           {"zero_v.dmat: row 1: the second of 2 vectors is zero while the face's "
                            "other vectors are not"}));
    uv.row(1) << 0, 0, 0, kV2;
    EXPECT_TRUE(throws_input_error(read("zero_u.dmat", uv, 2),
                                   {"zero_u.dmat: row 1: the first of 2 vectors is zero"}));
    EXPECT_TRUE(throws_input_error(read("none.dmat", Eigen::MatrixXd::Zero(2, 6), 2),
                                   {"none.dmat: no face has a nonzero vector"}));

    // Face-index lists.
    Eigen::MatrixXd list(3, 7);
    list.row(0) << 1, kU0, kV0;
    list.row(1) << 3, kU2, kV2;
    list.row(2) << 0, kU2, kV2;
    list(1, 0) = 2.5;
    EXPECT_TRUE(throws_input_error(read("frac.dmat", list, 5),
                                   {"frac.dmat: row 1: face index 2.5 is not an integer"}));
    list(1, 0) = 5;
    EXPECT_TRUE(throws_input_error(
        read("range.dmat", list, 5),
        {"range.dmat: row 1: face index 5 is out of range (the mesh has 5 faces)"}));
    list(1, 0) = -1;
    EXPECT_TRUE(throws_input_error(read("negative.dmat", list, 5),
                                   {"negative.dmat: row 1: face index -1 is out of range"}));
    list(1, 0) = 1;
    EXPECT_TRUE(throws_input_error(read("twice.dmat", list, 5),
                                   {"twice.dmat: row 1: face 1 is listed again (first in row 0)"}));
    list(1, 0) = 4;
    list.block<1, 6>(2, 1).setZero();
    EXPECT_TRUE(throws_input_error(read("zero.dmat", list, 5),
                                   {"zero.dmat: row 2: the vectors of face 0 are all zero"}));
}

TEST(FrameFieldIo, NotFiniteAndTruncated) {
    TempFolder folder;
    EXPECT_TRUE(throws_input_error(
        [&] { read_frame_field(folder.write("nan.dmat", "3 2\n1\n0\n0\n0\nnan\n1\n"), 2); },
        {"nan.dmat:6:", "not finite"}));
    Eigen::MatrixXd m(2, 3);
    m << 1, 0, 0, 0, 1, 0;
    m(1, 2) = std::nan("");
    EXPECT_TRUE(throws_input_error(
        [&] { read_frame_field(folder.write("nan_bin.dmat", binary_dmat(m)), 2); },
        {"nan_bin.dmat: value (1, 2) is not finite"}));
    m(1, 2) = 0;
    const std::string bytes = binary_dmat(m);
    EXPECT_TRUE(throws_input_error(
        [&] { read_frame_field(folder.write("short.dmat", bytes.substr(0, bytes.size() - 3)), 2); },
        {"short.dmat: binary data ends after 5 of 6 values (2 x 3)"}));
    EXPECT_TRUE(throws_input_error(
        [&] { read_frame_field(folder.write("nan.crossfield", "1 2\n0 1 0 0\n1 0 nan 1\n"), 2); },
        {"nan.crossfield:3:", "not finite"}));
}

TEST(FrameFieldIo, CrossfieldErrors) {
    TempFolder folder;
    auto read = [&](const std::string& name, const std::string& content) {
        const std::string path = folder.write(name, content);
        return [path] { read_frame_field(path, 2); };
    };
    EXPECT_TRUE(throws_input_error(
        read("faces.crossfield", "2 3\n"),
        {"faces.crossfield:1: header gives 3 faces; expected 2 (one per face of the mesh)"}));
    EXPECT_TRUE(throws_input_error(read("header.crossfield", "2\n"),
                                   {"header.crossfield:1: expected the header 'k #F'"}));
    EXPECT_TRUE(throws_input_error(read("k.crossfield", "5 2\n"),
                                   {"k.crossfield:1: vector count 5; expected 1 to 4"}));
    EXPECT_TRUE(throws_input_error(
        read("count.crossfield", "1 2\n0 1 0 0\n0 1 0\n"),
        {"count.crossfield:3: expected 4 numbers (a flag, then 1 vectors), found 3"}));
    EXPECT_TRUE(throws_input_error(read("ends.crossfield", "1 2\n0 1 0 0\n"),
                                   {"ends.crossfield: file ends after 1 of 2 faces"}));
    EXPECT_TRUE(throws_input_error(read("more.crossfield", "1 2\n0 1 0 0\n0 1 0 0\n7\n"),
                                   {"more.crossfield:4: unexpected data after the 2 faces"}));
    EXPECT_TRUE(
        throws_input_error(read("flag.crossfield", "1 2\n0 1 0 0\n1 0 0 0\n"),
                           {"flag.crossfield:3: flagged as constrained but its vectors are all "
                            "zero"}));
}

}  // namespace
}  // namespace sa
