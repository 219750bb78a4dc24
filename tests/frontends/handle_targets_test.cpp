#include "frontends/deform/handle_targets.h"

#include <gtest/gtest.h>

#include "geometry/io/mesh_file.h"
#include "geometry/mesh/mesh_generators.h"
#include "tests/geometry/io/io_test_util.h"

namespace sa {
namespace {

using test::TempFolder;
using test::throws_input_error;

// A 3 x 1 x 1 bar of tetrahedra (16 vertices) and its vertices moved by (1, 2, 3).
struct Fixture {
    SimplicialMesh mesh = grid_tetrahedra(3, 1, 1);
    Eigen::MatrixXd moved = mesh.vertices.rowwise() + Eigen::RowVector3d(1, 2, 3);
    std::vector<Index> handles = {0, 3, 12, 15};
};

std::string rows(const Eigen::MatrixXd& positions, const std::vector<Index>& which,
                 bool with_index) {
    std::string text;
    for (Index v : which) {
        if (with_index) text += std::to_string(v) + " ";
        for (Eigen::Index c = 0; c < positions.cols(); ++c) {
            char number[32];
            std::snprintf(number, sizeof number, "%.17g ", positions(v, c));
            text += number;
        }
        text += "\n";
    }
    return text;
}

void expect_targets(const HandleTargets& h, const Fixture& f, const std::vector<Index>& order) {
    EXPECT_EQ(h.handles, order);
    ASSERT_EQ(h.targets.rows(), static_cast<Eigen::Index>(order.size()));
    for (std::size_t k = 0; k < order.size(); ++k)
        EXPECT_EQ(h.targets.row(k), f.moved.row(order[k])) << k;
}

TEST(HandleTargets, HandleListWithEveryTargetsLayout) {
    TempFolder folder;
    const Fixture f;
    const std::string handles = folder.write("h.txt", "# handles\n0\n3\n12 15\n");
    // A mesh file, one vertex per rest vertex.
    const std::string node = folder.path("moved.node");
    write_mesh_file(node, f.moved, f.mesh.simplices);
    expect_targets(read_handle_targets(handles, node, 16, 3), f, f.handles);
    // Plain rows, one per vertex and one per handle.
    std::vector<Index> all(16);
    for (Index v = 0; v < 16; ++v) all[v] = v;
    expect_targets(
        read_handle_targets(handles, folder.write("all.txt", rows(f.moved, all, false)), 16, 3), f,
        f.handles);
    expect_targets(read_handle_targets(
                       handles, folder.write("per.txt", rows(f.moved, f.handles, false)), 16, 3),
                   f, f.handles);
    // Rows `index x y z` in another order.
    expect_targets(
        read_handle_targets(handles, folder.write("idx.txt", rows(f.moved, {15, 0, 12, 3}, true)),
                            16, 3),
        f, f.handles);
}

TEST(HandleTargets, IndexedRowsAloneNameTheHandles) {
    TempFolder folder;
    const Fixture f;
    const std::string path =
        folder.write("targets.txt", "4\n" + rows(f.moved, {12, 0, 3, 15}, true));
    expect_targets(read_handle_targets("", path, 16, 3), f, {12, 0, 3, 15});
}

TEST(HandleTargets, PlanarMapsReadTwoCoordinates) {
    TempFolder folder;
    const SimplicialMesh grid = grid_triangles(2, 2);  // 9 vertices
    const Eigen::MatrixXd moved = 2.0 * grid.vertices;
    const std::string obj = folder.path("moved.obj");
    write_mesh_file(obj, moved, grid.simplices);  // written with z = 0
    const HandleTargets h = read_handle_targets(folder.write("h.txt", "0 8\n"), obj, 9, 2);
    ASSERT_EQ(h.targets.cols(), 2);
    EXPECT_EQ(h.targets.row(1), moved.row(8));
    const HandleTargets g = read_handle_targets("", folder.write("t.txt", "8 2 2\n0 0 0\n"), 9, 2);
    EXPECT_EQ(g.handles, (std::vector<Index>{8, 0}));
    EXPECT_EQ(g.targets(0, 1), 2.0);
}

// In 2D, rows of three numbers are `index x y` or `x y 0`: the reading that fits the handles is
// taken and named; a file that fits both is refused, naming both.
TEST(HandleTargets, PlanarRowsOfThreeNumbersTakeTheReadingThatFits) {
    TempFolder folder;
    const std::string handles = folder.write("h.txt", "2\n6\n8\n");
    // Integer coordinates with z = 0, one row per handle: as `index x y` the indices 3, 1, 0 are
    // no handles, so they are `x y 0`.
    const HandleTargets plain =
        read_handle_targets(handles, folder.write("xyz.txt", "3 0 0\n1 2 0\n0 2 0\n"), 9, 2);
    EXPECT_EQ(plain.handles, (std::vector<Index>{2, 6, 8}));
    ASSERT_EQ(plain.targets.cols(), 2);
    EXPECT_EQ(plain.targets.row(0), Eigen::RowVector2d(3, 0));
    EXPECT_EQ(plain.targets.row(2), Eigen::RowVector2d(0, 2));
    EXPECT_NE(plain.reading.find("rows `x y 0` of"), std::string::npos) << plain.reading;
    EXPECT_NE(plain.reading.find("one per handle"), std::string::npos) << plain.reading;
    // Non-integer first numbers: only `x y 0` fits.
    EXPECT_EQ(read_handle_targets(handles, folder.write("f.txt", "0.5 0 0\n1 2 0\n0 2 0\n"), 9, 2)
                  .targets(0, 0),
              0.5);
    // The handles as indices, with a y that is not 0: `index x y`.
    const HandleTargets indexed =
        read_handle_targets(handles, folder.write("ixy.txt", "8 1 1\n2 0 0.5\n6 2 0\n"), 9, 2);
    EXPECT_EQ(indexed.targets.row(0), Eigen::RowVector2d(0, 0.5));
    EXPECT_EQ(indexed.targets.row(2), Eigen::RowVector2d(1, 1));
    EXPECT_NE(indexed.reading.find("rows `index x y` of"), std::string::npos) << indexed.reading;
    // Both fit (the first numbers are the handles, the last are 0): refused.
    EXPECT_TRUE(throws_input_error(
        [&] {
            read_handle_targets(handles, folder.write("both.txt", "2 1 0\n6 2 0\n8 3 0\n"), 9, 2);
        },
        {"both.txt: rows of three numbers fit both `index x y`", "and `x y 0` (one per handle)",
         "write rows `x y`"}));
    // Neither fits: the `index x y` reading's reason when the first numbers are integers, the
    // `x y 0` reading's otherwise.
    EXPECT_TRUE(throws_input_error(
        [&] { read_handle_targets(handles, folder.write("no.txt", "2 1 1\n5 2 1\n"), 9, 2); },
        {"no.txt:2: vertex 5 is not a handle of"}));
    EXPECT_TRUE(throws_input_error(
        [&] { read_handle_targets(handles, folder.write("far.txt", "2 1 1\n99 2 2\n"), 9, 2); },
        {"far.txt:2: vertex index 99 outside [0, 9)"}));
    EXPECT_TRUE(throws_input_error(
        [&] {
            read_handle_targets(handles, folder.write("z.txt", "0.5 1 0\n1 2 0.25\n3 1 0\n"), 9, 2);
        },
        {"z.txt:2: z = 0.25"}));
    // A handle list whose first number could be a count is read as a handle, and said so.
    const HandleTargets counted = read_handle_targets(
        folder.write("c.txt", "2\n0\n1\n"), folder.write("c3.txt", "0.5 0\n1 1\n0 1\n"), 9, 2);
    EXPECT_EQ(counted.handles, (std::vector<Index>{2, 0, 1}));
    EXPECT_NE(counted.reading.find("c.txt:1: 2 read as an index"), std::string::npos)
        << counted.reading;
}

// A target so far from the rest shape that its pose overflows is named with its file and line.
TEST(HandleTargets, ATargetBeyondDoubleArithmeticIsNamed) {
    TempFolder folder;
    const SimplicialMesh grid = grid_triangles(2, 2);  // the unit square, 9 vertices
    HandleTargets far = read_handle_targets("", folder.write("t.txt", "0 0 0\n8 1 1e200\n"), 9, 2);
    EXPECT_EQ(far.origins,
              (std::vector<std::string>{folder.path("t.txt") + ":1", folder.path("t.txt") + ":2"}));
    EXPECT_TRUE(throws_input_error([&] { check_target_reach(grid.vertices, far); },
                                   {"t.txt:2: the target of handle vertex 8 lies 1e+200"}));
    far.targets(1, 1) = 1e90;  // far, but representable
    check_target_reach(grid.vertices, far);
    // Relative to the rest shape's size: the same square at 1e-200 cannot reach 1.
    HandleTargets near = far;
    near.targets(1, 1) = 1.0;
    check_target_reach(grid.vertices, near);
    EXPECT_TRUE(throws_input_error([&] { check_target_reach(1e-200 * grid.vertices, near); },
                                   {"handle vertex 8", "times its diagonal"}));
}

TEST(HandleTargets, BadHandlesGiveOneLineNamingFileAndLine) {
    TempFolder folder;
    const Fixture f;
    const std::string handles = folder.write("h.txt", "0\n3\n12 15\n");
    const std::string per_handle = folder.write("per.txt", rows(f.moved, f.handles, false));
    // A handle out of range, in the list and in indexed rows.
    EXPECT_TRUE(throws_input_error(
        [&] { read_handle_targets(folder.write("far.txt", "0\n3\n16\n7\n"), per_handle, 16, 3); },
        {"far.txt:3:", "handle vertex 16 outside [0, 16)"}));
    EXPECT_TRUE(throws_input_error(
        [&] { read_handle_targets("", folder.write("far2.txt", "1 0 0 0\n99 0 0 0\n"), 16, 3); },
        {"far2.txt:2:", "vertex index 99 outside [0, 16)"}));
    // A handle listed twice: in the list; with two targets in rows.
    EXPECT_TRUE(throws_input_error(
        [&] { read_handle_targets(folder.write("dup.txt", "0\n3\n0 12\n"), per_handle, 16, 3); },
        {"dup.txt:3:", "index 0 repeated (first on line 1)"}));
    EXPECT_TRUE(throws_input_error(
        [&] {
            read_handle_targets("", folder.write("two.txt", "5 0 0 0\n6 1 1 1\n5 0 0 1\n"), 16, 3);
        },
        {"two.txt:3:", "vertex 5 listed twice with two targets (first on line 1)"}));
    // Indexed rows that do not match the list.
    EXPECT_TRUE(throws_input_error(
        [&] {
            read_handle_targets(
                handles, folder.write("other.txt", rows(f.moved, {0, 3, 12, 7}, true)), 16, 3);
        },
        {"other.txt:4:", "vertex 7 is not a handle of", "h.txt"}));
    EXPECT_TRUE(throws_input_error(
        [&] {
            read_handle_targets(handles, folder.write("few.txt", rows(f.moved, {0, 3, 12}, true)),
                                16, 3);
        },
        {"few.txt", "no target for handle vertex 15", "h.txt:3"}));
    // Plain rows of neither count; a mesh file of another size; no handle; no index.
    EXPECT_TRUE(throws_input_error(
        [&] {
            read_handle_targets(
                handles, folder.write("five.txt", rows(f.moved, {0, 1, 2, 3, 4}, false)), 16, 3);
        },
        {"five.txt", "5 rows", "one per vertex (16)", "one per handle", "(4)"}));
    const std::string small = folder.path("small.node");
    const SimplicialMesh other = grid_tetrahedra(1, 1, 1);
    write_mesh_file(small, other.vertices, other.simplices);
    EXPECT_TRUE(throws_input_error([&] { read_handle_targets(handles, small, 16, 3); },
                                   {"small.node", "8 vertices, the rest mesh has 16"}));
    EXPECT_TRUE(throws_input_error(
        [&] { read_handle_targets(folder.write("none.txt", "# none\n"), per_handle, 16, 3); },
        {"none.txt", "no handle vertex"}));
    EXPECT_TRUE(throws_input_error([&] { read_handle_targets("", per_handle, 16, 3); },
                                   {"per.txt:1:", "rows without a vertex index"}));
    EXPECT_TRUE(throws_input_error([&] { read_handle_targets("", small, 16, 3); },
                                   {"small.node", "give the handle list"}));
}

TEST(HandleTargets, MoveHandles) {
    const Fixture f;
    HandleTargets h;
    h.handles = {1, 4};
    h.targets = Eigen::MatrixXd::Constant(2, 3, 7.0);
    const Eigen::MatrixXd moved = move_handles(f.mesh.vertices, h);
    EXPECT_EQ(moved.row(4), Eigen::RowVector3d::Constant(7.0));
    EXPECT_EQ(moved.row(0), f.mesh.vertices.row(0));
    h.handles = {1, 16};
    EXPECT_THROW(move_handles(f.mesh.vertices, h), InvalidArgumentError);
}

}  // namespace
}  // namespace sa
