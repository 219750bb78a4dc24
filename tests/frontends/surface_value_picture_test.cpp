#include "frontends/output/surface_value_picture.h"

#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

#include <cstdlib>
#include <filesystem>

#include "frontends/output/colour_map.h"
#include "geometry/mesh/mesh_generators.h"
#include "optim/errors.h"
#include "render_test_util.h"

namespace sa {
namespace {

namespace fs = std::filesystem;

/// Pixels within `tolerance` (0..1 per channel, up to the lighting's brightness) of `c`.
int count_colour(vtkImageData* image, const std::array<double, 3>& c) {
    int dims[3];
    image->GetDimensions(dims);
    const Eigen::Vector3d target = Eigen::Vector3d(c[0], c[1], c[2]).normalized();
    int count = 0;
    for (int j = 0; j < dims[1]; ++j) {
        for (int i = 0; i < dims[0]; ++i) {
            Eigen::Vector3d p;
            for (int k = 0; k < 3; ++k) p[k] = image->GetScalarComponentAsDouble(i, j, 0, k) / 255;
            if (p.norm() < 0.1 || p.minCoeff() > 0.97) continue;  // black text, white background
            if (p.normalized().dot(target) > std::cos(3.0 * M_PI / 180.0)) ++count;
        }
    }
    return count;
}

// A sphere whose upper half has value 1 (the first colour), lower half 3 (the last), and a band
// of flagged faces (red).
TEST(SurfaceValuePicture, ColoursFacesByValueAndFlagsInRed) {
    SKIP_WITHOUT_X();
    const SimplicialMesh sphere = sphere_triangles(8);
    Eigen::VectorXd values(sphere.num_simplices());
    std::vector<unsigned char> flagged(sphere.num_simplices(), 0);
    for (Index f = 0; f < sphere.num_simplices(); ++f) {
        double z = 0.0;
        for (int k = 0; k < 3; ++k) z += sphere.vertices(sphere.simplices(f, k), 2) / 3.0;
        values[f] = z > 0.0 ? 1.0 : 3.0;
        flagged[f] = std::abs(z - 0.5) < 0.1;
    }
    const fs::path dir =
        fs::temp_directory_path() / ("sa_surface_picture_" + std::to_string(getpid()));
    fs::create_directories(dir);
    const std::string png = (dir / "sphere.png").string();
    SurfaceValuePicture picture;
    picture.title = "values 1 and 3";
    picture.value_name = "value";
    picture.low = 1.0;
    picture.high = 3.0;
    picture.width = 400;
    picture.height = 300;
    picture.elevation = 0.0;
    write_surface_value_png(png, sphere.vertices, sphere.simplices, values, picture, flagged);
    vtkNew<vtkPNGReader> reader;
    reader->SetFileName(png.c_str());
    reader->Update();
    vtkImageData* image = reader->GetOutput();
    int dims[3];
    image->GetDimensions(dims);
    EXPECT_EQ(dims[0], 400);
    EXPECT_EQ(dims[1], 300);
    const int pixels = 400 * 300;
    EXPECT_GT(count_colour(image, viridis(0.0)), pixels / 100) << "low values";
    EXPECT_GT(count_colour(image, viridis(1.0)), pixels / 100) << "high values";
    EXPECT_GT(count_colour(image, {0.9, 0.1, 0.1}), pixels / 500) << "flagged faces";

    EXPECT_THROW(write_surface_value_png((dir / "bad.png").string(), sphere.vertices,
                                         sphere.simplices, values.head(3), picture),
                 InvalidArgumentError);
    SurfaceValuePicture empty_range = picture;
    empty_range.high = empty_range.low;
    EXPECT_THROW(write_surface_value_png((dir / "bad.png").string(), sphere.vertices,
                                         sphere.simplices, values, empty_range),
                 InvalidArgumentError);
    EXPECT_FALSE(fs::exists(dir / "bad.png"));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace sa
