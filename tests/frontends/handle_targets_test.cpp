#include "frontends/deform/handle_targets.h"

#include <gtest/gtest.h>

#include "geometry/io/mesh_file.h"
#include "geometry/mesh_generators.h"
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
