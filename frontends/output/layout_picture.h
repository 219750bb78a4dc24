#pragma once
// A PNG of flat triangle layouts (UV maps) coloured by a per-face value, with a colour bar: the
// picture a user looks at first, without ParaView. Drawn with Cairo (no display needed).
// Faces flagged `inverted` are drawn in red whatever their value.
//
// Each layout is drawn in a panel whose aspect ratio is that of the layouts' bounding boxes
// (clamped to [1/4, 4]); each is scaled to fill its panel and centred in it, so that a long
// layout fills the picture rather than a strip of a square. Several layouts (say, a map before
// and after) sit side by side, each with its caption, sharing the colour bar.

#include <Eigen/Core>
#include <string>
#include <vector>

namespace sa {

struct LayoutPicture {
    std::string title;       ///< a line at the top (shrunk to fit the picture's width)
    std::string value_name;  ///< the colour bar's label
    double low = 1.0;        ///< values at or below: the first colour
    double high = 2.0;       ///< values at or above: the last colour
    int size = 1600;         ///< the longer side of each layout's panel, in pixels, in [16, 8192]
};

/// One layout of the picture: `uv` #V x 2, `values` one per face, `inverted` empty or one flag
/// per face, `caption` a line above the panel (empty for none).
struct LayoutPanel {
    std::string caption;
    Eigen::MatrixXd uv;
    Eigen::VectorXd values;
    std::vector<unsigned char> inverted;
};

/// `uv` #V x 2, `faces` #F x 3, `values` one per face; `inverted` (optional) one flag per face.
/// Throws InvalidArgumentError on inconsistent shapes, InputError when the file cannot be written.
void write_layout_png(const std::string& path, const Eigen::MatrixXd& uv,
                      const Eigen::MatrixXi& faces, const Eigen::VectorXd& values,
                      const LayoutPicture& picture,
                      const std::vector<unsigned char>& inverted = {});

/// The panels side by side, left to right, over the same `faces` (#F x 3); as write_layout_png.
void write_layouts_png(const std::string& path, const Eigen::MatrixXi& faces,
                       const std::vector<LayoutPanel>& panels, const LayoutPicture& picture);

}  // namespace sa
