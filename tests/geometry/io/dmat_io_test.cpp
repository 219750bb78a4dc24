#include "geometry/io/dmat_io.h"

#include <gtest/gtest.h>

#include "io_test_util.h"

namespace sa {
namespace {

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
                                   {"binary.dmat:", "only ASCII"}));
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
