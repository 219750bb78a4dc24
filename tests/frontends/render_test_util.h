#pragma once
// Shared by the tests that render pictures (labelled frontends_render): whether a picture can be
// rendered here, and a skip when it cannot.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

namespace sa {

/// An executable Xvfb on PATH.
inline bool xvfb_on_path() {
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "";
    for (std::size_t start = 0; start <= dirs.size();) {
        std::size_t end = dirs.find(':', start);
        if (end == std::string::npos) end = dirs.size();
        if (access((dirs.substr(start, end - start) + "/Xvfb").c_str(), X_OK) == 0) return true;
        start = end + 1;
    }
    return false;
}

// Rendering needs an X display, or Xvfb for the renderer to start.
#define SKIP_WITHOUT_X()                                                               \
    do {                                                                               \
        const char* display = std::getenv("DISPLAY");                                  \
        if (!(display && *display) && !xvfb_on_path())                                 \
            GTEST_SKIP() << "no DISPLAY and no Xvfb (scripts/setup.sh installs xvfb)"; \
    } while (0)

}  // namespace sa
