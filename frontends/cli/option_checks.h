#pragma once
// Range checks of the `sa` command's numeric options, as CLI11 validators: they run on the text
// the user typed, before it is converted, so that a bad value is reported under the option's own
// name ("--max-iterations: must be an integer >= 1, found '0'"), never under the name of the
// library field it ends up in. NaN is never in range; "inf" only where a check allows it.
// Below them, the options several commands share, defined once with one wording and one check.

#include <CLI/CLI.hpp>
#include <string>

namespace sa::cli {

/// A finite number >= `low` (> `low` when `strict`).
CLI::Validator number_at_least(double low, bool strict = false);

/// A number >= `low` (> `low` when `strict`), or inf.
CLI::Validator number_or_inf_at_least(double low, bool strict = false);

/// An integer (digits, an optional sign) >= `low`.
CLI::Validator integer_at_least(long long low);

/// --threads N: worker threads, 0 = all cores (an integer >= 0).
void add_threads_option(CLI::App& command, int& threads);

/// --max-iterations N (an integer >= 1), described as `description`.
void add_max_iterations_option(CLI::App& command, int& max_iterations,
                               const std::string& description);

/// --max-time S (a number or inf > 0): "wall-clock limit in seconds on SCOPE; the RESULT reached
/// by then is verified, written and reported as it is".
void add_max_time_option(CLI::App& command, double& max_time, const std::string& scope,
                         const std::string& result = "map");

/// --png FILE and --no-png, for PictureOutput (output_plan.h): `what` is the picture, "(default:
/// --out with .png)" is added.
void add_picture_options(CLI::App& command, std::string& png, bool& no_png,
                         const std::string& what);

/// --force (described as `force_description`) and --quiet (no progress rows on stderr).
void add_force_and_quiet(CLI::App& command, bool& force, bool& quiet,
                         const std::string& force_description = "overwrite existing output files");

}  // namespace sa::cli
