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

}  // namespace sa::cli
