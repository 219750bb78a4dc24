#pragma once
// `sa param`: a planar parameterization of a disk-topology surface (sections 5.1 and 5.2), and
// `sa subdivide`: Loop subdivision, to build large test meshes.

#include <string>

#include "optim/types.h"

namespace sa::cli {

struct ParamArguments {
    std::string mesh, init = "lscm", distortion = "conformal", bound = "inf", energy = "difference";
    std::string out, layout, png, report, mode = "auto";
    double mu = 1000.0;
    int optimal_bound_rounds = 0, threads = 0, max_iterations = 200;
    double max_time = kInfinity, optimal_bound_tolerance = 5e-3;
    bool optimal_bound = false, free_boundary_injective = false, force = false, quiet = false;
    bool no_fallback = false, no_png = false;
};

/// 0 for a verified parameterization (inversion-free, within the bound, and with the boundary
/// barrier every boundary angle sum below 2 pi).
int run_param_command(const ParamArguments& arguments);

struct SubdivideArguments {
    std::string mesh, out;
    int levels = 1;
    bool force = false;
};

int run_subdivide_command(const SubdivideArguments& arguments);

}  // namespace sa::cli
