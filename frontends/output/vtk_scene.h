#pragma once
// Internal to the picture plugin (libsa_pictures.so): rendering a VTK scene of a surface in space
// to a PNG, shared by the pictures of surfaces (checkerboard_picture.h, surface_value_picture.h).
//
// The caller builds the renderer's actors; render_scene_png() adds the title at the top, turns
// the camera (from the view down -z with +y up: `azimuth` about the view-up axis, then
// `elevation` upwards, in degrees), fits it so that `points` fill the picture below the title
// with a margin (left of `right`), renders off screen on an X display (XDisplay: DISPLAY or a
// private Xvfb) and writes the PNG under a temporary name, renamed into place. Calls are serialized
// by a process-wide lock; VTK's messages are captured and the first one is reported in the
// exception when the picture cannot be made.

#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <Eigen/Core>
#include <array>
#include <string>

namespace sa {

struct SceneView {
    std::string title;
    int width = 1600;
    int height = 1200;
    double azimuth = 30.0;
    double elevation = 25.0;
    /// The scene's right edge in normalized device coordinates (-1 left, 1 right): less than 1
    /// leaves room on the right, for a colour bar.
    double right = 1.0;
};

/// The view of a picture's settings (any struct with these fields).
template <class Picture>
SceneView scene_view(const Picture& picture) {
    SceneView view;
    view.title = picture.title;
    view.width = picture.width;
    view.height = picture.height;
    view.azimuth = picture.azimuth;
    view.elevation = picture.elevation;
    return view;
}

/// A surface of `faces` (#F x 3 rows into `points`, #V x 3) as VTK points (double) and triangle
/// cells in the order of `faces`; the caller adds its point or cell data.
vtkSmartPointer<vtkPolyData> triangle_surface(const Eigen::MatrixXd& points,
                                              const Eigen::MatrixXi& faces);

/// `points` #V x 3: what the camera must show. Throws InputError (messages start with `who`)
/// when there is no display or the picture cannot be rendered or written.
void render_scene_png(const std::string& path, vtkRenderer* renderer, const Eigen::MatrixXd& points,
                      const SceneView& view, const std::string& who);

}  // namespace sa
