#include "geometry/io/polycube_labels_io.h"

#include <gtest/gtest.h>

#include "io_test_util.h"

namespace sa {
namespace {

using test::TempFolder;
using test::throws_input_error;

TEST(PolycubeLabelsIo, ReadsFlagsInAnyLayout) {
    TempFolder folder;
    EXPECT_EQ(read_facet_flags(folder.write("a.flags", "-1\r\n0\r\n5 3\n\n-1 -1 2 4\n"), 2),
              (std::vector<int>{-1, 0, 5, 3, -1, -1, 2, 4}));
    EXPECT_EQ(read_triangle_labels(folder.write("l.txt", "0\n3\n4\n"), 3),
              (std::vector<int>{0, 3, 4}));
}

TEST(PolycubeLabelsIo, WrongCountsAndLabelsAreRejected) {
    TempFolder folder;
    EXPECT_TRUE(throws_input_error(
        [&] { read_facet_flags(folder.write("s.flags", "0 1 2\n"), 1); },
        {"s.flags: 3 labels, expected 4", "4 per tetrahedron for 1 tetrahedra"}));
    EXPECT_TRUE(throws_input_error(
        [&] { read_facet_flags(folder.write("r.flags", "0 1 2 3\n-1 7 -1 -1\n"), 2); },
        {"r.flags:2:", "label 7 of tetrahedron 1 facet 1 is outside [-1, 5]"}));
    EXPECT_TRUE(throws_input_error(
        [&] { read_facet_flags(folder.write("x.flags", "0 1 two 3\n"), 1); }, {"x.flags:1:"}));
    EXPECT_TRUE(
        throws_input_error([&] { read_triangle_labels(folder.write("n.txt", "0\n-1\n"), 2); },
                           {"n.txt:2:", "label -1 of triangle 1 is outside [0, 5]"}));
    EXPECT_TRUE(throws_input_error([&] { read_triangle_labels(folder.write("m.txt", "0\n"), 2); },
                                   {"m.txt: 1 labels, expected 2"}));
}

TEST(PolycubeLabelsIo, RoundTrip) {
    TempFolder folder;
    const std::vector<int> flags{-1, 0, 1, 2, 3, 4, 5, -1};
    write_facet_flags(folder.path("o.flags"), flags);
    EXPECT_EQ(read_facet_flags(folder.path("o.flags"), 2), flags);
    EXPECT_THROW(write_facet_flags(folder.path("bad.flags"), {0, 6}), InvalidArgumentError);
    EXPECT_EQ(folder.entries(), 1u);
}

}  // namespace
}  // namespace sa
