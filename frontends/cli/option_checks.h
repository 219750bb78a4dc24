#pragma once
// Range checks of the `sa` command's numeric options, as CLI11 validators: they run on the text
// the user typed, before it is converted, so that a bad value is reported under the option's own
// name ("--max-iterations: must be an integer >= 1, found '0'"), never under the name of the
// library field it ends up in. NaN is never in range; "inf" only where a check allows it.

#include <CLI/CLI.hpp>

namespace sa::cli {

/// A finite number >= `low` (> `low` when `strict`).
CLI::Validator number_at_least(double low, bool strict = false);

/// A number >= `low` (> `low` when `strict`), or inf.
CLI::Validator number_or_inf_at_least(double low, bool strict = false);

/// An integer (digits, an optional sign) >= `low`.
CLI::Validator integer_at_least(long long low);

}  // namespace sa::cli
