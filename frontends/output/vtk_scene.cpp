#include "frontends/output/vtk_scene.h"

#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPoints.h>
#include <vtkRenderWindow.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <mutex>

#include "frontends/output/x_display.h"
#include "geometry/io/atomic_file.h"
#include "geometry/io/vtk_capture.h"
#include "optim/errors.h"

namespace sa {

namespace {

/// Turns and zooms the camera so that the projected vertices fill the box [-1 + margin,
/// right - margin] x [-1 + margin, top] in normalized device coordinates, centred. A few rounds,
/// since panning a perspective view moves near and far points differently.
void fit_camera(vtkRenderer* renderer, const Eigen::MatrixXd& points, double aspect, double top,
                double right) {
    constexpr double kMargin = 0.06;
    vtkCamera* camera = renderer->GetActiveCamera();
    const double bottom = -1.0 + kMargin, left = -1.0 + kMargin;
    const double half_width = 0.5 * (right - kMargin - left),
                 centre_x = 0.5 * (right - kMargin + left);
    const double half_height = 0.5 * (top - bottom), centre_y = 0.5 * (top + bottom);
    for (int round = 0; round < 4; ++round) {
        renderer->ResetCameraClippingRange();
        vtkMatrix4x4* m = camera->GetCompositeProjectionTransformMatrix(aspect, -1.0, 1.0);
        Eigen::Array2d lo(1e300, 1e300), hi(-1e300, -1e300);
        for (Eigen::Index v = 0; v < points.rows(); ++v) {
            const double p[4] = {points(v, 0), points(v, 1), points(v, 2), 1.0};
            double q[4];
            m->MultiplyPoint(p, q);
            if (q[3] <= 0.0) continue;  // behind the camera: cannot happen after ResetCamera
            const Eigen::Array2d ndc(q[0] / q[3], q[1] / q[3]);
            lo = lo.min(ndc);
            hi = hi.max(ndc);
        }
        if (!(hi[0] > lo[0]) || !(hi[1] > lo[1])) return;  // a point or a segment: leave as is
        const double zoom =
            std::min(2.0 * half_width / (hi[0] - lo[0]), 2.0 * half_height / (hi[1] - lo[1]));
        camera->Zoom(zoom);
        // After the zoom the projection has scaled by `zoom` about the centre; pan the rest.
        const double dx = 0.5 * (lo[0] + hi[0]) * zoom - centre_x,
                     dy = 0.5 * (lo[1] + hi[1]) * zoom - centre_y;
        const double tan_half = std::tan(0.5 * camera->GetViewAngle() * M_PI / 180.0);
        const double reach = camera->GetDistance() * tan_half;
        double up[3], direction[3], right[3];
        camera->GetViewUp(up);
        camera->GetDirectionOfProjection(direction);
        right[0] = direction[1] * up[2] - direction[2] * up[1];
        right[1] = direction[2] * up[0] - direction[0] * up[2];
        right[2] = direction[0] * up[1] - direction[1] * up[0];
        double position[3], focal[3];
        camera->GetPosition(position);
        camera->GetFocalPoint(focal);
        for (int c = 0; c < 3; ++c) {
            const double move = dx * reach * aspect * right[c] + dy * reach * up[c];
            position[c] += move;
            focal[c] += move;
        }
        camera->SetPosition(position);
        camera->SetFocalPoint(focal);
    }
    renderer->ResetCameraClippingRange();
}

// ---- Rendering ------------------------------------------------------------------------------

// Serializes the calls (see checkerboard_picture.h).

// Serializes the calls (see vtk_scene.h).
std::mutex& render_mutex() {
    static std::mutex mutex;
    return mutex;
}

}  // namespace

void render_scene_png(const std::string& path, vtkRenderer* renderer, const Eigen::MatrixXd& points,
                      const SceneView& view, const std::string& who) {
    // The title: the fitted scene stays below it.
    const int font_size = std::max(12, view.height / 36);
    const int title_top = std::max(4, view.height / 60);
    double top = 1.0 - 0.06;
    vtkNew<vtkTextActor> title;
    if (!view.title.empty()) {
        title->SetInput(view.title.c_str());
        vtkTextProperty* text = title->GetTextProperty();
        text->SetFontFamilyToArial();
        text->SetFontSize(font_size);
        text->SetColor(0.1, 0.1, 0.1);
        text->SetJustificationToCentered();
        text->SetVerticalJustificationToTop();
        title->SetDisplayPosition(view.width / 2, view.height - title_top);
        renderer->AddActor2D(title);
        top = 1.0 - 2.0 * (title_top + 1.8 * font_size) / view.height;
    }

    renderer->ResetCamera();
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->Azimuth(view.azimuth);
    camera->Elevation(view.elevation);
    camera->OrthogonalizeViewUp();
    renderer->ResetCamera();
    fit_camera(renderer, points, double(view.width) / view.height, top, view.right);

    std::lock_guard<std::mutex> lock(render_mutex());
    VtkCapture caught;
    auto image = vtkSmartPointer<vtkImageData>::New();
    {
        const XDisplay display(view.width, view.height, who);
        vtkNew<vtkRenderWindow> window;
        window->SetDisplayId(display.get());
        window->SetOffScreenRendering(1);
        window->SetSize(view.width, view.height);
        window->SetMultiSamples(8);
        window->AddRenderer(renderer);
        window->Render();

        vtkNew<vtkWindowToImageFilter> grab;
        grab->SetInput(window);
        grab->SetInputBufferTypeToRGB();
        grab->ReadFrontBufferOff();
        grab->Update();
        image->DeepCopy(grab->GetOutput());
        grab->SetInput(nullptr);
        window->RemoveRenderer(renderer);
        window->Finalize();  // before the display connection closes
    }
    int dims[3];
    image->GetDimensions(dims);
    if (dims[0] != view.width || dims[1] != view.height) {
        const std::string why = caught.first_message();
        throw InputError(who + ": rendering gave a " + std::to_string(dims[0]) + " x " +
                         std::to_string(dims[1]) + " picture instead of " +
                         std::to_string(view.width) + " x " + std::to_string(view.height) +
                         (why.empty() ? "" : " (" + why + ")"));
    }

    AtomicFile file(path, true);
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName(file.temporary_path().c_str());
    writer->SetInputData(image);
    writer->Write();
    if (writer->GetErrorCode() != 0) {
        const std::string why = caught.first_message();
        throw InputError(path + ": cannot write the picture" +
                         (why.empty() ? "" : " (" + why + ")"));
    }
    file.commit();
}

vtkSmartPointer<vtkPolyData> triangle_surface(const Eigen::MatrixXd& points,
                                              const Eigen::MatrixXi& faces) {
    vtkNew<vtkPoints> vtk_points;
    vtk_points->SetDataTypeToDouble();
    vtk_points->SetNumberOfPoints(points.rows());
    for (Eigen::Index v = 0; v < points.rows(); ++v)
        vtk_points->SetPoint(v, points(v, 0), points(v, 1), points(v, 2));
    vtkNew<vtkCellArray> triangles;
    triangles->AllocateExact(faces.rows(), 3 * faces.rows());
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
        const vtkIdType ids[3] = {faces(f, 0), faces(f, 1), faces(f, 2)};
        triangles->InsertNextCell(3, ids);
    }
    auto surface = vtkSmartPointer<vtkPolyData>::New();
    surface->SetPoints(vtk_points);
    surface->SetPolys(triangles);
    return surface;
}

}  // namespace sa
