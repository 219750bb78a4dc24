#pragma once
// Index lists: handle and locked-vertex files, as deformation problems ship them.
//
// Whitespace-separated non-negative 0-based integers in any layout; `#` starts a comment. A number
// alone on the first line that equals the count of the numbers after it may be a count line or an
// index; it is read as a count, and dropped, only when something marks it as one:
//   - a comment on its line (`4792 #Vertices Locked`);
//   - every line after it holding several numbers (`4\n10 20\n30 40`);
//   - the same number again after it (as an index it would be repeated).
// Otherwise it is an index like the others (`17\n1\n2\n...`: vertex 17 is a handle), and
// IndexList::first_may_be_count says so, for the caller's summary. A lone first number that
// disagrees with the count after it is an error when the same marks set it apart (a comment, or
// every line after it holding several numbers); otherwise it is an index. A first line of several
// numbers (`3 10 20 30`) is a list of indices.

#include <string>
#include <vector>

#include "optim/types.h"

namespace sa {

struct IndexList {
    std::vector<Index> indices;  ///< 0-based, distinct, in file order
    std::vector<int> lines;      ///< the 1-based line of each index, for the caller's messages
    /// The first line's lone number equals the count of the numbers after it, nothing marks it as
    /// a count, and it was read as an index.
    bool first_may_be_count = false;
};

/// Reads an index list (0-based). Throws InputError `FILE:LINE: ...` on a token that is not a
/// non-negative integer, a repeated index (naming it and both lines), or a first number that is
/// a count by its comment or layout but does not match the numbers after it.
IndexList read_index_list(const std::string& path);

/// For a summary, when list.first_may_be_count: "PATH:LINE: N read as an index, not as the count
/// of the N numbers after it (a count line says so: `N # count`)"; "" otherwise.
std::string first_number_reading(const std::string& path, const IndexList& list);

/// Writes a count line marked by a comment (`3 # count`), then one index per line, so that the
/// file reads back the same whatever its first index. Throws InvalidArgumentError on a negative
/// or repeated index, and InputError when the file cannot be written (nothing is left at `path`
/// then).
void write_index_list(const std::string& path, const std::vector<Index>& indices);

}  // namespace sa
