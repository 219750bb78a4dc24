#pragma once
// `sa map`: an inversion-free map by Simplex Assembly from a rest mesh, an initial map and
// handles; writes the result, a picture of it (frontends/output/map_picture.h), a JSON report
// and, optionally, the iterations for ParaView.

#include <memory>
#include <string>

#include "frontends/simplex_assembly/map_options.h"

namespace sa::cli {

struct MapArguments {
    std::string rest, init, handles, targets, out, report, record, png;
    std::string distortion = "conformal", energy = "none", variant = "r", initialization;
    std::string bound = "inf", projection = "clamp", mode = "auto", linear_solver = "auto";
    int rings = 4, max_rings = 20, max_rounds = 2;
    double translation_shift = 0.0;
    double mu = 1000.0, s = 1.0, lambda_max = 1e16;
    int max_iterations = 200, threads = 0;
    double max_time = kInfinity;
    std::uint64_t seed = 1;
    bool force = false, quiet = false, no_vertex_stage = false, until_valid = false;
    bool no_png = false;
};

/// Adds the subcommand to `app`; `arguments` is filled when it is parsed.
/// Runs it: 0 for a verified success, 1 when the result did not pass verification. Bad input
/// throws (InputError, InvalidArgumentError) before any output is written.
int run_map_command(const MapArguments& arguments);

/// Parses "inf" or a number > 1.
double parse_bound(const std::string& text);

}  // namespace sa::cli
