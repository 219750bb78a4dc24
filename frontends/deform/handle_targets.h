#pragma once
// Handles and their targets: the input of deformation posing (section 5.4). A user has the rest
// shape, the handle vertices and where they go, no initial map.
//
// Accepted layouts (`handles` an index list as in geometry/io/index_list_io.h, 0-based):
//   handles + targets            targets is
//     a mesh file (.node .mesh .obj .off .vtk .vtu .ply .stl, by extension) with one vertex per
//       rest vertex: its rows at the handles (deform/*_init.node);
//     rows `index x y z` (`index x y` in 2D) naming exactly the handles, in any order;
//     rows `x y z` (`x y`): one per rest vertex (its rows at the handles) or one per handle (in
//       the handle list's order); a file with as many rows as the mesh has vertices is read per
//       vertex (refused when every vertex is a handle and the list is out of order);
//     in 2D, rows of three numbers are `index x y` or `x y 0` (a planar target saved with z = 0):
//       each reading is tried against the handles, the one that fits is taken, and a file that
//       fits both is refused with a message naming both.
//   targets alone                rows `index x y z`: the indices are the handles, in file order.
// Row files are read by geometry/io/indexed_positions_io.h (comments, an optional count line,
// a vertex listed twice at one position kept once, at two positions an error).
// Positions with more coordinates than the map (a 2D map saved with z = 0) keep the first d;
// the dropped ones must be zero.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "optim/types.h"

namespace sa {

struct HandleTargets {
    std::vector<Index> handles;  ///< distinct vertices, 0-based
    Eigen::MatrixXd targets;     ///< #handles x d: row k is where handles[k] goes
    /// How the files were read, for the summary: "rows `x y 0` of t.txt, one per handle", and the
    /// handle list's first number when it could have been a count (index_list_io.h).
    std::string reading = {};
    /// Where each target was read, for messages: "t.txt:12", "t.node (vertex 7)"; empty for
    /// targets built in code.
    std::vector<std::string> origins = {};
};

/// The most a pose may stretch its rest shape: no target farther than this many rest diagonals
/// from the rest shape's bounding box. A stretch s gives a tetrahedron's volume s^3 times its
/// own, and the distortions and energies powers of s: at 1e100 they stay finite in doubles.
inline constexpr double kMaxPoseStretch = 1e100;

/// Reads handles and targets for a mesh of `num_vertices` vertices mapped to `dimension` (2 or
/// 3) coordinates; `handles_path` may be empty (targets alone). Throws InputError with a one-line
/// message naming the file and, for a row, its line: a handle out of range, listed twice, or
/// twice with two targets; a target row for a vertex that is not a handle, a handle without a
/// target; a row count that is neither #V nor #H; rows that fit two layouts; no handle at all;
/// non-finite or missing coordinates.
HandleTargets read_handle_targets(const std::string& handles_path, const std::string& targets_path,
                                  Index num_vertices, int dimension);

/// Throws InputError naming the target (its origin, the vertex and its distance) when one lies
/// more than kMaxPoseStretch rest diagonals from the bounding box of `rest` (#V x d): its pose
/// would overflow double arithmetic, and no solve could say why.
void check_target_reach(const Eigen::MatrixXd& rest, const HandleTargets& handle_targets);

/// The rest positions (#V x d) with the handles moved to their targets: the start of the
/// local/global iterations. Throws InvalidArgumentError on inconsistent sizes or an index out of
/// range.
Eigen::MatrixXd move_handles(const Eigen::MatrixXd& rest, const HandleTargets& handle_targets);

}  // namespace sa
