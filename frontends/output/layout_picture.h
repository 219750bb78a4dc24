#pragma once
// A PNG of a flat triangle layout (a UV map) coloured by a per-face value, with a colour bar: the
// picture a user looks at first, without ParaView. Drawn with Cairo (no display needed).
// Faces flagged `inverted` are drawn in red whatever their value.

#include <Eigen/Core>
#include <string>
#include <vector>

namespace sa {

struct LayoutPicture {
    std::string title;       ///< a line at the top
    std::string value_name;  ///< the colour bar's label
    double low = 1.0;        ///< values at or below: the first colour
    double high = 2.0;       ///< values at or above: the last colour
    int size = 1600;         ///< the layout's square, in pixels
};

/// `uv` #V x 2, `faces` #F x 3, `values` one per face; `inverted` (optional) one flag per face.
void write_layout_png(const std::string& path, const Eigen::MatrixXd& uv,
                      const Eigen::MatrixXi& faces, const Eigen::VectorXd& values,
                      const LayoutPicture& picture,
                      const std::vector<unsigned char>& inverted = {});

}  // namespace sa
