#pragma once
// The options of every `sa` subcommand: each add_*_command registers its command on the program's
// CLI11 App, binding the options to the fields of its arguments (the *_command.h headers), with
// their defaults, checks and help texts.
//
// Only this unit and sa_main.cpp include CLI11: its headers (version 2.1) compile about 100 KB of
// code into every unit that includes them, whether it uses CLI11 or not.

#include "frontends/cli/deform_command.h"
#include "frontends/cli/demo_command.h"
#include "frontends/cli/map_command.h"
#include "frontends/cli/param_command.h"
#include "frontends/cli/polycube_command.h"
#include "frontends/cli/seamless_command.h"

namespace CLI {
class App;
}

namespace sa::cli {

CLI::App* add_map_command(CLI::App& app, MapArguments& arguments);
CLI::App* add_demo_command(CLI::App& app, DemoArguments& arguments);
CLI::App* add_param_command(CLI::App& app, ParamArguments& arguments);
CLI::App* add_subdivide_command(CLI::App& app, SubdivideArguments& arguments);
CLI::App* add_seamless_command(CLI::App& app, SeamlessArguments& arguments);
CLI::App* add_polycube_command(CLI::App& app, PolycubeArguments& arguments);
CLI::App* add_deform_command(CLI::App& app, DeformArguments& arguments);

}  // namespace sa::cli
