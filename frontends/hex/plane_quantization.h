#pragma once
// Quantization of a PolyCube's planes (issue 48): each plane (polycube_planes.h) gets an integer
// position on its axis, the PolyCube's planes then lie on a grid of unit cells and every cell
// inside it becomes a hexahedron (hex_extraction.h).
//
// The rule, per axis, with c_p the plane's coordinate and h the cell size:
//   - q_p = round(c_p / h): planes closer than about a cell may come to one integer (they
//     coincide in the hex mesh, as features smaller than a cell do);
//   - planes stay in their order: q is non-decreasing in c, so the map that moves the planes
//     (grid_start.h) keeps the slabs between them;
//   - the two corner planes of every PolyCube edge stay at least one cell apart (`apart`), so no
//     edge, and no chart (whose extent along the edge's axis its edges span), collapses.
// Solved exactly for the last two by one pass in increasing c, each plane raised to the
// smallest integer that keeps the order and its constraints from lower planes (a longest-path
// recurrence on the constraint graph); rounding then raising is the greedy repair of Protais et
// al. 2022's integer program, without a MILP solver.

#include <array>
#include <vector>

#include "optim/types.h"

namespace sa {

/// Two planes of one axis that must stay at least one cell apart, `low` below `high`.
struct PlaneSeparation {
    int low = -1, high = -1;
};

struct PlaneQuantization {
    std::vector<int> position;  ///< per plane: its integer position on its axis
    double cell = 0.0;          ///< h, in the coordinates' units
    /// Per axis: its planes, their distinct positions, and the cells between the outer two.
    std::array<int, 3> planes{}, distinct_positions{}, extent{};
    /// Planes placed above round(c / h) to keep the order or a separation.
    int raised = 0;
};

/// Quantizes the planes of `axis` (per plane: 0, 1 or 2) at `coordinates` (per plane) with cell
/// size `cell` > 0, keeping `apart`'s pairs a cell apart as described above. Throws
/// InvalidArgumentError on mismatched sizes, a non-finite coordinate, a cell size <= 0, or a
/// separation between planes of different axes or not in increasing coordinate.
PlaneQuantization quantize_planes(const std::vector<double>& coordinates,
                                  const std::vector<int>& axis,
                                  const std::vector<PlaneSeparation>& apart, double cell);

}  // namespace sa
