#include "geometry/io/index_list_io.h"

#include <gtest/gtest.h>

#include "io_test_util.h"

namespace sa {
namespace {

using test::TempFolder;
using test::throws_input_error;
using test::throws_invalid_argument;

TEST(IndexListIo, ReadsIndicesInAnyLayout) {
    TempFolder folder;
    EXPECT_EQ(read_index_list(folder.write("a.txt", "1\r\n2\r\n5 # comment\r\n\r\n 7 9 \r\n")).indices,
              (std::vector<Index>{1, 2, 5, 7, 9}));
    EXPECT_EQ(read_index_list(folder.write("b.txt", "80 131 145\n42 122\n")).indices,
              (std::vector<Index>{80, 131, 145, 42, 122}));
    EXPECT_TRUE(read_index_list(folder.write("empty.txt", "# nothing\n")).indices.empty());
    EXPECT_EQ(read_index_list(folder.write("single.txt", "5\n")).indices, (std::vector<Index>{5}));
}

TEST(IndexListIo, CountHeaderIsCheckedAndDropped) {
    TempFolder folder;
    // A count alone on the first line with a comment.
    EXPECT_EQ(read_index_list(folder.write("lock.txt", "3 #Vertices Locked\n0\n1\n14\n")).indices,
              (std::vector<Index>{0, 1, 14}));
    // A first number equal to the count of the numbers after it, marked as a count by its
    // repetition or the layout.
    EXPECT_EQ(read_index_list(folder.write("again.txt", "2\n7\n2\n")).indices,
              (std::vector<Index>{7, 2}));
    EXPECT_EQ(read_index_list(folder.write("apart.txt", "2\n7 9\n")).indices,
              (std::vector<Index>{7, 9}));
    EXPECT_TRUE(throws_input_error(
        [&] { read_index_list(folder.write("wrong.txt", "4 # locked\n0\n1\n")); },
        {"wrong.txt:1:", "count header says 4 but 2 indices follow"}));
}

// One per line, the first equal to the count of the numbers after it, nothing marking it: it
// could be either, and it is read as an index (vertex 17 is a handle), which the list says.
TEST(IndexListIo, AnUnmarkedFirstNumberIsAnIndexAndSaidSo) {
    TempFolder folder;
    std::string column = "17\n";
    for (int i = 1; i <= 17; ++i) column += std::to_string(i == 17 ? 18 : i) + "\n";
    const IndexList list = read_index_list(folder.write("column.txt", column));
    ASSERT_EQ(list.indices.size(), 18u);
    EXPECT_EQ(list.indices.front(), 17);
    EXPECT_TRUE(list.first_may_be_count);
    EXPECT_EQ(list.lines.front(), 1);
    EXPECT_NE(first_number_reading("column.txt", list).find("column.txt:1: 17 read as an index"),
              std::string::npos);
    const IndexList single = read_index_list(folder.write("zero.txt", "0\n"));
    EXPECT_EQ(single.indices, (std::vector<Index>{0}));
    EXPECT_FALSE(single.first_may_be_count);  // nothing after it to count
    const IndexList marked = read_index_list(folder.write("marked.txt", "2 # count\n7\n9\n"));
    EXPECT_EQ(marked.indices, (std::vector<Index>{7, 9}));
    EXPECT_FALSE(marked.first_may_be_count);
    EXPECT_EQ(first_number_reading("marked.txt", marked), "");
}

TEST(IndexListIo, ACountLineIsOneOnlyWhenItMatches) {
    TempFolder folder;
    // Several numbers on the first line: all indices, whatever the first one is.
    EXPECT_EQ(read_index_list(folder.write("row.txt", "3 10 20 30\n")).indices,
              (std::vector<Index>{3, 10, 20, 30}));
    // One per line, the first disagreeing with the count after it: an index like the others.
    EXPECT_EQ(read_index_list(folder.write("column.txt", "3\n10\n20\n30\n40\n")).indices,
              (std::vector<Index>{3, 10, 20, 30, 40}));
    // Set apart by the layout but disagreeing: ambiguous.
    EXPECT_TRUE(
        throws_input_error([&] { read_index_list(folder.write("apart.txt", "3\n10 20\n30 40\n")); },
                           {"apart.txt:1:", "one number, 3, apart from the 4 indices after it"}));
    EXPECT_EQ(read_index_list(folder.write("apart-ok.txt", "4\n10 20\n30 40\n")).indices,
              (std::vector<Index>{10, 20, 30, 40}));
}

TEST(IndexListIo, RoundTripWhateverTheFirstIndex) {
    TempFolder folder;
    const std::string path = folder.path("h.txt");
    for (const std::vector<Index>& indices :
         {std::vector<Index>{2, 7, 9}, std::vector<Index>{0}, std::vector<Index>{}, std::vector<Index>{2, 5, 7},
          std::vector<Index>{1, 0}, std::vector<Index>{12, 3, 40000}}) {
        write_index_list(path, indices);
        const IndexList list = read_index_list(path);
        EXPECT_EQ(list.indices, indices);
        EXPECT_FALSE(list.first_may_be_count);
    }
}

TEST(IndexListIo, MalformedFilesNameTheFileAndLine) {
    TempFolder folder;
    auto read = [&](const std::string& name, const std::string& content) {
        const std::string path = folder.write(name, content);
        return [path] { read_index_list(path); };
    };
    EXPECT_TRUE(throws_input_error(read("dup.txt", "4\n8\n9 4\n"),
                                   {"dup.txt:3:", "index 4 repeated (first on line 1)"}));
    EXPECT_TRUE(throws_input_error(read("neg.txt", "1\n-2\n"), {"neg.txt:2:", "index -2"}));
    EXPECT_TRUE(throws_input_error(read("float.txt", "1\n2.5\n"), {"float.txt:2:", "'2.5'"}));
    EXPECT_TRUE(throws_input_error(read("word.txt", "1 two\n"), {"word.txt:1:", "'two'"}));
    EXPECT_TRUE(
        throws_input_error(read("huge.txt", "99999999999\n"), {"huge.txt:1:", "too large"}));
    EXPECT_TRUE(throws_input_error([&] { read_index_list(folder.path("absent.txt")); },
                                   {"absent.txt: cannot open (No such file or directory)"}));
}

TEST(IndexListIo, WriterChecksArgumentsAndWritesAtomically) {
    TempFolder folder;
    test::check_atomic_writes(
        folder, "h.txt",
        [&](const std::string& p) {
            write_index_list(p, {3, 1});
        },
        [&](const std::string& p) {
            write_index_list(p, {3, 3});
        });
    EXPECT_TRUE(throws_invalid_argument(
        [&] {
            write_index_list(folder.path("x"), {1, -1});
        },
        "index -1 at position 1 is negative"));
    EXPECT_TRUE(throws_invalid_argument(
        [&] {
            write_index_list(folder.path("x"), {1, 2, 1});
        },
        "index 1 repeated at positions 0 and 2"));
}

}  // namespace
}  // namespace sa
