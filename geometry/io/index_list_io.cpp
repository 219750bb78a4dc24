#include "geometry/io/index_list_io.h"

#include <algorithm>
#include <limits>
#include <unordered_map>

#include "geometry/io/atomic_file.h"
#include "geometry/io/text_reader.h"
#include "optim/errors.h"

namespace sa {

IndexList read_index_list(const std::string& path) {
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
    // it, when its comment, the layout (every line after it holds several indices) or its own
    // repetition marks it as one. One that disagrees is an error when its comment or the layout
    // says it is a count; otherwise it is an index like the others.
    std::size_t first = 0;
    bool first_may_be_count = false;
    if (!values.empty() && first_line_values == 1) {
        const auto following = static_cast<long long>(values.size() - 1);
        const bool set_apart = first_line_comment || (apart && following > 0);
        if (values[0] == following) {
            const bool repeated =
                std::find(values.begin() + 1, values.end(), values[0]) != values.end();
            if (set_apart || repeated) {
                first = 1;
            } else {
                first_may_be_count = following > 0;  // a lone number counts nothing
            }
        } else if (first_line_comment) {
            reader.fail_at(lines[0], "count header says " + std::to_string(values[0]) + " but " +
                                         std::to_string(following) + " indices follow");
        } else if (set_apart) {
            reader.fail_at(lines[0], "the first line holds one number, " +
                                         std::to_string(values[0]) + ", apart from the " +
                                         std::to_string(following) +
                                         " indices after it: a count that disagrees, or an "
                                         "index? Correct the count, or put it with the others");
        }
    }
    IndexList list;
    list.first_may_be_count = first_may_be_count;
    list.indices.reserve(values.size() - first);
    list.lines.reserve(values.size() - first);
    std::unordered_map<Index, int> first_line_of;
    for (std::size_t i = first; i < values.size(); ++i) {
        const auto index = static_cast<Index>(values[i]);
        const auto [it, inserted] = first_line_of.emplace(index, lines[i]);
        if (!inserted)
            reader.fail_at(lines[i], "index " + std::to_string(index) +
                                         " repeated (first on line " + std::to_string(it->second) +
                                         ")");
        list.indices.push_back(index);
        list.lines.push_back(lines[i]);
    }
    return list;
}

std::string first_number_reading(const std::string& path, const IndexList& list) {
    if (!list.first_may_be_count || list.indices.empty()) return "";
    const std::string n = std::to_string(list.indices.front());
    return path + ":" + std::to_string(list.lines.front()) + ": " + n +
           " read as an index, not as the count of the " + n +
           " numbers after it (a count line says so: `" + n + " # count`)";
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
    out << indices.size() << " # count\n";
    for (const Index index : indices) out << index << '\n';
    file.commit();
}

}  // namespace sa
