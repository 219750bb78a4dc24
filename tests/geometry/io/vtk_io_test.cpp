#include "geometry/io/vtk_io.h"

#include <gtest/gtest.h>

#include <fstream>

#include <cstdint>
#include <cstring>
#include <functional>
#include <utility>
#include <vector>

#include "io_test_util.h"

namespace sa {
namespace {

using test::TempFolder;
using test::throws_input_error;
using test::throws_invalid_argument;

const char* kTets =
    "# vtk DataFile Version 3.0\r\n"
    "two tets\r\n"
    "ASCII\r\n"
    "DATASET UNSTRUCTURED_GRID\r\n"
    "POINTS 5 double\r\n"
    "0 0 0 1 0 0 0 1 0\r\n"
    "0 0 1 1 1 1\r\n"
    "CELLS 2 10\r\n"
    "4 0 1 2 3\r\n"
    "4 1 2 3 4\r\n"
    "CELL_TYPES 2\r\n"
    "10\r\n"
    "10\r\n";

std::string legacy_grid(const std::string& cells, int n, int size, const std::string& types) {
    return "# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\n"
           "POINTS 5 float\n0 0 0 1 0 0 0 1 0 0 0 1 1 1 1\nCELLS " +
           std::to_string(n) + " " + std::to_string(size) + "\n" + cells + "CELL_TYPES " +
           std::to_string(n) + "\n" + types;
}

TEST(VtkIo, ReadsLegacyUnstructuredGrid) {
    TempFolder folder;
    const MeshFile file = read_vtk(folder.write("tets.vtk", kTets));
    ASSERT_EQ(file.mesh.vertices.rows(), 5);
    ASSERT_EQ(file.mesh.vertices.cols(), 3);
    EXPECT_EQ(file.mesh.vertices(4, 1), 1.0);
    Eigen::MatrixXi expected(2, 4);
    expected << 0, 1, 2, 3, 1, 2, 3, 4;
    EXPECT_EQ(file.mesh.simplices, expected);
}

// What Gmsh writes: the geometry's points (1), curves (3) and boundary triangles (5) beside the
// tetrahedra. The tetrahedra are read; the rest is skipped with a warning.
TEST(VtkIo, SkipsLowerDimensionalCellsBesideTheTetrahedra) {
    TempFolder folder;
    const MeshFile file =
        read_vtk(folder.write("gmsh.vtk", legacy_grid("1 4\n2 0 1\n3 0 1 2\n4 0 1 2 3\n4 1 2 3 4\n",
                                                      5, 19, "1\n3\n5\n10\n10\n")));
    Eigen::MatrixXi expected(2, 4);
    expected << 0, 1, 2, 3, 1, 2, 3, 4;
    EXPECT_EQ(file.mesh.simplices, expected);
    ASSERT_EQ(file.warnings.size(), 1u);
    EXPECT_NE(file.warnings[0].find("gmsh.vtk: skipped 3 lower-dimensional cells (vertices, "
                                    "lines, triangles); read the 2 tetrahedra"),
              std::string::npos)
        << file.warnings[0];
}

TEST(VtkIo, ReadsFlatPolyDataAsTwoDimensional) {
    TempFolder folder;
    const MeshFile file = read_vtk(
        folder.write("flat.vtk",
                     "# vtk DataFile Version 3.0\nflat\nASCII\nDATASET POLYDATA\nPOINTS 4 double\n"
                     "0 0 0\n1 0 0\n1 1 0\n0 1 0\nPOLYGONS 2 8\n3 0 1 2\n3 0 2 3\n"));
    ASSERT_EQ(file.mesh.vertices.cols(), 2);
    EXPECT_EQ(file.mesh.vertices(2, 1), 1.0);
    Eigen::MatrixXi expected(2, 3);
    expected << 0, 1, 2, 0, 2, 3;
    EXPECT_EQ(file.mesh.simplices, expected);
}

TEST(VtkIo, RoundTripsBothFormats) {
    TempFolder folder;
    Eigen::MatrixXd positions(5, 3);
    positions << 0, 0, 0, 1.0 / 3.0, 0, 0, 0, 1, 0, 0, 0, 1, 1e-17, 1, -1e300;
    Eigen::MatrixXi tets(2, 4);
    tets << 0, 1, 2, 3, 1, 2, 3, 4;
    Eigen::MatrixXi triangles(2, 3);
    triangles << 0, 1, 2, 2, 1, 3;
    for (const char* extension : {".vtk", ".vtu"}) {
        SCOPED_TRACE(extension);
        const std::string path = folder.path(std::string("out") + extension);
        const bool legacy = std::string(extension) == ".vtk";
        auto write = legacy ? write_vtk : write_vtu;
        auto read = legacy ? read_vtk : read_vtu;
        write(path, positions, tets, {}, {});
        MeshFile file = read(path);
        EXPECT_EQ(file.mesh.vertices, positions);
        EXPECT_EQ(file.mesh.simplices, tets);

        write(path, positions.leftCols(2), triangles, {}, {});  // padded with z = 0
        file = read(path);
        EXPECT_EQ(file.mesh.vertices, positions.leftCols(2));
        EXPECT_EQ(file.mesh.simplices, triangles);

        write(path, positions, triangles, {}, {});  // a surface in space stays 3D
        EXPECT_EQ(read(path).mesh.vertices, positions);
    }
}

TEST(VtkIo, WritesPointAndCellData) {
    TempFolder folder;
    Eigen::MatrixXd positions(3, 2);
    positions << 0, 0, 1, 0, 0, 1;
    Eigen::MatrixXi triangles(1, 3);
    triangles << 0, 1, 2;
    const std::vector<DataArray> point_data{
        {"displacement", Eigen::MatrixXd::Constant(3, 2, 0.25), false},
        {"handle", Eigen::MatrixXd::Ones(3, 1), true},
        {"with space", Eigen::MatrixXd::Zero(3, 1), false}};
    const std::vector<DataArray> cell_data{{"distortion", Eigen::MatrixXd::Constant(1, 1, 1.5)}};

    write_vtk(folder.path("a.vtk"), positions, triangles, point_data, cell_data);
    const std::string legacy = test::read_all(folder.path("a.vtk"));
    EXPECT_NE(legacy.find("ASCII"), std::string::npos);
    EXPECT_NE(legacy.find("CELLS 1 4"), std::string::npos) << legacy;  // version 4.2 layout
    EXPECT_NE(legacy.find("POINTS 3 double"), std::string::npos);
    EXPECT_NE(legacy.find("displacement 2 3 double"), std::string::npos) << legacy;
    EXPECT_NE(legacy.find("handle 1 3 int"), std::string::npos) << legacy;
    EXPECT_NE(legacy.find("CELL_DATA 1"), std::string::npos);
    EXPECT_NE(legacy.find("distortion 1 1 double"), std::string::npos) << legacy;
    EXPECT_NE(legacy.find("with%20space 1 3 double"), std::string::npos) << legacy;
    EXPECT_EQ(read_vtk(folder.path("a.vtk")).mesh.simplices, triangles);  // VTK reads it

    write_vtu(folder.path("a.vtu"), positions, triangles, point_data, cell_data);
    const std::string xml = test::read_all(folder.path("a.vtu"));
    EXPECT_NE(xml.find("format=\"appended\""), std::string::npos);
    EXPECT_NE(xml.find("Name=\"displacement\" NumberOfComponents=\"2\""), std::string::npos)
        << xml.substr(0, 2000);
    EXPECT_NE(xml.find("type=\"Int32\" Name=\"handle\""), std::string::npos);
    EXPECT_NE(xml.find("type=\"Float64\" Name=\"distortion\""), std::string::npos);
    EXPECT_EQ(read_vtu(folder.path("a.vtu")).mesh.simplices, triangles);
}

TEST(VtkIo, MalformedFilesAreErrorsAndNothingIsPrinted) {
    TempFolder folder;
    auto read = [&](const std::string& name, const std::string& content) {
        const std::string path = folder.write(name, content);
        return [path, name] {
            if (name.ends_with(".vtu"))
                read_vtu(path);
            else
                read_vtk(path);
        };
    };
    testing::internal::CaptureStderr();
    testing::internal::CaptureStdout();
    EXPECT_TRUE(throws_input_error(
        read("mixed.vtk", legacy_grid("3 0 1 2\n4 0 1 2 3\n4 0 1 2 3\n", 3, 14, "5\n10\n9\n")),
        {"mixed.vtk: cell 2 has type 9 (vtkQuad)"}));
    EXPECT_TRUE(throws_input_error(read("quad.vtk", legacy_grid("4 0 1 2 3\n", 1, 5, "9\n")),
                                   {"quad.vtk: cell 0 has type 9 (vtkQuad)", "only triangles"}));
    EXPECT_TRUE(throws_input_error(read("garbage.vtk", "not a vtk file\n"),
                                   {"garbage.vtk:1: expected '# vtk DataFile Version x.y', found "
                                    "'not a vtk file'"}));
    EXPECT_TRUE(throws_input_error(read("header.vtk", "# vtk DataFile Version 3.0\nnothing\n"),
                                   {"header.vtk:3: the file ends where ASCII or BINARY belongs"}));
    EXPECT_TRUE(throws_input_error(read("gzip.vtk", std::string("\x1f\x8b\x08\0\0\0", 6)),
                                   {"gzip.vtk: not a text file (byte 0x1f at offset 0)"}));
    EXPECT_TRUE(throws_input_error(read("gzip.vtu", std::string("\x1f\x8b\x08\0\0\0", 6)),
                                   {"gzip.vtu: not a text file (byte 0x1f at offset 0)"}));
    EXPECT_TRUE(throws_input_error(
        read("image.vtk",
             "# vtk DataFile Version 3.0\nimage\nASCII\nDATASET STRUCTURED_POINTS\n"
             "DIMENSIONS 2 2 1\nSPACING 1 1 1\nORIGIN 0 0 0\n"),
        {"image.vtk:4: dataset type 'STRUCTURED_POINTS'; only UNSTRUCTURED_GRID and POLYDATA"}));
    EXPECT_TRUE(throws_input_error(read("garbage.vtu", "<VTKFile type=\"Unstruc"),
                                   {"garbage.vtu: cannot read as VTU (VTK: "}));
    EXPECT_TRUE(throws_input_error(read("other.vtu", "<?xml version=\"1.0\"?>\n<html></html>\n"),
                                   {"other.vtu: cannot read as VTU"}));
    const std::string printed =
        testing::internal::GetCapturedStdout() + testing::internal::GetCapturedStderr();
    EXPECT_EQ(printed, "");
    EXPECT_TRUE(throws_input_error([&] { read_vtk(folder.path("absent.vtk")); },
                                   {"absent.vtk: cannot open (No such file or directory)"}));
    EXPECT_TRUE(throws_input_error([&] { read_vtu(folder.path("absent.vtu")); },
                                   {"absent.vtu: cannot open (No such file or directory)"}));
}

// Every section of a legacy file is checked, with its line, before anything is allocated from
// its counts (VTK 9.1's own reader crashed on most of these: tests/fuzz/regressions/vtk).
TEST(VtkIo, MalformedLegacySectionsAreNamedWithTheirLine) {
    TempFolder folder;
    const auto poly = [](const std::string& version, const std::string& cells) {
        return "# vtk DataFile Version " + version +
               "\npoly\nASCII\nDATASET POLYDATA\nPOINTS 4 float\n0 0 0 1 0 0 1 1 0 0 1 0\n" + cells;
    };
    const auto read = [&](const std::string& name, const std::string& content) {
        const std::string path = folder.write(name, content);
        return [path] { read_vtk(path); };
    };
    const std::vector<std::pair<std::string, std::string>> cases = {
        {poly("3.0", "POLYGONS 1 4\n3( 0 1 2\n"),
         "8: POLYGONS holds '3(' where a whole number belongs"},
        {poly("3.0", "polygonsX 1 4\n3 0 1\n"),
         "7: unknown section 'polygonsX' in a DATASET POLYDATA"},
        {poly("3.0", "CELLS 1 4\n3 0 1 2\n"), "7: unknown section 'CELLS' in a DATASET POLYDATA"},
        {"# vtk DataFile Version 3.0\nt\nASCIIZ\n", "3: expected ASCII or BINARY, found 'ASCIIZ'"},
        {"# vtk DataFile Version 3.0\nt\nASCII\nDATASET FOO\n", "4: unknown dataset type 'FOO'"},
        {"# vtk DataFile Version 3.0\nt\nASCII\nPOINTS 1 float\n",
         "4: expected DATASET, found 'POINTS'"},
        {poly("3.0", "POLYGONS 1 99999999999999999999999\n3 0 1 2\n"),
         "7: POLYGONS: expected its size (a whole number from 0 to 2147483647), found "
         "'99999999999999999999999'"},
        {poly("3.0", "POLYGONS -1 4\n3 0 1 2\n"), "7: POLYGONS: expected its cell count"},
        {poly("5.1", "POLYGONS 2 3\nOFFSETS vtktypeint64\n0 3\nCONNECTIVITY vtktypeint64\n0 1\n"),
         "11: POLYGONS CONNECTIVITY is cut short: the file ends after 2 of 3 numbers"},
        {poly("5.1", "POLYGONS 2 3\nOFFSETS float\n0 3\n"),
         "8: POLYGONS OFFSETS: value type float where integers belong"},
        {poly("5.1", "POLYGONS 2 3\nOFFSETS int\n0 3\nCONNECTIVITY\n"),
         "10: the file ends where POLYGONS CONNECTIVITY's value type belongs"},
        {poly("5.1", "POLYGONS 2 3\nOFFSETS int\n0 3\n0 1 2\n"),
         "10: POLYGONS: expected CONNECTIVITY after the offsets, found '0'"},
        {poly("5.1",
              "POLYGONS 3 6\nOFFSETS vtktypeint64\n0 4 3\nCONNECTIVITY vtktypeint64\n"
              "0 1 2 0 2 3\n"),
         "9: POLYGONS OFFSETS: offset 2 is 3; they must rise from 0 to 6"},
        {poly("5.1", "POLYGONS 2 3\nOFFSETS int\n1 3\n"),
         "9: POLYGONS OFFSETS: offset 0 is 1; they must rise from 0 to 3"},
        // Cells whose point counts disagree with the section's COUNT and SIZE.
        {poly("3.0", "POLYGONS 110 1\n1\n"),
         "8: POLYGONS: 1 numbers do not hold 110 cells of 'COUNT POINTS...' (cell 0)"},
        {poly("3.0", "POLYGONS 1 8\n3 0 1 2\n3 0 2 3\n"),
         "9: POLYGONS: 8 numbers hold more than 1 cells"},
        {poly("3.0", "POLYGONS 2 8\n3 0 1 2\n3 0 2 3\nPOLYGONS 1 4\n3 0 1 2\n"),
         "10: a second POLYGONS section"},
        // A count larger than the rest of the file is refused before anything is allocated.
        {poly("3.0", "POLYGONS 1 2000000000\n3 0 1 2\n"), "7: POLYGONS is cut short (2000000000"},
        {"# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 2000000 double\n"
         "0 0 0\n",
         "5: POINTS is cut short (6000000 numbers declared"},
        {"# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 1 double\n"
         "0 0 x\n",
         "6: POINTS holds 'x' where a number belongs"},
        {"# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 1 string\n",
         "5: POINTS: value type 'string' is not read"},
        {"# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 1 double\n"
         "0 0\x01 0\n",
         "6: not a text file (byte 0x01 at offset"},
        // A FIELD section before the points.
        {poly("3.0", "FIELD FieldData 2\nu92 double0 4 3\n"),
         "8: FIELD array 'u92': expected its component count"},
        {poly("3.0", "FIELD FieldData 2\nTimeValue 1 1 double\n0.5\nCycle 1 2 int\n7\n"),
         "11: FIELD array 'Cycle' is cut short: the file ends after 1 of 2 numbers"},
        {poly("3.0", "FIELD FieldData 1\nName 1 1 string\nx\n"),
         "8: FIELD array 'Name': value type 'string' is not read"},
        {poly("3.0", "FIELD FieldData 1\nCycle 1 1 float\n1.5e\n"),
         "9: FIELD array 'Cycle' holds '1.5e' where a number belongs"},
    };
    testing::internal::CaptureStderr();
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const std::string name = "case" + std::to_string(i) + ".vtk";
        SCOPED_TRACE(name);
        EXPECT_TRUE(throws_input_error(read(name, cases[i].first), {name + ":" + cases[i].second}));
    }
    // Whole-file checks, after the sections.
    const std::string grid = "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n";
    EXPECT_TRUE(
        throws_input_error(read("nopoints.vtk", grid), {"nopoints.vtk: no POINTS section"}));
    EXPECT_TRUE(throws_input_error(
        read("notypes.vtk", grid + "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nCELLS 1 4\n3 0 1 2\n"),
        {"notypes.vtk: a CELLS section without CELL_TYPES"}));
    EXPECT_TRUE(throws_input_error(
        read("types.vtk", grid + "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nCELLS 1 4\n3 0 1 2\n"
                                 "CELL_TYPES 2\n5 5\n"),
        {"types.vtk: CELLS declares 1 cells but CELL_TYPES 2"}));
    EXPECT_TRUE(throws_input_error(
        read("range.vtk", grid + "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nCELLS 1 4\n3 0 1 3\n"
                                 "CELL_TYPES 1\n5\n"),
        {"range.vtk: cell 0 refers to point 3, out of range [0, 2]"}));
    EXPECT_TRUE(throws_input_error(read("lines.vtk", poly("3.0", "LINES 1 3\n2 0 1\n")),
                                   {"lines.vtk: no triangles or tetrahedra; cell 0 has type 3 "
                                    "(vtkLine)"}));
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
    // Keywords in any case, both cell layouts (the version 5 one told by its OFFSETS keyword),
    // CELL_TYPES before CELLS, FIELD and METADATA sections, and the data after POINT_DATA are read.
    for (const auto& [name, content] :
         {std::pair<std::string, std::string>{"lower.vtk",
                                              poly("3.0", "polygons 2 8\n3 0 1 2\n3 0 2 3\n")},
          {"v5.vtk", poly("5.1",
                          "POLYGONS 3 6\nOFFSETS vtktypeint64\n0 3 6\nCONNECTIVITY "
                          "vtktypeint64\n0 1 2 0 2 3\n")},
          {"v3offsets.vtk", poly("3.0",
                                 "POLYGONS 3 6\nOFFSETS int\n0 3 6\nCONNECTIVITY int\n"
                                 "0 1 2 0 2 3\n")},
          {"fieldok.vtk", poly("3.0",
                               "FIELD FieldData 3\nTimeValue 1 1 double\n0.5\nCycle 2 1 int\n"
                               "7 -8\nMETADATA\nINFORMATION 0\n\nNULL_ARRAY\nPOLYGONS 2 8\n"
                               "3 0 1 2\n3 0 2 3\nPOINT_DATA 4\nSCALARS s float\nwhatever\n")},
          {"typesfirst.vtk", grid + "POINTS 4 float\n0 0 0 1 0 0 1 1 0 0 1 0\nMETADATA\n"
                                    "INFORMATION 1\nNAME L2_NORM_RANGE LOCATION vtkDataArray\n"
                                    "DATA 2 0 1.4\n\nCELL_TYPES 2\n5 5\nCELLS 2 8\n3 0 1 2\n"
                                    "3 0 2 3\nCELL_DATA 2\n"}}) {
        SCOPED_TRACE(name);
        const MeshFile file = read_vtk(folder.write(name, content));
        Eigen::MatrixXi expected(2, 3);
        expected << 0, 1, 2, 0, 2, 3;
        EXPECT_EQ(file.mesh.simplices, expected);
        EXPECT_EQ(file.mesh.vertices.cols(), 2);
    }
}

/// A function that reads `content` written to `name` in `folder` as a legacy file.
std::function<void()> read_vtk_in(TempFolder& folder, const std::string& name,
                                  const std::string& content) {
    const std::string path = folder.write(name, content);
    return [path] { read_vtk(path); };
}

/// Big-endian bytes of `values` as `T`, as legacy BINARY files hold them.
template <class T>
std::string big_endian(std::initializer_list<T> values) {
    std::string bytes;
    for (const T value : values) {
        char raw[sizeof(T)];
        std::memcpy(raw, &value, sizeof(T));
        for (std::size_t b = sizeof(T); b-- > 0;) bytes.push_back(raw[b]);
    }
    return bytes;
}

TEST(VtkIo, ReadsBinaryLegacyFilesInBothCellLayouts) {
    TempFolder folder;
    const std::string head =
        "# vtk DataFile Version 5.1\nbinary\nBINARY\nDATASET UNSTRUCTURED_GRID\n"
        "FIELD FieldData 1\nTIME 1 1 double\n" +
        big_endian<double>({2.5}) + "\nPOINTS 5 float\n" +
        big_endian<float>({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1}) +
        "\nMETADATA\nINFORMATION 0\n\n";
    const std::string types = "CELL_TYPES 2\n" + big_endian<std::int32_t>({10, 10}) + "\n";
    const std::string v5 = head + "CELLS 3 8\nOFFSETS vtktypeint64\n" +
                           big_endian<std::int64_t>({0, 4, 8}) + "\nCONNECTIVITY vtktypeint64\n" +
                           big_endian<std::int64_t>({0, 1, 2, 3, 1, 2, 3, 4}) + "\n" + types;
    const std::string classic = head + "CELLS 2 10\n" +
                                big_endian<std::int32_t>({4, 0, 1, 2, 3, 4, 1, 2, 3, 4}) + "\n" +
                                types + "POINT_DATA 5\nSCALARS s double\nLOOKUP_TABLE default\n" +
                                big_endian<double>({1, 2, 3, 4, 5});
    Eigen::MatrixXi expected(2, 4);
    expected << 0, 1, 2, 3, 1, 2, 3, 4;
    for (const auto& [name, content] :
         {std::pair<std::string, std::string>{"v5.vtk", v5}, {"classic.vtk", classic}}) {
        SCOPED_TRACE(name);
        const MeshFile file = read_vtk(folder.write(name, content));
        EXPECT_EQ(file.mesh.simplices, expected);
        ASSERT_EQ(file.mesh.vertices.rows(), 5);
        EXPECT_EQ(file.mesh.vertices.row(4), Eigen::RowVector3d(1, 1, 1));
    }
    // Data cut short, or a count beyond the file, is named with its byte offset.
    const std::string cut = head + "CELLS 2 10\n" + big_endian<std::int32_t>({4, 0, 1});
    EXPECT_TRUE(
        throws_input_error(read_vtk_in(folder, "cut.vtk", cut),
                           {"cut.vtk: byte ", ": CELLS is cut short (10 numbers declared"}));
    const std::string wrong = head + "CELLS 2 10\n" +
                              big_endian<std::int32_t>({4, 0, 1, 2, 3, 9, 1, 2, 3, 4}) + "\n" +
                              types;
    EXPECT_TRUE(throws_input_error(read_vtk_in(folder, "wrong.vtk", wrong),
                                   {": CELLS: 10 numbers do not hold 2 cells"}));
    const std::string garbage = head + "\x01\x02" + types;
    EXPECT_TRUE(throws_input_error(read_vtk_in(folder, "garbage.vtk", garbage),
                                   {"unknown section '\\x01\\x02CELL_TYPES'"}));
}

// Hexahedra are written as VTK_HEXAHEDRON (12) cells with their cell data; the reader, which
// reads simplices, names the cell type it does not read.
TEST(VtkIo, HexahedraAreWrittenAsVtkHexahedron) {
    TempFolder folder;
    Eigen::MatrixXd positions(8, 3);
    positions << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1;
    Eigen::MatrixXi hexes(1, 8);
    hexes << 0, 1, 2, 3, 4, 5, 6, 7;
    const std::string path = folder.path("hex.vtk");
    write_vtk(path, positions, hexes, {}, {{"quality", Eigen::MatrixXd::Ones(1, 1)}});
    std::ifstream in(path);
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    EXPECT_NE(text.find("CELLS 1 9\n8 0 1 2 3 4 5 6 7\nCELL_TYPES 1\n12\n"), std::string::npos)
        << text;
    EXPECT_TRUE(throws_input_error([&] { read_vtk(path); }, {"cell 0 has type 12"}));
    write_vtu(folder.path("hex.vtu"), positions, hexes);
    EXPECT_TRUE(throws_invalid_argument(
        [&] { write_vtu(folder.path("x.vtu"), positions.leftCols(2), hexes); },
        "hexahedra need 3D positions"));
}

TEST(VtkIo, WritersCheckArgumentsAndWriteAtomically) {
    TempFolder folder;
    Eigen::MatrixXd positions(4, 3);
    positions << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
    Eigen::MatrixXi tets(1, 4);
    tets << 0, 1, 2, 3;
    Eigen::MatrixXi bad = tets;
    bad(0, 3) = 7;
    test::check_atomic_writes(
        folder, "a.vtk", [&](const std::string& p) { write_vtk(p, positions, tets); },
        [&](const std::string& p) { write_vtk(p, positions, bad); });
    test::check_atomic_writes(
        folder, "a.vtu", [&](const std::string& p) { write_vtu(p, positions, tets); },
        [&](const std::string& p) { write_vtu(p, positions, bad); });
    const std::string path = folder.path("x.vtu");
    EXPECT_TRUE(throws_invalid_argument([&] { write_vtu(path, positions.leftCols(2), tets); },
                                        "tetrahedra need 3D positions"));
    EXPECT_TRUE(throws_invalid_argument(
        [&] {
            write_vtu(path, positions, tets, {{"p", Eigen::MatrixXd::Ones(3, 1)}});
        },
        "point data array 'p' is 3 x 1; expected 4 rows"));
    EXPECT_TRUE(throws_invalid_argument(
        [&] {
            write_vtu(path, positions, tets, {},
                      {{"c", Eigen::MatrixXd::Constant(1, 1, 0.5), true}});
        },
        "cell data array 'c' row 0 column 0 is 0.5, not an int"));
    EXPECT_TRUE(throws_invalid_argument(
        [&] {
            write_vtu(path, positions, tets,
                      {{"p", Eigen::MatrixXd::Ones(4, 1)}, {"p", Eigen::MatrixXd::Ones(4, 1)}});
        },
        "given twice"));
    EXPECT_TRUE(throws_invalid_argument(
        [&] {
            write_vtu(path, positions, tets, {{"", Eigen::MatrixXd::Ones(4, 1)}});
        },
        "empty name"));
    EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace sa
