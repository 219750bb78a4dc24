#pragma once
// `sa seamless`: a seamless parameterization of a surface from a frame field, made integrable by
// Simplex Assembly (the paper's 5.2, "Global seamless parameterizations").

#include <string>
#include <vector>

#include "optim/types.h"

namespace sa::cli {

struct SeamlessArguments {
    std::string mesh, field, out, vtu, png, report;
    std::vector<std::string> constraints;  ///< libigl's _b.dmat and _bc.dmat
    double scale = 0.0, mu = 1000.0;
    int threads = 0, max_iterations = 200;
    double max_time = kInfinity;
    bool no_vtu = false, no_png = false, force = false, quiet = false;
};

/// 0 for a verified seamless map (seamless_parameterization.h), 1 otherwise.
int run_seamless_command(const SeamlessArguments& arguments);

}  // namespace sa::cli
