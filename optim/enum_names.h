#pragma once
// An option enum's names, listed once for both directions: to_string and parse functions look
// them up in one table instead of a switch and a loop that each list the values.
//
//     constexpr EnumName<SolveMode> kSolveModeNames[] = {
//         {SolveMode::kAuto, "auto"}, {SolveMode::kFull, "full"}, {SolveMode::kSubmesh,
//         "submesh"}};
//     std::string to_string(SolveMode m) { return enum_name(kSolveModeNames, m); }
//     SolveMode parse_solve_mode(const std::string& s) { return parse_enum(kSolveModeNames, s,
//     "mode"); }

#include <cstddef>
#include <string>

#include "optim/errors.h"

namespace sa {

template <class Enum>
struct EnumName {
    Enum value;
    const char* name;
};

/// The name of `value` in `names` ("unknown" when it is not listed).
template <class Enum, std::size_t N>
std::string enum_name(const EnumName<Enum> (&names)[N], Enum value) {
    for (const EnumName<Enum>& n : names)
        if (n.value == value) return n.name;
    return "unknown";
}

/// The value named `name`; throws InvalidArgumentError "unknown <what> '<name>' (expected a, b or
/// c)" otherwise.
template <class Enum, std::size_t N>
Enum parse_enum(const EnumName<Enum> (&names)[N], const std::string& name,
                const std::string& what) {
    std::string expected;
    for (std::size_t i = 0; i < N; ++i) {
        if (names[i].name == name) return names[i].value;
        expected += (i == 0 ? "" : i + 1 == N ? " or " : ", ") + std::string(names[i].name);
    }
    throw InvalidArgumentError("unknown " + what + " '" + name + "' (expected " + expected + ")");
}

}  // namespace sa
