#include "geometry/io/index_list_io.h"

#include <limits>
#include <unordered_map>

#include "geometry/io/atomic_file.h"
#include "geometry/io/text_reader.h"
#include "optim/errors.h"

namespace sa {

std::vector<Index> read_index_list(const std::string& path, std::vector<int>* index_lines) {
    io::TextReader reader(path);
    std::vector<long long> values;
    std::vector<int> lines;
    std::size_t first_line_values = 0;
    bool first_line_comment = false;
    bool apart = true;  // every line after the first holds several values
    bool first_line = true;
    while (reader.next_line()) {
        const auto& tokens = reader.tokens();
        if (first_line) {
            first_line_values = tokens.size();
            first_line_comment = !reader.comment().empty();
            first_line = false;
        } else if (tokens.size() < 2) {
            apart = false;
        }
        for (const std::string_view token : tokens) {
            const long long value = reader.to_integer(token, "index");
            if (value < 0) reader.fail("index " + std::to_string(value) + " is negative");
            if (value > std::numeric_limits<Index>::max())
                reader.fail("index " + std::to_string(value) + " is too large");
            values.push_back(value);
            lines.push_back(reader.line_number());
        }
    }
    // A count line: one number alone on the first line that equals the number of indices after
    // it. One that disagrees is an error when the file says it is a count (a comment on its
    // line) or when the layout sets it apart (every line after it holds several indices);
    // otherwise it is an index like the others.
    std::size_t first = 0;
    if (!values.empty() && first_line_values == 1) {
        const auto following = static_cast<long long>(values.size() - 1);
        if (values[0] == following) {
            first = 1;
        } else if (first_line_comment) {
            reader.fail_at(lines[0], "count header says " + std::to_string(values[0]) + " but " +
                                         std::to_string(following) + " indices follow");
        } else if (apart && following > 0) {
            reader.fail_at(lines[0], "the first line holds one number, " +
                                         std::to_string(values[0]) + ", apart from the " +
                                         std::to_string(following) +
                                         " indices after it: a count that disagrees, or an "
                                         "index? Correct the count, or put it with the others");
        }
    }
    std::vector<Index> indices;
    indices.reserve(values.size() - first);
    if (index_lines) index_lines->clear();
    std::unordered_map<Index, int> first_line_of;
    for (std::size_t i = first; i < values.size(); ++i) {
        const auto index = static_cast<Index>(values[i]);
        const auto [it, inserted] = first_line_of.emplace(index, lines[i]);
        if (!inserted)
            reader.fail_at(lines[i], "index " + std::to_string(index) +
                                         " repeated (first on line " + std::to_string(it->second) +
                                         ")");
        indices.push_back(index);
        if (index_lines) index_lines->push_back(lines[i]);
    }
    return indices;
}

void write_index_list(const std::string& path, const std::vector<Index>& indices) {
    std::unordered_map<Index, std::size_t> seen;
    for (std::size_t i = 0; i < indices.size(); ++i) {
        if (indices[i] < 0)
            throw InvalidArgumentError("write_index_list: index " + std::to_string(indices[i]) +
                                       " at position " + std::to_string(i) + " is negative");
        const auto [it, inserted] = seen.emplace(indices[i], i);
        if (!inserted)
            throw InvalidArgumentError("write_index_list: index " + std::to_string(indices[i]) +
                                       " repeated at positions " + std::to_string(it->second) +
                                       " and " + std::to_string(i));
    }
    AtomicFile file(path);
    std::ostream& out = file.stream();
    out << indices.size() << '\n';
    for (const Index index : indices) out << index << '\n';
    file.commit();
}

}  // namespace sa
