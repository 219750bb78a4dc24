// The `sa` command: inversion-free mappings by Simplex Assembly.
//   sa map  ...   a mesh, an initial map and handles -> a verified inversion-free map
//   sa demo ...   the paper's Figure 1 in miniature
//   sa param ...  a planar parameterization of a disk-topology surface
//   sa seamless   a seamless parameterization from a frame field (integrable by Simplex Assembly)
//   sa polycube   a PolyCube map of a tetrahedral mesh with a labelled boundary
//   sa hex        a hexahedral mesh of a tetrahedral mesh, through its PolyCube map
//   sa deform     a pose of a tet mesh (or planar triangles) from its handles' targets alone
//   sa subdivide  Loop subdivision (to build large test meshes)
// Exit status (cli_support.h, README.md): 0 verified success, 1 a result that did not pass
// verification or a problem whose handles rule out any solution
// (geometry/quality/handle_feasibility.h), 2 bad input, 3 internal error, 4 out of memory; killed
// by SIGINT, SIGTERM, SIGHUP or SIGPIPE after removing the run's outputs (interruption.h). Every
// error is one line on stderr.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <iostream>
#include <new>
#include <system_error>

#include "frontends/cli/cli_support.h"
#include "frontends/cli/command_options.h"
#include "frontends/cli/deform_command.h"
#include "frontends/cli/demo_command.h"
#include "frontends/cli/hex_command.h"
#include "frontends/cli/interruption.h"
#include "frontends/cli/map_command.h"
#include "frontends/cli/out_of_memory.h"
#include "frontends/cli/output_plan.h"
#include "frontends/cli/param_command.h"
#include "frontends/cli/polycube_command.h"
#include "frontends/cli/runtime_settings.h"
#include "frontends/cli/seamless_command.h"
#include "geometry/quality/handle_feasibility.h"
#include "optim/errors.h"

namespace {

/// One line on stderr, in one write: a reader that goes away sees all of it or none.
int report(const char* kind, const std::string& message, int status) {
    std::cerr << ("sa: " + std::string(kind) + ": " + sa::cli::one_line(message) + '\n')
              << std::flush;
    return status;
}

std::vector<CLI::App*> all_commands(CLI::App& app) {
    return app.get_subcommands([](CLI::App*) { return true; });
}

/// "map, demo, param, seamless or subdivide".
std::string command_list(CLI::App& app) {
    std::string list;
    const std::vector<CLI::App*> commands = all_commands(app);
    for (std::size_t i = 0; i < commands.size(); ++i) {
        if (i > 0) list += i + 1 == commands.size() ? " or " : ", ";
        list += commands[i]->get_name();
    }
    return list;
}

/// The summary went to stdout: a write error there (a full disk, /dev/full) is an error too,
/// unless the run failed already (its one line said why). OutputPlan::commit() writes the
/// summary before the outputs are in place; this catches what a command printed after.
int check_standard_output(int status) {
    if (status != sa::cli::kExitVerified && status != sa::cli::kExitNotVerified) return status;
    try {
        sa::cli::flush_standard_output();
    } catch (const sa::Error& e) {
        return report("error", e.what(), sa::cli::kExitBadInput);
    }
    return status;
}

int run(int argc, char** argv) {
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
    sa::cli::PolycubeArguments polycube_arguments;
    CLI::App* polycube = sa::cli::add_polycube_command(app, polycube_arguments);
    sa::cli::HexArguments hex_arguments;
    CLI::App* hex = sa::cli::add_hex_command(app, hex_arguments);
    sa::cli::DeformArguments deform_arguments;
    CLI::App* deform = sa::cli::add_deform_command(app, deform_arguments);
    sa::cli::SubdivideArguments subdivide_arguments;
    CLI::App* subdivide = sa::cli::add_subdivide_command(app, subdivide_arguments);

    // A first word that is no command is an error even with --help after it (CLI11 would print
    // the main help and succeed), and with no word at all.
    if (argc < 2) {
        return report("error", "a command is required: " + command_list(app) + " (sa --help)",
                      sa::cli::kExitBadInput);
    }
    const std::string first = argv[1];
    const std::vector<CLI::App*> commands = all_commands(app);
    const bool known = std::any_of(commands.begin(), commands.end(),
                                   [&](CLI::App* c) { return c->check_name(first); });
    if (!first.empty() && first[0] != '-' && !known) {
        return report("error",
                      "unknown command '" + first + "' (expected " + command_list(app) + ")",
                      sa::cli::kExitBadInput);
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {  // --help, --version
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        return report("error", e.what(), sa::cli::kExitBadInput);
    }

    try {
        // Every command that solves, in this one place (a command added later cannot forget it):
        // under a memory limit OpenBLAS's work buffer is taken now, or the run ends with exit 4.
        if (!subdivide->parsed()) sa::cli::reserve_blas_buffer();
        if (map->parsed()) return sa::cli::run_map_command(map_arguments);
        if (demo->parsed()) return sa::cli::run_demo_command(demo_arguments);
        if (param->parsed()) return sa::cli::run_param_command(param_arguments);
        if (seamless->parsed()) return sa::cli::run_seamless_command(seamless_arguments);
        if (polycube->parsed()) return sa::cli::run_polycube_command(polycube_arguments);
        if (hex->parsed()) return sa::cli::run_hex_command(hex_arguments);
        if (deform->parsed()) return sa::cli::run_deform_command(deform_arguments);
        if (subdivide->parsed()) return sa::cli::run_subdivide_command(subdivide_arguments);
    } catch (const std::bad_alloc&) {
        return report("error", sa::cli::out_of_memory_message(), sa::cli::kExitOutOfMemory);
    } catch (const sa::NoSolutionError& e) {
        // A problem with no solution as posed: diagnosed, nothing optimized (exit 1, not 2).
        std::cerr << ("sa: " + sa::cli::one_line(e.what()) + '\n') << std::flush;
        return sa::cli::kExitNotVerified;
    } catch (const sa::Error& e) {
        return report("error", e.what(), sa::cli::kExitBadInput);
    } catch (const std::system_error& e) {
        // A thread that cannot start for lack of address space (TBB's, with 8 MB stacks).
        const int code = e.code().value();
        if (e.code().category() == std::generic_category() && (code == EAGAIN || code == ENOMEM) &&
            sa::cli::memory_limit() > 0) {
            return report("error", sa::cli::out_of_memory_message() + " (" + e.what() + ")",
                          sa::cli::kExitOutOfMemory);
        }
        return report("internal error", e.what(), sa::cli::kExitInternalError);
    } catch (const std::exception& e) {
        // oneTBB reports a worker it cannot start as a std::runtime_error
        // "pthread_create has failed: Resource temporarily unavailable" (EAGAIN), not a
        // system_error: under an address-space limit that is running out of memory too.
        const std::string what = e.what();
        if (what.rfind("pthread_create has failed", 0) == 0 && sa::cli::memory_limit() > 0) {
            return report("error", sa::cli::out_of_memory_message() + " (" + what + ")",
                          sa::cli::kExitOutOfMemory);
        }
        return report("internal error", e.what(), sa::cli::kExitInternalError);
    }
    return report("error", "a command is required: " + command_list(app), sa::cli::kExitBadInput);
}

}  // namespace

int main(int argc, char** argv) {
    sa::cli::apply_runtime_settings();
    sa::cli::install_interruption_handling();
    return check_standard_output(run(argc, argv));
}
