#pragma once
// `sa demo`: the paper's Figure 1 in miniature. A square grid's boundary goes onto a non-convex
// eight-pointed star, the interior follows by a harmonic map (which folds near the reflex
// corners), and Simplex Assembly repairs it with K_conf = inf and with K_conf = 4 (E_m = 0).
// Writes the three maps as .vtu files, a picture of each beside it (.png: the layout coloured by
// conformal distortion, foldovers in red) and prints foldovers, distortion and time.

#include <string>

namespace sa::cli {

struct DemoArguments {
    std::string out_dir = "sa-demo";
    int size = 24;
    int threads = 0;
    std::string initialization;  ///< the disassembly's projection; empty: the default
    bool force = false, quiet = false, no_png = false;
};

/// 0 when both maps are verified inversion-free.
int run_demo_command(const DemoArguments& arguments);

}  // namespace sa::cli
