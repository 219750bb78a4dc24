#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "frontends/output/colour_map.h"
#include "frontends/output/picture_plugin.h"
#include "geometry/io/atomic_file.h"
#include "optim/errors.h"

namespace sa {

namespace {

void check_panels(const Eigen::MatrixXi& faces, const std::vector<LayoutPanel>& panels,
                  const LayoutPicture& picture) {
    const std::string where = "write_layout_png: ";
    if (panels.empty()) throw InvalidArgumentError(where + "no layout to draw");
    if (faces.cols() != 3) throw InvalidArgumentError(where + "faces must be #F x 3");
    if (picture.size < 16 || picture.size > 8192) {
        throw InvalidArgumentError(where + "picture size " + std::to_string(picture.size) +
                                   " outside [16, 8192]");
    }
    for (const LayoutPanel& p : panels) {
        if (p.uv.cols() < 2 || p.uv.rows() == 0 || p.values.size() != faces.rows() ||
            (!p.inverted.empty() && Eigen::Index(p.inverted.size()) != faces.rows())) {
            throw InvalidArgumentError(
                where + "expected #V x 2 positions, #F x 3 faces, #F values and #F flags or none");
        }
        if (faces.size() > 0 && (faces.minCoeff() < 0 || faces.maxCoeff() >= p.uv.rows())) {
            throw InvalidArgumentError(where + "a face has a vertex index outside [0, " +
                                       std::to_string(p.uv.rows()) + ")");
        }
        if (!p.uv.leftCols(2).allFinite())
            throw InvalidArgumentError(where + "a position is not finite");
    }
}

/// Shows `text` at (x, y) in at most `size` points, smaller when it would be wider than `width`.
void show_text_within(cairo_t* cr, const std::string& text, double x, double y, double size,
                      double width) {
    cairo_set_font_size(cr, size);
    cairo_text_extents_t extents;
    cairo_text_extents(cr, text.c_str(), &extents);
    if (extents.x_advance > width && extents.x_advance > 0.0)
        cairo_set_font_size(cr, std::max(6.0, size * width / extents.x_advance));
    cairo_move_to(cr, x, y);
    cairo_show_text(cr, text.c_str());
}

}  // namespace

void write_layouts_png_impl(const std::string& path, const Eigen::MatrixXi& faces,
                            const std::vector<LayoutPanel>& panels, const LayoutPicture& picture) {
    check_panels(faces, panels, picture);
    // The panels' aspect ratio: that of the largest extents, so that each layout fills its panel.
    double extent_x = 0.0, extent_y = 0.0;
    for (const LayoutPanel& p : panels) {
        const Eigen::RowVector2d span =
            p.uv.leftCols(2).colwise().maxCoeff() - p.uv.leftCols(2).colwise().minCoeff();
        extent_x = std::max(extent_x, span[0]);
        extent_y = std::max(extent_y, span[1]);
    }
    const double aspect =
        extent_y > 0.0 ? std::clamp(extent_x / extent_y, 0.25, 4.0) : (extent_x > 0.0 ? 4.0 : 1.0);
    const int panel_w = aspect >= 1.0 ? picture.size : int(std::lround(picture.size * aspect));
    const int panel_h = aspect >= 1.0 ? int(std::lround(picture.size / aspect)) : picture.size;

    const int margin = 40, bar = 140, title = 60, gap = 40;
    bool captions = false;
    for (const LayoutPanel& p : panels) captions = captions || !p.caption.empty();
    const int caption = captions ? 34 : 0;
    bool any_inverted = false;
    for (const LayoutPanel& p : panels)
        any_inverted =
            any_inverted || std::find(p.inverted.begin(), p.inverted.end(), 1) != p.inverted.end();
    const int n = int(panels.size());
    const int width = margin + n * panel_w + (n - 1) * gap + margin + bar;

    // The measuring surface: the colour bar is at least as tall as its label.
    cairo_surface_t* probe = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1);
    cairo_t* measure = cairo_create(probe);
    cairo_select_font_face(measure, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                           CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(measure, 16);
    cairo_text_extents_t label_extents;
    cairo_text_extents(measure, picture.value_name.c_str(), &label_extents);
    cairo_destroy(measure);
    cairo_surface_destroy(probe);
    const double bh = std::max({0.6 * panel_h, label_extents.x_advance + 20.0, 160.0});
    const int legend = any_inverted ? 60 : 0;
    const int height = std::max(title + caption + panel_h + 2 * margin,
                                int(std::ceil(title + margin + bh + legend + margin)));
    // The panels are centred vertically below the title.
    const double panel_top =
        title + caption + margin + 0.5 * (height - (title + caption + panel_h + 2 * margin));

    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
    cairo_t* cr = cairo_create(surface);
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_paint(cr);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);

    const bool edges = faces.rows() <= 20000;
    for (int k = 0; k < n; ++k) {
        const LayoutPanel& p = panels[k];
        const double left = margin + k * (panel_w + gap);
        // Scale the layout to fill the panel, keeping its aspect ratio, centred; y grows upwards.
        const Eigen::RowVector2d lo = p.uv.leftCols(2).colwise().minCoeff(),
                                 hi = p.uv.leftCols(2).colwise().maxCoeff();
        const double ex = hi[0] - lo[0], ey = hi[1] - lo[1];
        // A point or a segment: as large as the other side allows (a point: any scale).
        const double s = ex > 0.0 && ey > 0.0 ? std::min(panel_w / ex, panel_h / ey)
                         : ex > 0.0           ? panel_w / ex
                         : ey > 0.0           ? panel_h / ey
                                              : 1.0;
        const double ox = left + 0.5 * (panel_w - ex * s),
                     oy = panel_top + panel_h - 0.5 * (panel_h - ey * s);
        auto to_pixel = [&](Eigen::Index v) {
            return std::pair<double, double>{ox + (p.uv(v, 0) - lo[0]) * s,
                                             oy - (p.uv(v, 1) - lo[1]) * s};
        };
        cairo_set_antialias(cr, edges ? CAIRO_ANTIALIAS_DEFAULT : CAIRO_ANTIALIAS_NONE);
        cairo_set_line_width(cr, 0.4);
        // The inverted faces last, so that the faces over them do not hide them.
        for (int pass = 0; pass < 2; ++pass) {
            for (Eigen::Index f = 0; f < faces.rows(); ++f) {
                const bool red = !p.inverted.empty() && p.inverted[f];
                if (red != (pass == 1)) continue;
                for (int c = 0; c < 3; ++c) {
                    const auto [x, y] = to_pixel(faces(f, c));
                    c == 0 ? cairo_move_to(cr, x, y) : cairo_line_to(cr, x, y);
                }
                cairo_close_path(cr);
                if (red) {
                    cairo_set_source_rgb(cr, 0.9, 0.1, 0.1);
                } else {
                    const double t = picture.high > picture.low ? (p.values[f] - picture.low) /
                                                                      (picture.high - picture.low)
                                                                : 0.0;
                    const auto colour = viridis(std::isfinite(p.values[f]) ? t : 1.0);
                    cairo_set_source_rgb(cr, colour[0], colour[1], colour[2]);
                }
                if (edges) {
                    cairo_fill_preserve(cr);
                    cairo_set_source_rgba(cr, 0.0, 0.0, 0.0, 0.35);
                    cairo_stroke(cr);
                } else {
                    cairo_fill(cr);
                }
            }
        }
        if (!p.caption.empty()) {
            cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
            cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
            show_text_within(cr, p.caption, left, panel_top - 14, 18, panel_w);
        }
    }

    // The colour bar and the text.
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
    const double bx = width - bar + 40 - margin, by = title + margin;
    for (int i = 0; i < 256; ++i) {
        const auto c = viridis(1.0 - i / 255.0);
        cairo_set_source_rgb(cr, c[0], c[1], c[2]);
        cairo_rectangle(cr, bx, by + bh * i / 256.0, 30, bh / 256.0 + 1.0);
        cairo_fill(cr);
    }
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
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
    if (any_inverted) {
        cairo_set_source_rgb(cr, 0.9, 0.1, 0.1);
        cairo_rectangle(cr, bx, by + bh + 30, 30, 16);
        cairo_fill(cr);
        cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
        cairo_move_to(cr, bx + 36, by + bh + 44);
        cairo_show_text(cr, "inverted");
    }
    show_text_within(cr, picture.title, margin, 38, 20, width - 2 * margin);
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
