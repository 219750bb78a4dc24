#include "frontends/deform/deform_options.h"

#include <cmath>
#include <string>

#include "optim/errors.h"

namespace sa {

void DeformOptions::validate() const {
    auto fail = [](const std::string& what) {
        throw InvalidArgumentError("DeformOptions: " + what);
    };
    auto check_bound = [&](const char* name, double K) {
        if (!(K > 1.0)) fail(std::string(name) + " = " + std::to_string(K) + " must be > 1 or inf");
    };
    check_bound("conformal_bound", conformal_bound);
    check_bound("volumetric_bound", volumetric_bound);
    if (optimal_bound && (std::isfinite(conformal_bound) || std::isfinite(volumetric_bound))) {
        fail("optimal_bound finds both bounds; conformal_bound and volumetric_bound must be inf");
    }
    if (optimal_bound_rounds < 1)
        fail("optimal_bound_rounds = " + std::to_string(optimal_bound_rounds) + " < 1");
    if (!(optimal_bound_tolerance >= 0.0 && optimal_bound_tolerance < 1.0)) {
        fail("optimal_bound_tolerance = " + std::to_string(optimal_bound_tolerance) +
             " must be in [0, 1)");
    }
    if (!(optimal_bound_band > 0.0 && optimal_bound_band <= 1.0))
        fail("optimal_bound_band = " + std::to_string(optimal_bound_band) + " must be in (0, 1]");
    if (!(mu >= 0.0 && std::isfinite(mu))) fail("mu = " + std::to_string(mu) + " must be >= 0");
    if (!(max_time_seconds > 0.0))
        fail("max_time_seconds = " + std::to_string(max_time_seconds) + " must be > 0");
    if (num_threads < 0) fail("num_threads = " + std::to_string(num_threads) + " < 0");
    start.validate();
}

}  // namespace sa
