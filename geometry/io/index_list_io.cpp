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
    bool header_with_comment = false;
    bool first_line = true;
    while (reader.next_line()) {
        const auto& tokens = reader.tokens();
        if (first_line) {
            header_with_comment = tokens.size() == 1 && !reader.comment().empty();
            first_line = false;
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
    std::size_t first = 0;
    if (!values.empty()) {
        const auto following = static_cast<long long>(values.size() - 1);
        if (header_with_comment && values[0] != following)
            reader.fail_at(lines[0], "count header says " + std::to_string(values[0]) + " but " +
                                         std::to_string(following) + " indices follow");
        if (header_with_comment || values[0] == following) first = 1;
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
