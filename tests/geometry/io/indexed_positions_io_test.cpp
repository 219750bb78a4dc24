#include "geometry/io/indexed_positions_io.h"

#include <gtest/gtest.h>

#include "io_test_util.h"

namespace sa {
namespace {

using test::TempFolder;
using test::throws_input_error;

TEST(IndexedPositionsIo, ReadsIndexedRows) {
    TempFolder folder;
    const PositionRows r = read_position_rows(
        folder.write("t.txt", "# handle targets\r\n12 0.5 1 -2\r\n\r\n3 1e-3 2 3 # note\r\n"), 3,
        20);
    ASSERT_TRUE(r.indexed());
    EXPECT_EQ(r.indices, (std::vector<Index>{12, 3}));
    Eigen::MatrixXd expected(2, 3);
    expected << 0.5, 1, -2, 1e-3, 2, 3;
    EXPECT_EQ(r.positions, expected);
    EXPECT_EQ(r.lines, (std::vector<int>{2, 4}));
    // 2D: `index x y`.
    const PositionRows p = read_position_rows(folder.write("p.txt", "2\n0 1 2\n5 3 4\n"), 2);
    EXPECT_EQ(p.indices, (std::vector<Index>{0, 5}));
    EXPECT_EQ(p.positions.rows(), 2);
    EXPECT_EQ(p.positions(1, 1), 4.0);
}

TEST(IndexedPositionsIo, ReadsPlainRows) {
    TempFolder folder;
    const PositionRows r = read_position_rows(folder.write("plain.txt", "1 2 3\n4 5 6\n"), 3);
    EXPECT_FALSE(r.indexed());
    EXPECT_EQ(r.positions.rows(), 2);
    EXPECT_EQ(r.positions(1, 0), 4.0);
    const PositionRows q = read_position_rows(folder.write("plain2.txt", "3\n1 2\n3 4\n5 6\n"), 2);
    EXPECT_FALSE(q.indexed());
    EXPECT_EQ(q.positions.rows(), 3);
}

TEST(IndexedPositionsIo, RepeatAtTheSamePositionIsKeptOnce) {
    TempFolder folder;
    const PositionRows r =
        read_position_rows(folder.write("rep.txt", "3\n4 1 2 3\n7 0 0 0\n4 1 2 3\n"), 3);
    EXPECT_EQ(r.indices, (std::vector<Index>{4, 7}));
    EXPECT_EQ(r.positions.rows(), 2);
}

TEST(IndexedPositionsIo, BadRowsNameTheFileAndLine) {
    TempFolder folder;
    auto read = [&](const std::string& name, const std::string& content, int d = 3, Index n = 10) {
        const std::string path = folder.write(name, content);
        return [path, d, n] { read_position_rows(path, d, n); };
    };
    EXPECT_TRUE(throws_input_error(
        read("twice.txt", "4 1 2 3\n5 0 0 0\n4 1 2 3.5\n"),
        {"twice.txt:3:", "vertex 4 listed twice with two targets", "first on line 1"}));
    EXPECT_TRUE(throws_input_error(read("range.txt", "1 0 0 0\n10 0 0 0\n"),
                                   {"range.txt:2:", "vertex index 10 outside [0, 10)"}));
    EXPECT_TRUE(throws_input_error(read("neg.txt", "-1 0 0 0\n"), {"neg.txt:1:", "negative"}));
    EXPECT_TRUE(throws_input_error(read("frac.txt", "1.5 0 0 0\n"), {"frac.txt:1:", "'1.5'"}));
    EXPECT_TRUE(throws_input_error(read("word.txt", "1 0 zero 0\n"), {"word.txt:1:", "'zero'"}));
    EXPECT_TRUE(throws_input_error(read("mixed.txt", "1 0 0 0\n0 0 0\n"),
                                   {"mixed.txt:2:", "3 numbers, the rows before have 4"}));
    EXPECT_TRUE(throws_input_error(read("wide.txt", "1 0 0 0 0\n"),
                                   {"wide.txt:1:", "5 numbers", "`index x y z`", "`x y z`"}));
    EXPECT_TRUE(throws_input_error(read("count.txt", "3\n1 0 0 0\n2 0 0 0\n"),
                                   {"count.txt:1:", "count line says 3 but 2 rows follow"}));
    EXPECT_TRUE(throws_input_error(read("empty.txt", "# nothing\n"), {"empty.txt:", "no rows"}));
    EXPECT_TRUE(throws_input_error(read("nan.txt", "1 0 nan 0\n"), {"nan.txt:1:"}));
    // In 2D, 3 numbers are `index x y`: a z column does not pass as an index.
    EXPECT_TRUE(throws_input_error(read("xyz.txt", "0.5 0.5 0\n", 2), {"xyz.txt:1:", "'0.5'"}));
    EXPECT_TRUE(throws_input_error([&] { read_position_rows(folder.path("absent.txt"), 3); },
                                   {"absent.txt", "cannot open"}));
}

}  // namespace
}  // namespace sa
