#include "frontends/output/pose_picture.h"

#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

#include <filesystem>

#include "geometry/mesh/mesh_generators.h"
#include "optim/errors.h"
#include "render_test_util.h"
#include "tests/geometry/io/io_test_util.h"

namespace sa {
namespace {

namespace fs = std::filesystem;

class PosePictureTest : public ::testing::Test {
  protected:
    std::string path(const std::string& name) const { return folder_.path(name); }

    // Pixels whose colour is red-dominated (the inverted colour, 0.9 0.1 0.1, alone or seen
    // through the translucent surface), and the picture's size.
    static int red_pixels(const std::string& png, int* width = nullptr) {
        EXPECT_GT(fs::file_size(png), 1000u);
        vtkNew<vtkPNGReader> reader;
        reader->SetFileName(png.c_str());
        reader->Update();
        vtkImageData* image = reader->GetOutput();
        int dims[3];
        image->GetDimensions(dims);
        if (width) *width = dims[0];
        int count = 0;
        for (int j = 0; j < dims[1]; ++j) {
            for (int i = 0; i < dims[0]; ++i) {
                double c[3];
                for (int k = 0; k < 3; ++k) c[k] = image->GetScalarComponentAsDouble(i, j, 0, k);
                count += c[0] > 60 && c[0] > 2.0 * c[1] && c[0] > 1.6 * c[2];
            }
        }
        return count;
    }

    test::TempFolder folder_;
};

PosePicture small_picture() {
    PosePicture p;
    p.width = 480;
    p.height = 360;
    return p;
}

TEST_F(PosePictureTest, FoldedTetrahedraInsideShowInRed) {
    SKIP_WITHOUT_X();
    // A 6 x 6 x 6 cube; its centre vertex (3, 3, 3) pushed through its neighbours folds
    // tetrahedra that have no boundary facet.
    const SimplicialMesh cube = grid_tetrahedra(6, 6, 6);
    Eigen::MatrixXd pose = cube.vertices;
    const Index centre = (3 * 7 + 3) * 7 + 3;
    pose(centre, 0) += 0.3;  // the spacing is 1/6
    write_pose_png(path("folded.png"), cube, pose, small_picture());
    int width = 0;
    EXPECT_GT(red_pixels(path("folded.png"), &width), 30);
    EXPECT_EQ(width, 480);
    // The rest pose has nothing to mark.
    write_pose_png(path("rest.png"), cube, cube.vertices, small_picture());
    EXPECT_EQ(red_pixels(path("rest.png")), 0);
}

TEST_F(PosePictureTest, FoldedBoundaryTetrahedraAndTriangles) {
    SKIP_WITHOUT_X();
    // A corner vertex pulled through the cube: inverted tetrahedra on the surface.
    const SimplicialMesh cube = grid_tetrahedra(4, 4, 4);
    Eigen::MatrixXd pose = cube.vertices;
    pose.row(0) = Eigen::RowVector3d(0.6, 0.6, 0.6);
    write_pose_png(path("corner.png"), cube, pose, small_picture());
    EXPECT_GT(red_pixels(path("corner.png")), 30);
    // Planar triangles, seen from above.
    const SimplicialMesh grid = grid_triangles(10, 10);
    Eigen::MatrixXd flat = grid.vertices;
    flat.row(60) += Eigen::RowVector2d(0.25, 0.0);  // over its neighbours
    write_pose_png(path("grid.png"), grid, flat, small_picture());
    EXPECT_GT(red_pixels(path("grid.png")), 30);
    write_pose_png(path("grid-rest.png"), grid, grid.vertices, small_picture());
    EXPECT_EQ(red_pixels(path("grid-rest.png")), 0);
}

TEST_F(PosePictureTest, MarkedTetrahedraShowInRedOnAValidPose) {
    SKIP_WITHOUT_X();
    // The rest pose, no tetrahedron inverted, the ones around the centre marked (as sa deform
    // marks those its start inverted).
    const SimplicialMesh cube = grid_tetrahedra(6, 6, 6);
    PosePicture picture = small_picture();
    for (Index s = 0; s < cube.num_simplices(); ++s) {
        const Eigen::RowVector3d centre =
            (cube.vertices.row(cube.simplices(s, 0)) + cube.vertices.row(cube.simplices(s, 1)) +
             cube.vertices.row(cube.simplices(s, 2)) + cube.vertices.row(cube.simplices(s, 3))) /
            4.0;
        if ((centre - Eigen::RowVector3d(0.5, 0.5, 0.5)).norm() < 0.2) picture.marked.push_back(s);
    }
    ASSERT_FALSE(picture.marked.empty());
    write_pose_png(path("marked.png"), cube, cube.vertices, picture);
    EXPECT_GT(red_pixels(path("marked.png")), 30);
    picture.marked = {cube.num_simplices()};
    EXPECT_THROW(write_pose_png(path("bad.png"), cube, cube.vertices, picture),
                 InvalidArgumentError);
    EXPECT_FALSE(fs::exists(path("bad.png")));
}

TEST_F(PosePictureTest, RejectsWrongShapes) {
    const SimplicialMesh cube = grid_tetrahedra(2, 2, 2);
    EXPECT_THROW(write_pose_png(path("a.png"), cube, cube.vertices.leftCols(2)),
                 InvalidArgumentError);
    const SimplicialMesh torus = torus_triangles(6, 6);
    EXPECT_THROW(write_pose_png(path("b.png"), torus, torus.vertices), InvalidArgumentError);
    EXPECT_FALSE(fs::exists(path("a.png")));
}

}  // namespace
}  // namespace sa
