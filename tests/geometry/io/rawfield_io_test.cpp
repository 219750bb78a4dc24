#include "geometry/io/rawfield_io.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "geometry/io/frame_field_io.h"
#include "io_test_util.h"

namespace sa {
namespace {

using test::TempFolder;
using test::throws_input_error;
using Flags = std::vector<unsigned char>;

// Directional's layout: `N #F`, then per face N vectors of 3 coordinates.
TEST(RawfieldIo, ReadsACrossFieldAsUAndV) {
    TempFolder folder;
    const std::string path = folder.write("f.rawfield",
                                          "4 3\n"
                                          "1 0 0  0 1 0  -1 0 0  0 -1 0\n"
                                          "0 0 0  0 0 0  0 0 0  0 0 0\n"
                                          "0 0 2  -3 0 0  0 0 -2  3 0 0\r\n");
    for (const FrameFieldFile& field :
         {read_rawfield(path, 3), read_frame_field(path, 3)}) {  // also by extension
        EXPECT_EQ(field.u.row(0), Eigen::RowVector3d(1, 0, 0));
        EXPECT_EQ(field.v.row(0), Eigen::RowVector3d(0, 1, 0));
        EXPECT_EQ(field.u.row(2), Eigen::RowVector3d(0, 0, 2));
        EXPECT_EQ(field.v.row(2), Eigen::RowVector3d(-3, 0, 0));
        EXPECT_EQ(field.given, Flags({1, 0, 1}));
        EXPECT_EQ(field.constrained, Flags({0, 0, 0}));
        EXPECT_EQ(field.vectors.cols(), 12);
        EXPECT_NE(field.layout.find("rawfield"), std::string::npos);
    }
}

TEST(RawfieldIo, RejectsOtherFieldsAndMalformedFiles) {
    TempFolder folder;
    auto read = [&](const std::string& name, const std::string& text, Index faces = 2) {
        return [&folder, name, text, faces] { read_rawfield(folder.write(name, text), faces); };
    };
    const std::string face = "1 0 0 0 1 0 -1 0 0 0 -1 0\n";
    EXPECT_TRUE(throws_input_error(read("n2.rawfield", "2 2\n1 0 0 -1 0 0\n1 0 0 -1 0 0\n"),
                                   {"n2.rawfield:1: N = 2", "N = 4"}));
    EXPECT_TRUE(throws_input_error(read("n6.rawfield", "6 2\n"), {"n6.rawfield:1: N = 6"}));
    EXPECT_TRUE(throws_input_error(read("empty.rawfield", ""), {"empty.rawfield: empty file"}));
    EXPECT_TRUE(throws_input_error(read("header.rawfield", "4\n" + face),
                                   {"header.rawfield:1: expected the header 'N #F'"}));
    EXPECT_TRUE(throws_input_error(read("faces.rawfield", "4 3\n" + face + face),
                                   {"faces.rawfield:1: header gives 3 faces; expected 2"}));
    EXPECT_TRUE(throws_input_error(read("short.rawfield", "4 2\n" + face + "1 0 0 0 1 0\n"),
                                   {"short.rawfield:3: face 1: expected 12 numbers", "found 6"}));
    EXPECT_TRUE(throws_input_error(read("ends.rawfield", "4 2\n" + face),
                                   {"ends.rawfield: file ends after 1 of 2 faces"}));
    EXPECT_TRUE(throws_input_error(read("more.rawfield", "4 2\n" + face + face + "0\n"),
                                   {"more.rawfield:4: unexpected data after the 2 faces"}));
    EXPECT_TRUE(
        throws_input_error(read("nan.rawfield", "4 2\n" + face + "nan 0 0 0 1 0 -1 0 0 0 -1 0\n"),
                           {"nan.rawfield:3:"}));
    EXPECT_TRUE(
        throws_input_error(read("zero.rawfield", "4 2\n" + face + "1 0 0 0 0 0 -1 0 0 0 0 0\n"),
                           {"zero.rawfield:3: face 1: 2 of its 4 vectors are zero"}));
    EXPECT_TRUE(throws_input_error(
        read("asym.rawfield", "4 2\n" + face + "1 0 0 0 1 0 -1 0 0 0 1 0\n"),
        {"asym.rawfield:3: face 1: the third and fourth vectors are not -u and -v"}));
    EXPECT_TRUE(throws_input_error(read("none.rawfield", "4 1\n0 0 0 0 0 0 0 0 0 0 0 0\n", 1),
                                   {"none.rawfield: no face has a nonzero vector"}));
    EXPECT_THROW(read_rawfield(folder.write("ok.rawfield", "4 1\n" + face), -1),
                 InvalidArgumentError);
}

}  // namespace
}  // namespace sa
