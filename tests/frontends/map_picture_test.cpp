// The pictures of layouts and maps: a layout fills its frame, sa map's picture shows the
// folds of the initial map in red and none in a verified result, in 2D and 3D, and the command
// writes it by default (next to --out), where --png says, or not at all with --no-png.
#include "frontends/output/map_picture.h"

#include <gtest/gtest.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <vector>

#include "frontends/output/layout_picture.h"
#include "geometry/io/mesh_file.h"
#include "geometry/mesh/mesh_generators.h"
#include "geometry/mesh/mesh_topology.h"
#include "optim/errors.h"
#include "render_test_util.h"
#include "tests/geometry/io/io_test_util.h"

namespace sa {
namespace {

namespace fs = std::filesystem;

/// A PNG read back: its size, and per pixel whether it is red-dominated (the inverted colour)
/// or not white (drawn).
struct Pixels {
    int width = 0, height = 0;
    std::vector<unsigned char> red, drawn;  // row 0 at the top

    explicit Pixels(const std::string& png) {
        EXPECT_GT(fs::file_size(png), 1000u) << png;
        vtkNew<vtkPNGReader> reader;
        reader->SetFileName(png.c_str());
        reader->Update();
        vtkImageData* image = reader->GetOutput();
        int dims[3];
        image->GetDimensions(dims);
        width = dims[0];
        height = dims[1];
        red.assign(std::size_t(width) * height, 0);
        drawn.assign(std::size_t(width) * height, 0);
        for (int j = 0; j < height; ++j) {
            for (int i = 0; i < width; ++i) {
                double c[3];
                for (int k = 0; k < 3; ++k) c[k] = image->GetScalarComponentAsDouble(i, j, 0, k);
                const std::size_t at = std::size_t(height - 1 - j) * width + i;  // VTK: y up
                red[at] = c[0] > 60 && c[0] > 2.0 * c[1] && c[0] > 1.6 * c[2];
                drawn[at] = c[0] < 250 || c[1] < 250 || c[2] < 250;
            }
        }
    }
    /// Red pixels in columns [x0, x1).
    int red_in(int x0, int x1) const {
        int count = 0;
        for (int j = 0; j < height; ++j)
            for (int i = std::max(0, x0); i < std::min(width, x1); ++i)
                count += red[std::size_t(j) * width + i];
        return count;
    }
    /// The extent (columns, rows) of the drawn pixels in columns [x0, x1) and rows [y0, height).
    std::pair<int, int> drawn_extent(int x0, int x1, int y0) const {
        int left = width, right = -1, top = height, bottom = -1;
        for (int j = y0; j < height; ++j) {
            for (int i = x0; i < x1; ++i) {
                if (!drawn[std::size_t(j) * width + i]) continue;
                left = std::min(left, i);
                right = std::max(right, i);
                top = std::min(top, j);
                bottom = std::max(bottom, j);
            }
        }
        return {right - left + 1, bottom - top + 1};
    }
};

// Where layout_picture.cpp puts things: margins, the title row, the colour bar on the right.
constexpr int kMargin = 40, kTitle = 60, kBar = 140, kGap = 40;

/// A planar grid with its boundary as handles and one interior vertex pushed over its neighbours.
MappingProblem folded_grid() {
    MappingProblem problem;
    problem.source = "folded grid";
    problem.mesh = grid_triangles(8, 8);
    problem.initial = problem.mesh.vertices.leftCols(2);
    const MeshTopology topology = mesh_topology(problem.mesh, "grid");
    for (Index v = 0; v < problem.mesh.num_vertices(); ++v)
        if (topology.boundary_vertex[v]) problem.handles.push_back(v);
    problem.initial.row(4 * 9 + 4) += Eigen::RowVector2d(0.3, 0.05);  // spacing 1/8
    return problem;
}

TEST(LayoutPicture, ALongLayoutFillsItsFrame) {
    test::TempFolder folder;
    // A 10 x 1 strip: its panel is 4:1 (the clamp), and the strip fills the panel's width.
    const SimplicialMesh strip = grid_triangles(40, 4);
    Eigen::MatrixXd uv = strip.vertices.leftCols(2);
    uv.col(0) *= 10.0;
    const Eigen::VectorXd values = Eigen::VectorXd::Ones(strip.num_simplices());
    LayoutPicture picture;
    picture.size = 400;
    write_layout_png(folder.path("wide.png"), uv, strip.simplices, values, picture);
    const Pixels wide(folder.path("wide.png"));
    EXPECT_EQ(wide.width, 2 * kMargin + 400 + kBar);
    EXPECT_LT(wide.height, wide.width / 2);  // not the square frame of old
    const auto [w, h] = wide.drawn_extent(0, wide.width - kBar, kTitle);
    EXPECT_GE(w, 396);  // the whole panel width (edges antialiased)
    EXPECT_LE(w, 404);
    EXPECT_GE(h, 36);  // 400 / 10, the strip's own aspect, centred in the 400 x 100 panel
    EXPECT_LE(h, 44);

    // Tall: the panel is 100 x 400, the strip spans its height.
    Eigen::MatrixXd tall(uv.rows(), 2);
    tall << uv.col(1), uv.col(0);
    write_layout_png(folder.path("tall.png"), tall, strip.simplices, values, picture);
    const Pixels high(folder.path("tall.png"));
    EXPECT_EQ(high.width, 2 * kMargin + 100 + kBar);
    EXPECT_GE(high.drawn_extent(0, high.width - kBar, kTitle).second, 396);
    EXPECT_EQ(high.red_in(0, high.width), 0);
}

TEST(LayoutPicture, RejectsInconsistentShapes) {
    test::TempFolder folder;
    const SimplicialMesh grid = grid_triangles(2, 2);
    const Eigen::MatrixXd uv = grid.vertices.leftCols(2);
    const Eigen::VectorXd values = Eigen::VectorXd::Ones(grid.num_simplices());
    EXPECT_THROW(write_layout_png(folder.path("a.png"), uv, grid.simplices, values.head(2), {}),
                 InvalidArgumentError);
    Eigen::MatrixXi faces = grid.simplices;
    faces(0, 0) = int(uv.rows());
    EXPECT_THROW(write_layout_png(folder.path("b.png"), uv, faces, values, {}),
                 InvalidArgumentError);
    EXPECT_THROW(write_layouts_png(folder.path("c.png"), grid.simplices, {}, {}),
                 InvalidArgumentError);
    EXPECT_FALSE(fs::exists(folder.path("a.png")) || fs::exists(folder.path("b.png")));
}

TEST(MapPicture, TwoDimensionsShowTheInitialFoldsBesideTheResult) {
    test::TempFolder folder;
    const MappingProblem problem = folded_grid();
    const SimplexAssemblyResult result = run_simplex_assembly(problem, {});
    ASSERT_GT(result.initial_quality.inverted, 0);
    ASSERT_TRUE(result.success) << result.message;
    MapPicture settings;
    settings.size = 300;
    write_map_png(folder.path("map.png"), problem, result, settings);
    const Pixels p(folder.path("map.png"));
    // Two square panels (the grid is square) and the colour bar.
    EXPECT_EQ(p.width, 2 * kMargin + 2 * 300 + kGap + kBar);
    const int second = kMargin + 300 + kGap;
    EXPECT_GT(p.red_in(kMargin, kMargin + 300), 30);   // the initial map's folds
    EXPECT_EQ(p.red_in(second - 5, second + 305), 0);  // none in the verified result
    EXPECT_GT(p.drawn_extent(second, second + 300, kTitle).first, 290);
}

TEST(MapPicture, ThreeDimensionsMarkTheInitialFolds) {
    SKIP_WITHOUT_X();
    test::TempFolder folder;
    MappingProblem problem;
    problem.mesh = grid_tetrahedra(4, 4, 4);
    problem.initial = problem.mesh.vertices;
    const MeshTopology topology = mesh_topology(problem.mesh, "cube");
    std::vector<unsigned char> boundary(problem.mesh.num_vertices(), 0);
    for (const BoundaryFacet& f : topology.boundary_facets)
        for (int k = 0; k < 4; ++k)
            if (k != f.opposite) boundary[problem.mesh.simplices(f.simplex, k)] = 1;
    for (Index v = 0; v < problem.mesh.num_vertices(); ++v)
        if (boundary[v]) problem.handles.push_back(v);
    problem.initial.row((2 * 5 + 2) * 5 + 2) += Eigen::RowVector3d(0.4, 0.1, 0.0);  // spacing 1/4
    const SimplexAssemblyResult result = run_simplex_assembly(problem, {});
    ASSERT_GT(result.initial_quality.inverted, 0);
    ASSERT_TRUE(result.success) << result.message;
    MapPicture settings;
    settings.size = 480;
    write_map_png(folder.path("cube.png"), problem, result, settings);
    const Pixels p(folder.path("cube.png"));
    EXPECT_EQ(p.width, 480);
    EXPECT_EQ(p.height, 360);
    EXPECT_GT(p.red_in(0, p.width), 30);
}

// ---- The command ----------------------------------------------------------------------------

class SaMapPicture : public ::testing::Test {
  protected:
    int sa(const std::string& arguments) {
        const std::string command = std::string(SA_EXECUTABLE) + " " + arguments + " > " +
                                    folder_.path("out.txt") + " 2> " + folder_.path("err.txt");
        return WEXITSTATUS(std::system(command.c_str()));
    }
    std::string text(const std::string& name) const {
        std::ifstream in(folder_.path(name));
        return std::string(std::istreambuf_iterator<char>(in), {});
    }
    /// The problem as a plain-text problem file (shared/data/README.md).
    std::string write_problem(const std::string& name, const MappingProblem& problem) {
        std::ofstream f(folder_.path(name));
        f.precision(17);
        const Eigen::MatrixXd& rest = problem.mesh.vertices;
        f << rest.rows() << ' ' << rest.cols() << '\n'
          << rest << '\n'
          << problem.initial.rows() << ' ' << problem.initial.cols() << '\n'
          << problem.initial << '\n'
          << problem.mesh.simplices.rows() << ' ' << problem.mesh.simplices.cols() << '\n'
          << problem.mesh.simplices << '\n'
          << problem.handles.size() << '\n';
        for (Index h : problem.handles) f << h << '\n';
        return folder_.path(name);
    }
    test::TempFolder folder_;
};

TEST_F(SaMapPicture, WritesItsPictureByDefaultWhereToldOrNot) {
    MappingProblem problem = folded_grid();
    problem.mesh.vertices = problem.mesh.vertices.leftCols(2).eval();
    const std::string input = write_problem("grid.txt", problem);
    ASSERT_EQ(sa("map --rest " + input + " --out " + folder_.path("m.vtu") + " --quiet"), 0)
        << text("err.txt");
    EXPECT_NE(text("out.txt").find("wrote " + folder_.path("m.vtu") + ", " + folder_.path("m.png")),
              std::string::npos)
        << text("out.txt");
    const Pixels p(folder_.path("m.png"));
    EXPECT_GT(p.width, p.height);  // two panels side by side
    EXPECT_GT(p.red_in(0, p.width / 2), 30);

    ASSERT_EQ(sa("map --rest " + input + " --out " + folder_.path("n.vtu") + " --png " +
                 folder_.path("elsewhere.png") + " --quiet"),
              0);
    EXPECT_TRUE(fs::exists(folder_.path("elsewhere.png")));
    EXPECT_FALSE(fs::exists(folder_.path("n.png")));
    ASSERT_EQ(sa("map --rest " + input + " --out " + folder_.path("o.vtu") + " --no-png --quiet"),
              0);
    EXPECT_FALSE(fs::exists(folder_.path("o.png")));
    // Not a PNG name: one line, exit 2, nothing written.
    EXPECT_EQ(sa("map --rest " + input + " --out " + folder_.path("q.vtu") + " --png " +
                 folder_.path("q.jpg")),
              2);
    EXPECT_FALSE(fs::exists(folder_.path("q.vtu")));
}

TEST_F(SaMapPicture, ThreeDimensionalPictureOrOneLineWhy) {
    const SimplicialMesh cube = grid_tetrahedra(3, 3, 3);
    MappingProblem problem;
    problem.mesh = cube;
    problem.initial = cube.vertices;
    for (Index v = 0; v < cube.num_vertices(); ++v) {
        const Eigen::RowVector3d x = cube.vertices.row(v);
        if ((x.array() == 0.0).any() || (x.array() == 1.0).any()) problem.handles.push_back(v);
    }
    problem.initial.row((1 * 4 + 1) * 4 + 1) += Eigen::RowVector3d(0.5, 0.0, 0.0);  // folds
    const std::string input = write_problem("cube.txt", problem);
    const char* display = std::getenv("DISPLAY");
    const bool renders = (display && *display) || xvfb_on_path();
    ASSERT_EQ(sa("map --rest " + input + " --out " + folder_.path("c.vtu") + " --quiet"), 0)
        << text("err.txt");
    EXPECT_TRUE(fs::exists(folder_.path("c.vtu")));
    if (renders) {
        const Pixels p(folder_.path("c.png"));
        EXPECT_GT(p.red_in(0, p.width), 30);
    }
    // Without a display and without Xvfb the map is still written, and one line says why.
    const std::string no_x = "env -u DISPLAY PATH=/nonexistent ";
    const std::string command = no_x + SA_EXECUTABLE + " map --rest " + input + " --out " +
                                folder_.path("d.vtu") + " --quiet > " + folder_.path("out.txt") +
                                " 2> " + folder_.path("err.txt");
    ASSERT_EQ(WEXITSTATUS(std::system(command.c_str())), 0) << text("err.txt");
    EXPECT_TRUE(fs::exists(folder_.path("d.vtu")));
    EXPECT_FALSE(fs::exists(folder_.path("d.png")));
    const std::string err = text("err.txt");
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_NE(err.find("no picture " + folder_.path("d.png")), std::string::npos) << err;
}

// `sa param`, `sa deform` and `sa polycube` as `sa map`: a picture beside --out by default, where
// --png says, none with --no-png, a name that is not a PNG refused before anything is written.
TEST_F(SaMapPicture, EveryCommandDrawsItsPictureByDefault) {
    const SimplicialMesh square = grid_triangles(8, 8);
    Eigen::MatrixXd bump(square.num_vertices(), 3);
    for (Index v = 0; v < square.num_vertices(); ++v) {
        const double x = square.vertices(v, 0), y = square.vertices(v, 1);
        bump.row(v) << x, y, 0.2 * std::sin(4.0 * x) * y;
    }
    write_mesh_file(folder_.path("bump.off"), bump, square.simplices);
    const SimplicialMesh box = grid_tetrahedra(2, 2, 2);
    write_mesh_file(folder_.path("box.mesh"), box.vertices, box.simplices);
    std::ofstream targets(folder_.path("t.txt"));  // the x = 1 face lifted, the x = 0 face fixed
    for (Index v = 0; v < box.num_vertices(); ++v) {
        const double x = box.vertices(v, 0);
        if (x > 0.0 && x < 1.0) continue;
        targets << v << ' ' << x << ' ' << box.vertices(v, 1) + (x > 0.5 ? 0.2 : 0.0) << ' '
                << box.vertices(v, 2) << '\n';
    }
    targets.close();
    const char* display = std::getenv("DISPLAY");
    const bool renders = (display && *display) || xvfb_on_path();
    struct Command {
        std::string arguments, out;  // `out` without its extension
        bool needs_x;
    };
    const std::vector<Command> commands = {
        {"param --mesh " + folder_.path("bump.off") + " --out ", "uv", false},
        {"deform --rest " + folder_.path("box.mesh") + " --targets " + folder_.path("t.txt") +
             " --out ",
         "pose", true},
        {"polycube --mesh " + folder_.path("box.mesh") + " --out ", "cube", true}};
    const std::map<std::string, std::string> extension = {
        {"uv", ".obj"}, {"pose", ".vtu"}, {"cube", ".mesh"}};
    for (const Command& c : commands) {
        const std::string ext = extension.at(c.out);
        const std::string out = folder_.path(c.out + ext), png = folder_.path(c.out + ".png");
        ASSERT_EQ(sa(c.arguments + out + " --quiet"), 0) << c.arguments << text("err.txt");
        EXPECT_TRUE(fs::exists(out)) << out;
        if (!c.needs_x || renders) {
            EXPECT_GT(fs::file_size(png), 1000u) << png;
            EXPECT_NE(text("out.txt").find(", " + png + " ("), std::string::npos)
                << text("out.txt");
        }
        const std::string other = folder_.path(c.out + "-2" + ext);
        ASSERT_EQ(sa(c.arguments + other + " --png " + folder_.path(c.out + "-elsewhere.png") +
                     " --quiet"),
                  0)
            << text("err.txt");
        EXPECT_FALSE(fs::exists(folder_.path(c.out + "-2.png")));
        if (!c.needs_x || renders) {
            EXPECT_TRUE(fs::exists(folder_.path(c.out + "-elsewhere.png")));
        }
        const std::string plain = folder_.path(c.out + "-3" + ext);
        ASSERT_EQ(sa(c.arguments + plain + " --no-png --quiet"), 0) << text("err.txt");
        EXPECT_TRUE(fs::exists(plain));
        EXPECT_FALSE(fs::exists(folder_.path(c.out + "-3.png")));
        const std::string refused = folder_.path(c.out + "-4" + ext);
        EXPECT_EQ(sa(c.arguments + refused + " --png " + folder_.path(c.out + "-4.jpg")), 2);
        EXPECT_EQ(text("err.txt"), "sa: error: --png " + folder_.path(c.out + "-4.jpg") +
                                       ": expected a .png file\n");
        EXPECT_FALSE(fs::exists(refused));
    }
}

}  // namespace
}  // namespace sa
