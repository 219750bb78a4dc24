#pragma once
// A PNG of a triangle surface in space textured with a checkerboard of its per-vertex (u, v)
// coordinates: the picture a user looks at first after a seamless parameterization. One unit of
// u or v is one square, so a good map shows squares of even size with right angles, and seams
// across which the squares line up. Rendered with VTK (OpenGL): smooth shading under a
// headlight, the camera fitted to the mesh from an oblique view, the title at the top.
//
// Display: rendered off screen (no window appears) on DISPLAY when it is usable, otherwise on a
// private Xvfb started for the duration of the call and stopped before returning, also when an
// exception is thrown (XDisplay, frontends/output/x_display.h). With neither a display nor Xvfb,
// InputError. Calls are serialized by a process-wide lock. Nothing is printed: VTK's messages
// during the call are captured (VtkCapture, geometry/io/vtk_capture.h), and the first one is
// reported in the exception when the picture cannot be made.

#include <Eigen/Core>
#include <array>
#include <string>

namespace sa {

struct CheckerboardPicture {
    std::string title;  ///< a line of text at the top; empty for none
    int width = 1600;   ///< pixels, in [16, 8192]
    int height = 1200;  ///< pixels, in [16, 8192]
    /// The view, in degrees: starting from the view down -z with +y up, the camera turns by
    /// `azimuth` about the view-up axis, then by `elevation` upwards; then it is fitted so that
    /// the mesh fills the picture with a margin.
    double azimuth = 30.0;
    double elevation = 25.0;
    /// Square colours, RGB in [0, 1], before lighting.
    std::array<double, 3> light_colour{0.97, 0.91, 0.78};
    std::array<double, 3> dark_colour{0.27, 0.43, 0.68};
    bool lines = true;  ///< thin darker lines along the squares' edges
    std::array<double, 3> background{1.0, 1.0, 1.0};
};

/// Writes `path` (PNG, picture.width x picture.height, RGB).
/// `positions` #V x 3 (or #V x 2, z = 0): vertices in space. `faces` #F x 3: 0-based vertex
/// indices, counter-clockwise seen from outside. `uv` #V x 2: texture coordinates per vertex of
/// the cut mesh (seam vertices duplicated by the caller); one unit is one checkerboard square.
/// Normals for shading are averaged over vertices at the same position, so seams do not show
/// in the shading. Written under a temporary name in the same folder, then renamed: nothing is
/// left at `path` on failure. Throws InvalidArgumentError on inconsistent shapes, an index out
/// of range, a non-finite value or an invalid picture field; InputError when there is no X
/// display and no Xvfb, or the file cannot be written.
void write_checkerboard_png(const std::string& path, const Eigen::MatrixXd& positions,
                            const Eigen::MatrixXi& faces, const Eigen::MatrixXd& uv,
                            const CheckerboardPicture& picture);

}  // namespace sa
