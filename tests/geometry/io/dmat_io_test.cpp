#include "geometry/io/dmat_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include "io_test_util.h"

namespace sa {
namespace {

using test::binary_dmat;
using test::TempFolder;
using test::throws_input_error;
using test::throws_invalid_argument;

TEST(DmatIo, ReadsColumnByColumn) {
    TempFolder folder;
    const Eigen::MatrixXd matrix =
        read_dmat(folder.write("m.dmat", "2 3\r\n1\r\n2\r\n3 4\r\n5\r\n6\r\n"));
    Eigen::MatrixXd expected(3, 2);
    expected << 1, 4, 2, 5, 3, 6;
    EXPECT_EQ(matrix, expected);
    EXPECT_EQ(read_dmat(folder.write("empty.dmat", "0 0\n")).size(), 0);
    EXPECT_EQ(read_dmat(folder.write("rows.dmat", "0 4\n")).rows(), 4);
}

TEST(DmatIo, ReadsBinary) {
    TempFolder folder;
    Eigen::MatrixXd matrix(3, 2);
    matrix << 1.0 / 3.0, -1e-300, 7, 1e300, 0, -2.5;
    matrix(2, 0) = 3.25;  // 0x400a000000000000: its bytes hold '\n' and '\0'
    EXPECT_EQ(read_dmat(folder.write("m.dmat", binary_dmat(matrix))), matrix);
    // The exact bytes of 2.0 and 1.5 (little-endian), and a CRLF header.
    const std::string bytes("0 0\r\n1 2\r\n\0\0\0\0\0\0\0\x40\0\0\0\0\0\0\xf8\x3f", 26);
    EXPECT_EQ(read_dmat(folder.write("crlf.dmat", bytes)), Eigen::Vector2d(2.0, 1.5));
    // A 0 x 0 and a 4 x 0 binary matrix.
    EXPECT_EQ(read_dmat(folder.write("empty.dmat", "0 0\n0 0\n")).size(), 0);
    EXPECT_EQ(read_dmat(folder.write("rows.dmat", "0 0\n0 4\n")).rows(), 4);
}

TEST(DmatIo, MalformedBinaryFiles) {
    TempFolder folder;
    auto read = [&](const std::string& name, const std::string& content) {
        const std::string path = folder.write(name, content);
        return [path] { read_dmat(path); };
    };
    const Eigen::MatrixXd matrix = Eigen::MatrixXd::Ones(2, 3);
    const std::string bytes = binary_dmat(matrix);
    EXPECT_TRUE(throws_input_error(read("short.dmat", bytes.substr(0, bytes.size() - 1)),
                                   {"short.dmat: binary data ends after 5 of 6 values (2 x 3)"}));
    EXPECT_TRUE(throws_input_error(read("long.dmat", bytes + "\n"),
                                   {"long.dmat: 1 bytes after the 6 values of a 2 x 3 binary"}));
    EXPECT_TRUE(throws_input_error(read("header.dmat", "0 0\nx 2\n\x01\x02"),
                                   {"header.dmat:2: expected the binary .dmat header 'cols rows', "
                                    "found 'x 2'"}));
    EXPECT_TRUE(
        throws_input_error(read("three.dmat", "0 0\n1 2 3\n"), {"three.dmat:2:", "'1 2 3'"}));
    EXPECT_TRUE(
        throws_input_error(read("negative.dmat", "0 0\n-1 2\n"), {"negative.dmat:2:", "'-1 2'"}));
    EXPECT_TRUE(
        throws_input_error(read("noline.dmat", "0 0\n1 2"),
                           {"noline.dmat:2: binary .dmat (header '0 0') without a second"}));
    Eigen::MatrixXd infinite = matrix;
    infinite(1, 2) = std::numeric_limits<double>::infinity();
    EXPECT_TRUE(throws_input_error(read("inf.dmat", binary_dmat(infinite)),
                                   {"inf.dmat: value (1, 2) is not finite (inf)"}));
}

TEST(DmatIo, RoundTrip) {
    TempFolder folder;
    Eigen::MatrixXd matrix(2, 3);
    matrix << 1.0 / 3.0, -1e-300, 7, 1e300, 0, -2.5;
    const std::string path = folder.path("out.dmat");
    write_dmat(path, matrix);
    EXPECT_EQ(read_dmat(path), matrix);
    EXPECT_EQ(test::read_all(path).substr(0, 4), "3 2\n");
}

TEST(DmatIo, MalformedFiles) {
    TempFolder folder;
    auto read = [&](const std::string& name, const std::string& content) {
        const std::string path = folder.write(name, content);
        return [path] { read_dmat(path); };
    };
    EXPECT_TRUE(throws_input_error(read("binary.dmat", std::string("0 0\n2 1\n\0\0\x01\xff", 12)),
                                   {"binary.dmat:", "ends after 0 of 2 values"}));
    EXPECT_TRUE(
        throws_input_error(read("header.dmat", "2\n1\n2\n"), {"header.dmat:1:", "'cols rows'"}));
    EXPECT_TRUE(throws_input_error(read("number.dmat", "1 2\n1\nx\n"), {"number.dmat:3:", "'x'"}));
    EXPECT_TRUE(
        throws_input_error(read("few.dmat", "2 2\n1\n2\n3\n"), {"few.dmat:", "3 of 4 values"}));
    EXPECT_TRUE(throws_input_error(read("many.dmat", "1 2\n1\n2\n3\n"), {"many.dmat:4:", "'3'"}));
    EXPECT_TRUE(
        throws_input_error(read("negative.dmat", "-1 2\n"), {"negative.dmat:1:", "negative"}));
    EXPECT_TRUE(throws_input_error([&] { read_dmat(folder.path("absent.dmat")); },
                                   {"absent.dmat: cannot open (No such file or directory)"}));
}

TEST(DmatIo, WriterWritesAtomically) {
    TempFolder folder;
    Eigen::MatrixXd matrix = Eigen::MatrixXd::Ones(2, 2);
    Eigen::MatrixXd bad = matrix;
    bad(0, 1) = std::nan("");
    test::check_atomic_writes(
        folder, "m.dmat", [&](const std::string& p) { write_dmat(p, matrix); },
        [&](const std::string& p) { write_dmat(p, bad); });
    EXPECT_TRUE(throws_invalid_argument([&] { write_dmat(folder.path("x.dmat"), bad); },
                                        "entry (0, 1) is not finite"));
}

}  // namespace
}  // namespace sa
