// The `sa` command: inversion-free mappings by Simplex Assembly.
//   sa map  ...   a mesh, an initial map and handles -> a verified inversion-free map
//   sa demo ...   the paper's Figure 1 in miniature
//   sa param ...  a planar parameterization of a disk-topology surface
//   sa seamless   a seamless parameterization from a frame field (integrable by Simplex Assembly)
//   sa subdivide  Loop subdivision (to build large test meshes)
// Exit status: 0 verified success, 1 a result that did not pass verification or a problem whose
// handles rule out any solution (geometry/handle_feasibility.h), 2 bad input.
#include <CLI/CLI.hpp>
#include <iostream>

#include "frontends/cli/demo_command.h"
#include "frontends/cli/map_command.h"
#include "frontends/cli/param_command.h"
#include "frontends/cli/runtime_settings.h"
#include "frontends/cli/seamless_command.h"
#include "geometry/handle_feasibility.h"
#include "optim/errors.h"

int main(int argc, char** argv) {
    sa::cli::apply_runtime_settings();
    CLI::App app{"sa: inversion-free mappings by Simplex Assembly (Fu and Liu 2016)"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "sa 0.1.0");
    sa::cli::MapArguments map_arguments;
    sa::cli::DemoArguments demo_arguments;
    CLI::App* map = sa::cli::add_map_command(app, map_arguments);
    CLI::App* demo = sa::cli::add_demo_command(app, demo_arguments);
    sa::cli::ParamArguments param_arguments;
    CLI::App* param = sa::cli::add_param_command(app, param_arguments);
    sa::cli::SeamlessArguments seamless_arguments;
    CLI::App* seamless = sa::cli::add_seamless_command(app, seamless_arguments);
    sa::cli::SubdivideArguments subdivide_arguments;
    CLI::App* subdivide = sa::cli::add_subdivide_command(app, subdivide_arguments);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? 0 : 2;
    }
    try {
        if (map->parsed()) return sa::cli::run_map_command(map_arguments);
        if (demo->parsed()) return sa::cli::run_demo_command(demo_arguments);
        if (param->parsed()) return sa::cli::run_param_command(param_arguments);
        if (seamless->parsed()) return sa::cli::run_seamless_command(seamless_arguments);
        if (subdivide->parsed()) return sa::cli::run_subdivide_command(subdivide_arguments);
    } catch (const sa::InfeasibleProblemError& e) {
        // A problem with no solution as posed: diagnosed, nothing optimized (exit 1, not 2).
        std::cerr << "sa: " << e.what() << '\n';
        return 1;
    } catch (const sa::Error& e) {
        std::cerr << "sa: error: " << e.what() << '\n';
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "sa: internal error: " << e.what() << '\n';
        return 3;
    }
    return 2;
}
