#pragma once
// Where library code writes progress and notes: a function the caller gives (the command-line
// tool passes one that writes to stderr). Library code never writes to stdout or stderr itself.

#include <functional>
#include <string>

namespace sa {

/// Receives one line (without its newline) at a time. An empty Logger discards everything.
using Logger = std::function<void(const std::string& line)>;

inline void log_line(const Logger& logger, const std::string& line) {
    if (logger) logger(line);
}

}  // namespace sa
