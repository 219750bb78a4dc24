#pragma once
// Internal to geometry/io: checks of the arrays a writer is given, and row output shared by the
// text writers. Bad arrays throw InvalidArgumentError `FUNCTION: what is wrong`, before anything
// is written.

#include <Eigen/Core>
#include <ostream>

namespace sa::io {

/// Checks that `positions` has between `min_cols` and `max_cols` columns and finite entries.
void check_positions(const char* function, const Eigen::MatrixXd& positions, int min_cols = 2,
                     int max_cols = 3);

/// Checks that `simplices` has `cols` columns (3 or 4 when `cols` is 0) and that every entry is
/// a vertex index in [0, num_vertices).
void check_simplices(const char* function, const char* name, const Eigen::MatrixXi& simplices,
                     Eigen::Index num_vertices, int cols = 0);

/// Writes `value` in the shortest decimal form that reads back as the same double (std::to_chars:
/// several times faster than a stream's 17 significant digits, which on a million-vertex OBJ
/// were most of the output time).
void write_number(std::ostream& out, double value);

/// Writes row `row` of `positions` (write_number) separated by spaces; with `pad_to_3`, a 2-column
/// row gets a third coordinate 0. No line ending.
void write_position(std::ostream& out, const Eigen::MatrixXd& positions, Eigen::Index row,
                    bool pad_to_3);

}  // namespace sa::io
