#pragma once
// Index lists: handle and locked-vertex files (deform/*_handles.txt, wrench-lock.txt).
//
// Whitespace-separated non-negative 0-based integers in any layout; `#` starts a comment. A count
// line is recognized only when its number is alone on the first line and equals the count of the
// numbers after it; then it is dropped. When a number alone on the first line disagrees, it is
// an error if the line has a comment (`4792 #Vertices Locked`) or if every line after it holds
// several numbers (ambiguous: a wrong count, or an index?); otherwise it is an index. A first line
// of several numbers (`3 10 20 30`) is a list of indices.

#include <string>
#include <vector>

#include "optim/types.h"

namespace sa {

/// Reads an index list (0-based). Throws InputError `FILE:LINE: ...` on a token that is not a
/// non-negative integer, a repeated index (naming it and both lines), or a first number that is
/// a count by its comment or layout but does not match the numbers after it. `lines`, when given,
/// receives the 1-based line of each index (for the caller's own messages, e.g. an index out of a
/// mesh's range).
std::vector<Index> read_index_list(const std::string& path, std::vector<int>* lines = nullptr);

/// Writes a count header line, then one index per line, so that the file reads back the same
/// whatever its first index. Throws InvalidArgumentError on a negative or repeated index, and
/// InputError when the file cannot be written (nothing is left at `path` then).
void write_index_list(const std::string& path, const std::vector<Index>& indices);

}  // namespace sa
