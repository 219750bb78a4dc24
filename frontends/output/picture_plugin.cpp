#include "frontends/output/picture_plugin.h"

extern "C" const sa::PictureFunctions* sa_picture_functions() {
    static const sa::PictureFunctions table{sa::write_checkerboard_png_impl,
                                            sa::write_layouts_png_impl,
                                            sa::write_surface_value_png_impl};
    return &table;
}
