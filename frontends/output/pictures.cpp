// The public picture functions, forwarded to the plugin libsa_pictures.so (picture_plugin.h).
#include "frontends/output/picture_plugin.h"
#include "geometry/io/plugin_library.h"

namespace sa {

namespace {

const PictureFunctions& pictures() {
    return plugin_table<PictureFunctions>("sa_pictures", "sa_picture_functions",
                                          "writing PNG pictures");
}

}  // namespace

void write_checkerboard_png(const std::string& path, const Eigen::MatrixXd& positions,
                            const Eigen::MatrixXi& faces, const Eigen::MatrixXd& uv,
                            const CheckerboardPicture& picture) {
    pictures().write_checkerboard_png(path, positions, faces, uv, picture);
}

void write_layout_png(const std::string& path, const Eigen::MatrixXd& uv,
                      const Eigen::MatrixXi& faces, const Eigen::VectorXd& values,
                      const LayoutPicture& picture, const std::vector<unsigned char>& inverted) {
    pictures().write_layouts_png(path, faces, {LayoutPanel{"", uv, values, inverted}}, picture);
}

void write_layouts_png(const std::string& path, const Eigen::MatrixXi& faces,
                       const std::vector<LayoutPanel>& panels, const LayoutPicture& picture) {
    pictures().write_layouts_png(path, faces, panels, picture);
}

void write_surface_value_png(const std::string& path, const Eigen::MatrixXd& positions,
                             const Eigen::MatrixXi& faces, const Eigen::VectorXd& values,
                             const SurfaceValuePicture& picture,
                             const std::vector<unsigned char>& flagged) {
    pictures().write_surface_value_png(path, positions, faces, values, picture, flagged);
}

}  // namespace sa
