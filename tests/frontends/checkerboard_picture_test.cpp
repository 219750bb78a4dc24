#include "frontends/output/checkerboard_picture.h"

#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "geometry/mesh/mesh_generators.h"
#include "optim/errors.h"
#include "render_test_util.h"

namespace sa {
namespace {

namespace fs = std::filesystem;

// An empty folder of its own, removed afterwards.
class CheckerboardPictureTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("sa_checkerboard_" + std::to_string(getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    bool folder_empty() const { return fs::is_empty(dir_); }

    fs::path dir_;
};

// Sets (or, with nullopt, unsets) an environment variable for its lifetime.
class ScopedEnv {
  public:
    ScopedEnv(const char* name, std::optional<std::string> value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        value ? setenv(name, value->c_str(), 1) : unsetenv(name);
    }
    ~ScopedEnv() { old_ ? setenv(name_, old_->c_str(), 1) : unsetenv(name_); }

  private:
    const char* name_;
    std::optional<std::string> old_;
};

// A bumpy unit square in space, uv = 4 (x, y): 4 x 4 squares.
struct Surface {
    Eigen::MatrixXd positions, uv;
    Eigen::MatrixXi faces;
};

Surface bumpy_square() {
    const SimplicialMesh grid = grid_triangles(24, 24);
    Surface s;
    s.faces = grid.simplices;
    s.positions.resize(grid.vertices.rows(), 3);
    s.uv.resize(grid.vertices.rows(), 2);
    for (Eigen::Index v = 0; v < grid.vertices.rows(); ++v) {
        const double x = grid.vertices(v, 0), y = grid.vertices(v, 1);
        s.positions.row(v) << x, y, 0.15 * std::sin(3.0 * x) * std::cos(2.0 * y);
        s.uv.row(v) << 4.0 * x, 4.0 * y;
    }
    return s;
}

// Pixels whose colour is, up to brightness (the lighting scales it), within 2 degrees of `c`,
// not too dark to tell and not the background.
int count_shades(vtkImageData* image, const std::array<double, 3>& c,
                 const std::array<double, 3>& background) {
    int dims[3];
    image->GetDimensions(dims);
    const Eigen::Vector3d target = Eigen::Vector3d(c[0], c[1], c[2]).normalized();
    const Eigen::Vector3d back(background[0], background[1], background[2]);
    int count = 0;
    for (int j = 0; j < dims[1]; ++j) {
        for (int i = 0; i < dims[0]; ++i) {
            Eigen::Vector3d p;
            for (int k = 0; k < 3; ++k) p[k] = image->GetScalarComponentAsDouble(i, j, 0, k) / 255;
            if (p.norm() < 0.15 || (p - back).norm() < 0.02) continue;
            if (p.normalized().dot(target) > std::cos(2.0 * M_PI / 180.0)) ++count;
        }
    }
    return count;
}

TEST_F(CheckerboardPictureTest, ShowsBothSquareColoursAtTheRequestedSize) {
    SKIP_WITHOUT_X();
    const Surface s = bumpy_square();
    CheckerboardPicture picture;
    picture.title = "bumpy square, uv = 4 (x, y)";
    picture.width = 480;
    picture.height = 360;
    const std::string png = path("square.png");
    write_checkerboard_png(png, s.positions, s.faces, s.uv, picture);

    ASSERT_TRUE(fs::exists(png));
    vtkNew<vtkPNGReader> reader;
    reader->SetFileName(png.c_str());
    reader->Update();
    vtkImageData* image = reader->GetOutput();
    int dims[3];
    image->GetDimensions(dims);
    EXPECT_EQ(dims[0], picture.width);
    EXPECT_EQ(dims[1], picture.height);
    ASSERT_GE(image->GetNumberOfScalarComponents(), 3);
    // Without the texture the surface would be shades of white: neither colour would appear.
    const int pixels = picture.width * picture.height;
    const int light = count_shades(image, picture.light_colour, picture.background);
    const int dark = count_shades(image, picture.dark_colour, picture.background);
    EXPECT_GT(light, pixels / 20) << "light squares";
    EXPECT_GT(dark, pixels / 20) << "dark squares";
    // Nothing but the picture in the folder: the temporary name is gone.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

TEST_F(CheckerboardPictureTest, StartsItsOwnXvfbWithoutDisplay) {
    if (!xvfb_on_path()) GTEST_SKIP() << "no Xvfb (scripts/setup.sh installs xvfb)";
    const ScopedEnv no_display("DISPLAY", std::nullopt);
    const SimplicialMesh torus = torus_triangles(32, 16);
    Eigen::MatrixXd uv = 3.0 * torus.vertices.leftCols(2);
    CheckerboardPicture picture;
    picture.width = 200;
    picture.height = 160;
    const std::string png = path("torus.png");
    write_checkerboard_png(png, torus.vertices, torus.simplices, uv, picture);
    EXPECT_TRUE(fs::exists(png));
    EXPECT_EQ(std::getenv("DISPLAY"), nullptr);  // left as it was
}

TEST_F(CheckerboardPictureTest, NoDisplayAndNoXvfbIsAnInputError) {
    const Surface s = bumpy_square();
    const std::string png = path("none.png");
    {
        const ScopedEnv no_display("DISPLAY", std::nullopt);
        const ScopedEnv no_path("PATH", dir_.string());  // an empty folder: no Xvfb
        EXPECT_THROW(write_checkerboard_png(png, s.positions, s.faces, s.uv, {}), InputError);
    }
    EXPECT_TRUE(folder_empty());
}

TEST_F(CheckerboardPictureTest, BadInputThrowsAndWritesNothing) {
    const Surface s = bumpy_square();
    const std::string png = path("bad.png");
    const CheckerboardPicture picture;
    auto expect_invalid = [&](const Eigen::MatrixXd& positions, const Eigen::MatrixXi& faces,
                              const Eigen::MatrixXd& uv, const CheckerboardPicture& p) {
        EXPECT_THROW(write_checkerboard_png(png, positions, faces, uv, p), InvalidArgumentError);
        EXPECT_TRUE(folder_empty());
    };
    expect_invalid(s.positions, s.faces, s.uv.topRows(s.uv.rows() - 1), picture);  // #uv != #V
    expect_invalid(s.positions, s.faces, s.uv.leftCols(1), picture);               // uv #V x 1
    expect_invalid(s.positions.leftCols(1), s.faces, s.uv, picture);               // positions
    expect_invalid(s.positions, s.faces.leftCols(2), s.uv, picture);               // faces #F x 2
    Eigen::MatrixXi out_of_range = s.faces;
    out_of_range(3, 1) = static_cast<int>(s.positions.rows());
    expect_invalid(s.positions, out_of_range, s.uv, picture);
    out_of_range(3, 1) = -1;
    expect_invalid(s.positions, out_of_range, s.uv, picture);
    Eigen::MatrixXd nan_positions = s.positions;
    nan_positions(5, 2) = std::nan("");
    expect_invalid(nan_positions, s.faces, s.uv, picture);
    Eigen::MatrixXd inf_uv = s.uv;
    inf_uv(7, 0) = INFINITY;
    expect_invalid(s.positions, s.faces, inf_uv, picture);
    CheckerboardPicture tiny;
    tiny.width = 0;
    expect_invalid(s.positions, s.faces, s.uv, tiny);
    CheckerboardPicture bad_colour;
    bad_colour.dark_colour[1] = 1.5;
    expect_invalid(s.positions, s.faces, s.uv, bad_colour);

    // An existing file is left as it was.
    { std::ofstream(png) << "old"; }
    EXPECT_THROW(write_checkerboard_png(png, s.positions, s.faces, s.uv.leftCols(1), picture),
                 InvalidArgumentError);
    std::ifstream in(png);
    std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(content, "old");
}

}  // namespace
}  // namespace sa
