#pragma once
// The options of every `sa` subcommand: each add_*_command registers its command on the program's
// CLI11 App, binding the options to the fields of its arguments (the *_command.h headers), with
// their defaults, checks and help texts.
//
// Only this unit and sa_main.cpp include CLI11: its headers (version 2.1) compile about 100 KB of
// code into every unit that includes them, whether it uses CLI11 or not. Other callers (the
// tests) parse a command line with parse_command_line().

#include <string>
#include <vector>

#include "frontends/cli/deform_command.h"
#include "frontends/cli/demo_command.h"
#include "frontends/cli/hex_command.h"
#include "frontends/cli/map_command.h"
#include "frontends/cli/param_command.h"
#include "frontends/cli/polycube_command.h"
#include "frontends/cli/seamless_command.h"
#include "optim/errors.h"

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
CLI::App* add_hex_command(CLI::App& app, HexArguments& arguments);
CLI::App* add_deform_command(CLI::App& app, DeformArguments& arguments);

/// A command line that does not parse; what() is CLI11's message, as `sa` prints it.
class CommandLineError : public InvalidArgumentError {
  public:
    using InvalidArgumentError::InvalidArgumentError;
};

/// Parses `words`, what follows `sa <command>` on a command line, into `arguments` with that
/// command's definitions, defaults and checks, as the sa command does. Throws CommandLineError.
void parse_command_line(const std::vector<std::string>& words, MapArguments& arguments);
void parse_command_line(const std::vector<std::string>& words, ParamArguments& arguments);
void parse_command_line(const std::vector<std::string>& words, SeamlessArguments& arguments);
void parse_command_line(const std::vector<std::string>& words, PolycubeArguments& arguments);
void parse_command_line(const std::vector<std::string>& words, HexArguments& arguments);
void parse_command_line(const std::vector<std::string>& words, DeformArguments& arguments);

}  // namespace sa::cli
