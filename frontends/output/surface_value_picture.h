#pragma once
// A PNG of a triangle surface in space coloured by a per-face value (viridis, with a colour bar),
// flat-shaded under a headlight, the camera fitted from an oblique view: a PolyCube's surface
// coloured by the conformal distortion of the tetrahedra under it, say. Faces flagged (inverted
// tetrahedra) are drawn in red whatever their value.
//
// Rendered with VTK as the checkerboard pictures are (frontends/output/vtk_scene.h): off screen
// on DISPLAY or a private Xvfb, serialized, written atomically.

#include <Eigen/Core>
#include <string>
#include <vector>

namespace sa {

struct SurfaceValuePicture {
    std::string title;       ///< a line of text at the top; empty for none
    std::string value_name;  ///< the colour bar's label
    double low = 1.0;        ///< values at or below: the first colour
    double high = 2.0;       ///< values at or above: the last colour
    int width = 1600;        ///< pixels, in [16, 8192]
    int height = 1200;
    double azimuth = 30.0;  ///< degrees (vtk_scene.h)
    double elevation = 25.0;
    /// Opacity of the faces not flagged, in (0, 1]: below 1, flagged faces behind them show
    /// through (the faces of inverted tetrahedra inside a volume).
    double opacity = 1.0;
};

/// Writes `path` (PNG). `positions` #V x 3, `faces` #F x 3 (0-based, counter-clockwise seen from
/// outside), `values` one per face (non-finite values take the last colour), `flagged` empty or
/// one per face. Throws InvalidArgumentError on inconsistent shapes, an index out of range, a
/// non-finite position or an invalid picture field; InputError when there is no X display and no
/// Xvfb, or the file cannot be written.
void write_surface_value_png(const std::string& path, const Eigen::MatrixXd& positions,
                             const Eigen::MatrixXi& faces, const Eigen::VectorXd& values,
                             const SurfaceValuePicture& picture,
                             const std::vector<unsigned char>& flagged = {});

}  // namespace sa
