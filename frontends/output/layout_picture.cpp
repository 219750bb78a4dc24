#include "frontends/output/picture_plugin.h"

#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "frontends/output/colour_map.h"
#include "geometry/io/atomic_file.h"
#include "optim/errors.h"

namespace sa {

void write_layout_png_impl(const std::string& path, const Eigen::MatrixXd& uv,
                           const Eigen::MatrixXi& faces, const Eigen::VectorXd& values,
                           const LayoutPicture& picture,
                           const std::vector<unsigned char>& inverted) {
    if (uv.cols() < 2 || faces.cols() != 3 || values.size() != faces.rows()) {
        throw InvalidArgumentError(
            "write_layout_png: expected #V x 2 positions, #F x 3 faces and #F values");
    }
    const int margin = 40, bar = 140, title = 60;
    const int width = picture.size + 2 * margin + bar, height = picture.size + 2 * margin + title;
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
    cairo_t* cr = cairo_create(surface);
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_paint(cr);

    // Fit the layout in the square, keeping its aspect ratio; y grows upwards.
    const Eigen::RowVector2d lo = uv.leftCols(2).colwise().minCoeff(),
                             hi = uv.leftCols(2).colwise().maxCoeff();
    const double extent = std::max(hi[0] - lo[0], hi[1] - lo[1]);
    const double scale = extent > 0.0 ? picture.size / extent : 1.0;
    auto to_pixel = [&](Eigen::Index v) {
        return std::pair<double, double>{
            margin + (uv(v, 0) - lo[0]) * scale,
            title + margin + picture.size - (uv(v, 1) - lo[1]) * scale};
    };
    const bool edges = faces.rows() <= 20000;
    cairo_set_antialias(cr, edges ? CAIRO_ANTIALIAS_DEFAULT : CAIRO_ANTIALIAS_NONE);
    cairo_set_line_width(cr, 0.4);
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const auto [x, y] = to_pixel(faces(f, k));
            k == 0 ? cairo_move_to(cr, x, y) : cairo_line_to(cr, x, y);
        }
        cairo_close_path(cr);
        if (!inverted.empty() && inverted[f]) {
            cairo_set_source_rgb(cr, 0.9, 0.1, 0.1);
        } else {
            const double t = picture.high > picture.low
                                 ? (values[f] - picture.low) / (picture.high - picture.low)
                                 : 0.0;
            const auto c = viridis(std::isfinite(values[f]) ? t : 1.0);
            cairo_set_source_rgb(cr, c[0], c[1], c[2]);
        }
        if (edges) {
            cairo_fill_preserve(cr);
            cairo_set_source_rgba(cr, 0.0, 0.0, 0.0, 0.35);
            cairo_stroke(cr);
        } else {
            cairo_fill(cr);
        }
    }

    // The colour bar and the text.
    const double bx = margin + picture.size + 40, by = title + margin, bh = picture.size * 0.6;
    for (int i = 0; i < 256; ++i) {
        const auto c = viridis(1.0 - i / 255.0);
        cairo_set_source_rgb(cr, c[0], c[1], c[2]);
        cairo_rectangle(cr, bx, by + bh * i / 256.0, 30, bh / 256.0 + 1.0);
        cairo_fill(cr);
    }
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 16);
    char label[64];
    std::snprintf(label, sizeof label, "%.3g", picture.high);
    cairo_move_to(cr, bx + 36, by + 12);
    cairo_show_text(cr, label);
    std::snprintf(label, sizeof label, "%.3g", picture.low);
    cairo_move_to(cr, bx + 36, by + bh);
    cairo_show_text(cr, label);
    cairo_save(cr);
    cairo_move_to(cr, bx - 8, by + bh);
    cairo_rotate(cr, -M_PI / 2);
    cairo_show_text(cr, picture.value_name.c_str());
    cairo_restore(cr);
    if (!inverted.empty()) {
        cairo_set_source_rgb(cr, 0.9, 0.1, 0.1);
        cairo_rectangle(cr, bx, by + bh + 30, 30, 16);
        cairo_fill(cr);
        cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
        cairo_move_to(cr, bx + 36, by + bh + 44);
        cairo_show_text(cr, "inverted");
    }
    cairo_set_font_size(cr, 20);
    cairo_move_to(cr, margin, 38);
    cairo_show_text(cr, picture.title.c_str());
    cairo_destroy(cr);
    cairo_surface_flush(surface);

    AtomicFile file(path, true);
    const cairo_status_t status =
        cairo_surface_write_to_png(surface, file.temporary_path().c_str());
    cairo_surface_destroy(surface);
    if (status != CAIRO_STATUS_SUCCESS) {
        throw InputError(path + ": cannot write the picture (" + cairo_status_to_string(status) +
                         ")");
    }
    file.commit();
}

}  // namespace sa
