#pragma once
// The picture writers live in the plugin libsa_pictures.so (checkerboard_picture.cpp and
// surface_value_picture.cpp with VTK's OpenGL rendering and X11, layout_picture.cpp with Cairo),
// loaded on the first picture (geometry/io/plugin_library.h); pictures.cpp forwards the functions
// of checkerboard_picture.h, layout_picture.h and surface_value_picture.h to this table
// (write_layout_png as write_layouts_png with one panel).

#include "frontends/output/checkerboard_picture.h"
#include "frontends/output/layout_picture.h"
#include "frontends/output/surface_value_picture.h"

namespace sa {

struct PictureFunctions {
    decltype(&sa::write_checkerboard_png) write_checkerboard_png;
    decltype(&sa::write_layouts_png) write_layouts_png;
    decltype(&sa::write_surface_value_png) write_surface_value_png;
};

// The implementations inside the plugin, with the contracts of the public functions.
void write_checkerboard_png_impl(const std::string& path, const Eigen::MatrixXd& positions,
                                 const Eigen::MatrixXi& faces, const Eigen::MatrixXd& uv,
                                 const CheckerboardPicture& picture);
void write_layouts_png_impl(const std::string& path, const Eigen::MatrixXi& faces,
                            const std::vector<LayoutPanel>& panels, const LayoutPicture& picture);
void write_surface_value_png_impl(const std::string& path, const Eigen::MatrixXd& positions,
                                  const Eigen::MatrixXi& faces, const Eigen::VectorXd& values,
                                  const SurfaceValuePicture& picture,
                                  const std::vector<unsigned char>& flagged);

}  // namespace sa

/// The plugin's entry point: a table valid for the life of the process.
extern "C" const sa::PictureFunctions* sa_picture_functions();
