#include "frontends/cli/option_checks.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace sa::cli {
namespace {

std::string format(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

/// The value of `text` when all of it is a number, NaN otherwise.
double parse(const std::string& text) {
    if (text.empty()) return std::nan("");
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size()) return std::nan("");
    return value;
}

CLI::Validator number_check(double low, bool strict, bool allow_inf) {
    const std::string rule = std::string(allow_inf ? "a number or inf " : "a finite number ") +
                             (strict ? "> " : ">= ") + format(low);
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            const double value = parse(text);
            const bool finite_enough =
                allow_inf ? value == INFINITY || std::isfinite(value) : std::isfinite(value);
            if (finite_enough && (strict ? value > low : value >= low)) return {};
            return "must be " + rule + ", found '" + text + "'";
        },
        rule);
}

}  // namespace

CLI::Validator number_at_least(double low, bool strict) {
    return number_check(low, strict, false);
}

CLI::Validator number_or_inf_at_least(double low, bool strict) {
    return number_check(low, strict, true);
}

CLI::Validator integer_at_least(long long low) {
    const std::string rule = "an integer >= " + std::to_string(low);
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            std::size_t i = text.size() > 0 && (text[0] == '-' || text[0] == '+') ? 1 : 0;
            bool digits = i < text.size();
            for (; i < text.size(); ++i) digits = digits && text[i] >= '0' && text[i] <= '9';
            if (digits) {
                errno = 0;
                const long long value = std::strtoll(text.c_str(), nullptr, 10);
                if (errno == 0 && value >= low) return {};
            }
            return "must be " + rule + ", found '" + text + "'";
        },
        rule);
}

void add_threads_option(CLI::App& command, int& threads) {
    command.add_option("--threads", threads, "worker threads, 0 = all cores")
        ->check(integer_at_least(0))
        ->capture_default_str();
}

void add_max_iterations_option(CLI::App& command, int& max_iterations,
                               const std::string& description) {
    command.add_option("--max-iterations", max_iterations, description)
        ->check(integer_at_least(1))
        ->capture_default_str();
}

void add_max_time_option(CLI::App& command, double& max_time, const std::string& scope,
                         const std::string& result) {
    command
        .add_option("--max-time", max_time,
                    "wall-clock limit in seconds on " + scope + "; the " + result +
                        " reached by then is verified, written and reported as it is")
        ->check(number_or_inf_at_least(0.0, true))
        ->capture_default_str();
}

void add_picture_options(CLI::App& command, std::string& png, bool& no_png,
                         const std::string& what) {
    command.add_option("--png", png, what + " (default: --out with .png)");
    command.add_flag("--no-png", no_png, "do not draw the picture");
}

void add_force_and_quiet(CLI::App& command, bool& force, bool& quiet,
                         const std::string& force_description) {
    command.add_flag("--force", force, force_description);
    command.add_flag("--quiet", quiet, "no progress rows on stderr");
}

}  // namespace sa::cli
