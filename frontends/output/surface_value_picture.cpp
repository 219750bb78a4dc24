#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>

#include "frontends/output/colour_map.h"
#include "frontends/output/picture_plugin.h"
#include "frontends/output/vtk_scene.h"
#include "optim/errors.h"

namespace sa {

namespace {

void check_input(const Eigen::MatrixXd& positions, const Eigen::MatrixXi& faces,
                 const Eigen::VectorXd& values, const SurfaceValuePicture& picture,
                 const std::vector<unsigned char>& flagged) {
    const std::string where = "write_surface_value_png: ";
    if (positions.cols() != 3) {
        throw InvalidArgumentError(where + "positions must be #V x 3, got " +
                                   std::to_string(positions.rows()) + " x " +
                                   std::to_string(positions.cols()));
    }
    if (faces.cols() != 3 || faces.rows() == 0) {
        throw InvalidArgumentError(where + "faces must be #F x 3 with #F > 0");
    }
    if (values.size() != faces.rows() ||
        (!flagged.empty() && Eigen::Index(flagged.size()) != values.size())) {
        throw InvalidArgumentError(where + "one value (and flag) per face expected, got " +
                                   std::to_string(values.size()) + " values for " +
                                   std::to_string(faces.rows()) + " faces");
    }
    if ((faces.array() < 0).any() || (faces.array() >= positions.rows()).any()) {
        throw InvalidArgumentError(where + "a face has a vertex index outside [0, " +
                                   std::to_string(positions.rows()) + ")");
    }
    if (!positions.allFinite()) throw InvalidArgumentError(where + "a position is not finite");
    for (const int size : {picture.width, picture.height}) {
        if (size < 16 || size > 8192) {
            throw InvalidArgumentError(where + "picture size " + std::to_string(size) +
                                       " outside [16, 8192]");
        }
    }
    if (!(picture.high > picture.low) || !std::isfinite(picture.low) ||
        !std::isfinite(picture.high)) {
        throw InvalidArgumentError(where + "the colour range needs finite low < high");
    }
    if (!(picture.opacity > 0.0 && picture.opacity <= 1.0)) {
        throw InvalidArgumentError(where + "picture.opacity = " + std::to_string(picture.opacity) +
                                   ", outside (0, 1]");
    }
    if (!std::isfinite(picture.azimuth) || !std::isfinite(picture.elevation)) {
        throw InvalidArgumentError(where + "picture.azimuth and picture.elevation must be finite");
    }
}

}  // namespace

void write_surface_value_png_impl(const std::string& path, const Eigen::MatrixXd& positions,
                                  const Eigen::MatrixXi& faces, const Eigen::VectorXd& values,
                                  const SurfaceValuePicture& picture,
                                  const std::vector<unsigned char>& flagged) {
    check_input(positions, faces, values, picture, flagged);
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetNumberOfComponents(4);  // RGBA: unflagged faces get picture.opacity
    colours->SetNumberOfTuples(faces.rows());
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
        std::array<double, 3> c{0.9, 0.1, 0.1};
        if (flagged.empty() || !flagged[f]) {
            const double t = std::isfinite(values[f])
                                 ? (values[f] - picture.low) / (picture.high - picture.low)
                                 : 1.0;
            c = viridis(t);
        }
        for (int k = 0; k < 3; ++k) {
            colours->SetTypedComponent(f, k, static_cast<unsigned char>(std::lround(255 * c[k])));
        }
        const bool opaque = !flagged.empty() && flagged[f];
        colours->SetTypedComponent(
            f, 3, static_cast<unsigned char>(std::lround(255 * (opaque ? 1.0 : picture.opacity))));
    }
    const vtkSmartPointer<vtkPolyData> surface = triangle_surface(positions, faces);
    surface->GetCellData()->SetScalars(colours);

    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(surface);
    mapper->SetScalarModeToUseCellData();
    mapper->SetColorModeToDirectScalars();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    vtkProperty* property = actor->GetProperty();
    property->SetInterpolationToFlat();
    property->SetAmbient(0.3);
    property->SetDiffuse(0.7);
    property->SetSpecular(0.0);

    // The colour bar: the same map over [low, high].
    vtkNew<vtkLookupTable> table;
    table->SetNumberOfTableValues(256);
    table->SetRange(picture.low, picture.high);
    for (int i = 0; i < 256; ++i) {
        const auto c = viridis(i / 255.0);
        table->SetTableValue(i, c[0], c[1], c[2], 1.0);
    }
    vtkNew<vtkScalarBarActor> bar;
    bar->SetLookupTable(table);
    bar->SetTitle(picture.value_name.c_str());
    bar->SetNumberOfLabels(5);
    bar->SetPosition(0.84, 0.12);
    bar->SetWidth(0.14);
    bar->SetHeight(0.66);
    bar->SetBarRatio(0.3);
    bar->UnconstrainedFontSizeOn();
    const int font = std::max(10, picture.height / 50);
    for (vtkTextProperty* text : {bar->GetTitleTextProperty(), bar->GetLabelTextProperty()}) {
        text->SetColor(0.1, 0.1, 0.1);
        text->SetFontFamilyToArial();
        text->SetFontSize(font);
        text->ShadowOff();
        text->ItalicOff();
        text->BoldOff();
    }

    vtkNew<vtkRenderer> renderer;
    renderer->SetBackground(1.0, 1.0, 1.0);
    renderer->AddActor(actor);
    renderer->AddActor2D(bar);
    SceneView view = scene_view(picture);
    view.right = 0.62;  // the colour bar on the right
    render_scene_png(path, renderer, positions, view, "write_surface_value_png");
}

}  // namespace sa
