#include "frontends/output/picture_plugin.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "frontends/output/vtk_scene.h"
#include "optim/errors.h"

namespace sa {

namespace {

// ---- Checking the input ----------------------------------------------------------------------

void check_colour(const char* field, const std::array<double, 3>& c) {
    for (double x : c) {
        if (!(x >= 0.0 && x <= 1.0)) {
            throw InvalidArgumentError("write_checkerboard_png: picture." + std::string(field) +
                                       " has a component " + std::to_string(x) + " outside [0, 1]");
        }
    }
}

void check_input(const Eigen::MatrixXd& positions, const Eigen::MatrixXi& faces,
                 const Eigen::MatrixXd& uv, const CheckerboardPicture& picture) {
    const std::string where = "write_checkerboard_png: ";
    if (positions.cols() != 3 && positions.cols() != 2) {
        throw InvalidArgumentError(where + "positions must be #V x 3, got " +
                                   std::to_string(positions.rows()) + " x " +
                                   std::to_string(positions.cols()));
    }
    if (uv.rows() != positions.rows() || uv.cols() != 2) {
        throw InvalidArgumentError(
            where + "uv must be #V x 2 = " + std::to_string(positions.rows()) + " x 2, got " +
            std::to_string(uv.rows()) + " x " + std::to_string(uv.cols()));
    }
    if (faces.cols() != 3 || faces.rows() == 0) {
        throw InvalidArgumentError(where + "faces must be #F x 3 with #F > 0, got " +
                                   std::to_string(faces.rows()) + " x " +
                                   std::to_string(faces.cols()));
    }
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
        for (int k = 0; k < 3; ++k) {
            if (faces(f, k) < 0 || faces(f, k) >= positions.rows()) {
                throw InvalidArgumentError(where + "face " + std::to_string(f) +
                                           " has vertex index " + std::to_string(faces(f, k)) +
                                           ", outside [0, " + std::to_string(positions.rows()) +
                                           ")");
            }
        }
    }
    for (Eigen::Index v = 0; v < positions.rows(); ++v) {
        if (!positions.row(v).allFinite()) {
            throw InvalidArgumentError(where + "vertex " + std::to_string(v) +
                                       " has a non-finite position");
        }
        if (!uv.row(v).allFinite()) {
            throw InvalidArgumentError(where + "vertex " + std::to_string(v) +
                                       " has non-finite uv");
        }
    }
    auto check_size = [&](const char* field, int value) {
        if (value < 16 || value > 8192) {
            throw InvalidArgumentError(where + "picture." + field + " = " + std::to_string(value) +
                                       ", outside [16, 8192]");
        }
    };
    check_size("width", picture.width);
    check_size("height", picture.height);
    if (!std::isfinite(picture.azimuth) || !std::isfinite(picture.elevation)) {
        throw InvalidArgumentError(where + "picture.azimuth and picture.elevation must be finite");
    }
    check_colour("light_colour", picture.light_colour);
    check_colour("dark_colour", picture.dark_colour);
    check_colour("background", picture.background);
}

// ---- The scene ---------------------------------------------------------------------------------

/// Per-vertex normals, area-weighted over the faces around all vertices at the same position,
/// so that the copies of a seam vertex get one normal.
Eigen::MatrixXd welded_normals(const Eigen::MatrixXd& points, const Eigen::MatrixXi& faces) {
    const Eigen::Index n = points.rows();
    std::vector<Eigen::Index> order(n);
    std::iota(order.begin(), order.end(), Eigen::Index(0));
    auto less = [&](Eigen::Index a, Eigen::Index b) {
        for (int c = 0; c < 3; ++c) {
            if (points(a, c) != points(b, c)) return points(a, c) < points(b, c);
        }
        return false;
    };
    std::sort(order.begin(), order.end(), less);
    std::vector<Eigen::Index> group(n);
    Eigen::Index groups = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
        if (i > 0 && less(order[i - 1], order[i])) ++groups;
        group[order[i]] = groups;
    }
    Eigen::MatrixXd sums = Eigen::MatrixXd::Zero(groups + 1, 3);
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
        const Eigen::Vector3d a = points.row(faces(f, 0)), b = points.row(faces(f, 1)),
                              c = points.row(faces(f, 2));
        const Eigen::RowVector3d area_normal = (b - a).cross(c - a).transpose();
        for (int k = 0; k < 3; ++k) sums.row(group[faces(f, k)]) += area_normal;
    }
    Eigen::MatrixXd normals(n, 3);
    for (Eigen::Index v = 0; v < n; ++v) {
        const Eigen::RowVector3d s = sums.row(group[v]);
        const double length = s.norm();
        normals.row(v) =
            length > 0.0 ? Eigen::RowVector3d(s / length) : Eigen::RowVector3d(0, 0, 1);
    }
    return normals;
}

vtkSmartPointer<vtkPolyData> make_surface(const Eigen::MatrixXd& points,
                                          const Eigen::MatrixXi& faces, const Eigen::MatrixXd& uv) {
    // The texture holds 2 x 2 squares, so texture coordinates are uv / 2. They are shifted by
    // an even number of squares first, keeping the pattern, so that large uv keep their
    // precision in single precision on the GPU.
    const Eigen::RowVector2d shift = 2.0 * (uv.colwise().minCoeff() / 2.0).array().floor();
    vtkNew<vtkFloatArray> tcoords;
    tcoords->SetName("uv");
    tcoords->SetNumberOfComponents(2);
    tcoords->SetNumberOfTuples(uv.rows());
    for (Eigen::Index v = 0; v < uv.rows(); ++v) {
        tcoords->SetTypedComponent(v, 0, static_cast<float>((uv(v, 0) - shift[0]) / 2.0));
        tcoords->SetTypedComponent(v, 1, static_cast<float>((uv(v, 1) - shift[1]) / 2.0));
    }
    const Eigen::MatrixXd normals = welded_normals(points, faces);
    vtkNew<vtkFloatArray> vtk_normals;
    vtk_normals->SetName("normals");
    vtk_normals->SetNumberOfComponents(3);
    vtk_normals->SetNumberOfTuples(normals.rows());
    for (Eigen::Index v = 0; v < normals.rows(); ++v) {
        for (int c = 0; c < 3; ++c) {
            vtk_normals->SetTypedComponent(v, c, static_cast<float>(normals(v, c)));
        }
    }
    vtkSmartPointer<vtkPolyData> surface = triangle_surface(points, faces);
    surface->GetPointData()->SetTCoords(tcoords);
    surface->GetPointData()->SetNormals(vtk_normals);
    return surface;
}

/// One period of the checkerboard: 2 x 2 squares of kSquare pixels, light at the lower left.
vtkSmartPointer<vtkImageData> make_checkerboard(const CheckerboardPicture& picture) {
    constexpr int kSquare = 128, kHalfLine = 2;
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(2 * kSquare, 2 * kSquare, 1);
    image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    auto byte = [](double x) { return static_cast<unsigned char>(std::lround(255.0 * x)); };
    for (int j = 0; j < 2 * kSquare; ++j) {
        for (int i = 0; i < 2 * kSquare; ++i) {
            const bool dark = (i / kSquare + j / kSquare) % 2 == 1;
            std::array<double, 3> c = dark ? picture.dark_colour : picture.light_colour;
            auto on_line = [](int x) {
                const int r = x % kSquare;
                return r < kHalfLine || r >= kSquare - kHalfLine;
            };
            if (picture.lines && (on_line(i) || on_line(j))) {
                for (int k = 0; k < 3; ++k) c[k] = 0.45 * picture.dark_colour[k];
            }
            auto* pixel = static_cast<unsigned char*>(image->GetScalarPointer(i, j, 0));
            for (int k = 0; k < 3; ++k) pixel[k] = byte(c[k]);
        }
    }
    return image;
}

// ---- Rendering ------------------------------------------------------------------------------

/// The checkerboard-textured surface as a renderer's actor.
vtkSmartPointer<vtkRenderer> scene(vtkPolyData* surface, const CheckerboardPicture& picture) {
    vtkNew<vtkTexture> texture;
    texture->SetInputData(make_checkerboard(picture));
    texture->RepeatOn();
    texture->InterpolateOn();
    texture->MipmapOn();
    texture->SetMaximumAnisotropicFiltering(8.0f);

    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(surface);
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->SetTexture(texture);
    vtkProperty* property = actor->GetProperty();
    property->SetColor(1.0, 1.0, 1.0);
    property->SetInterpolationToGouraud();
    property->SetAmbient(0.2);
    property->SetDiffuse(0.8);
    property->SetSpecular(0.0);

    auto renderer = vtkSmartPointer<vtkRenderer>::New();
    renderer->SetBackground(picture.background.data());
    renderer->AddActor(actor);
    return renderer;
}

}  // namespace

void write_checkerboard_png_impl(const std::string& path, const Eigen::MatrixXd& positions,
                                 const Eigen::MatrixXi& faces, const Eigen::MatrixXd& uv,
                                 const CheckerboardPicture& picture) {
    check_input(positions, faces, uv, picture);
    Eigen::MatrixXd points = Eigen::MatrixXd::Zero(positions.rows(), 3);
    points.leftCols(positions.cols()) = positions;
    const vtkSmartPointer<vtkPolyData> surface = make_surface(points, faces, uv);
    const vtkSmartPointer<vtkRenderer> renderer = scene(surface, picture);
    render_scene_png(path, renderer, points, scene_view(picture), "write_checkerboard_png");
}

}  // namespace sa
