#pragma once
// The colour map of the pictures that colour a value (layout_picture.h, surface_value_picture.h).

#include <algorithm>
#include <array>

namespace sa {

/// Viridis at t in [0, 1] (clamped), sampled at 9 points and interpolated linearly.
inline std::array<double, 3> viridis(double t) {
    static const double stops[9][3] = {
        {0.267, 0.005, 0.329}, {0.278, 0.175, 0.483}, {0.231, 0.322, 0.546},
        {0.173, 0.449, 0.558}, {0.128, 0.567, 0.551}, {0.153, 0.680, 0.510},
        {0.361, 0.786, 0.388}, {0.668, 0.862, 0.196}, {0.993, 0.906, 0.144}};
    t = std::clamp(t, 0.0, 1.0) * 8.0;
    const int i = std::min(int(t), 7);
    const double f = t - i;
    return {stops[i][0] + f * (stops[i + 1][0] - stops[i][0]),
            stops[i][1] + f * (stops[i + 1][1] - stops[i][1]),
            stops[i][2] + f * (stops[i + 1][2] - stops[i][2])};
}

}  // namespace sa
