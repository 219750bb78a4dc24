#include "frontends/hex/plane_quantization.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "optim/errors.h"

namespace sa {

PlaneQuantization quantize_planes(const std::vector<double>& coordinates,
                                  const std::vector<int>& axis,
                                  const std::vector<PlaneSeparation>& apart, double cell) {
    const int n = static_cast<int>(coordinates.size());
    if (static_cast<int>(axis.size()) != n)
        throw InvalidArgumentError("quantize_planes: one axis per plane coordinate");
    if (!(cell > 0.0) || !std::isfinite(cell))
        throw InvalidArgumentError("quantize_planes: the cell size must be finite and > 0");
    for (int p = 0; p < n; ++p) {
        if (!std::isfinite(coordinates[p]) || axis[p] < 0 || axis[p] > 2) {
            throw InvalidArgumentError("quantize_planes: plane " + std::to_string(p) +
                                       " has a non-finite coordinate or an axis outside 0..2");
        }
    }
    std::vector<std::vector<int>> below(n);  // per plane: the planes it must stay above
    for (const PlaneSeparation& s : apart) {
        if (s.low < 0 || s.low >= n || s.high < 0 || s.high >= n || axis[s.low] != axis[s.high] ||
            !(coordinates[s.low] < coordinates[s.high])) {
            throw InvalidArgumentError("quantize_planes: the separation of planes " +
                                       std::to_string(s.low) + " and " + std::to_string(s.high) +
                                       " is not between planes of one axis in increasing order");
        }
        below[s.high].push_back(s.low);
    }
    PlaneQuantization q;
    q.cell = cell;
    q.position.assign(n, 0);
    for (int a = 0; a < 3; ++a) {
        std::vector<int> order;
        for (int p = 0; p < n; ++p)
            if (axis[p] == a) order.push_back(p);
        std::stable_sort(order.begin(), order.end(),
                         [&](int x, int y) { return coordinates[x] < coordinates[y]; });
        q.planes[a] = static_cast<int>(order.size());
        for (std::size_t i = 0; i < order.size(); ++i) {
            const int p = order[i];
            const double nearest = std::round(coordinates[p] / cell);
            int position = static_cast<int>(nearest);
            if (i > 0) position = std::max(position, q.position[order[i - 1]]);
            for (const int low : below[p]) position = std::max(position, q.position[low] + 1);
            if (position != static_cast<int>(nearest)) ++q.raised;
            q.position[p] = position;
        }
        if (!order.empty()) {
            q.extent[a] = q.position[order.back()] - q.position[order.front()];
            q.distinct_positions[a] = 1;
            for (std::size_t i = 1; i < order.size(); ++i)
                if (q.position[order[i]] != q.position[order[i - 1]]) ++q.distinct_positions[a];
        }
    }
    return q;
}

}  // namespace sa
