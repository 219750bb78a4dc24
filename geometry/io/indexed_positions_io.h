#pragma once
// Rows of positions, with or without a leading vertex index: handle targets for deformation.
//
//   indexed   `index x y z` (3D) or `index x y` (2D): a 0-based vertex and its position, as
//             public deformation data lists handle targets; alone it names the handles too
//   plain     `x y z` or `x y`: one position per row (the caller decides whether a row is a
//             vertex or a handle)
// `#` starts a comment; blank lines are skipped; LF or CRLF. The first line may be a count of
// the rows that follow, alone on it (a row has at least 2 numbers, so this is unambiguous); it is
// checked and dropped. By default the layout is fixed by the first row's count of numbers (d + 1
// indexed, d plain) and every row must have the same count; so in 2D, 3 numbers are read as
// `index x y`. RowLayout::plain reads them as `x y z` with z = 0 (a planar position saved with
// three coordinates) instead: the caller that can tell the two apart (deform/handle_targets.h)
// asks for both. A vertex listed twice at the same position is kept once; at two positions it is
// an error.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "optim/types.h"

namespace sa {

struct PositionRows {
    /// The vertex of each row (indexed layout, in file order, repeats removed); empty in the
    /// plain layout.
    std::vector<Index> indices;
    /// One row per position, #rows x d.
    Eigen::MatrixXd positions;
    /// The 1-based line of each row in the file, for messages.
    std::vector<int> lines;

    bool indexed() const { return !indices.empty(); }
};

enum class RowLayout {
    by_count,  ///< d + 1 numbers a row: `index x y (z)`; d numbers: `x y (z)`
    plain,     ///< `x y (z)`; in 2D also `x y 0`, three numbers whose last is zero
};

/// Reads `path` for a map of `dimension` (2 or 3) coordinates. `num_vertices` >= 0 checks the
/// indices against [0, num_vertices) (a negative value skips that check). Throws InputError
/// `FILE:LINE: ...` on a token that is not a number, a non-integer or negative index, an index out
/// of range, a row with another count of numbers, a vertex listed twice at two positions (naming
/// both lines), a count line that does not match, a third coordinate other than 0 in a plain 2D
/// row, or a file without rows; `FILE: cannot open` when it cannot be read. InvalidArgumentError
/// for a dimension other than 2 or 3.
PositionRows read_position_rows(const std::string& path, int dimension, Index num_vertices = -1,
                                RowLayout layout = RowLayout::by_count);

}  // namespace sa
