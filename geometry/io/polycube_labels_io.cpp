#include "geometry/io/polycube_labels_io.h"

#include "geometry/io/atomic_file.h"
#include "geometry/io/text_reader.h"
#include "optim/errors.h"

namespace sa {

namespace {

/// Reads every integer of the file into `labels`, checking each against [lowest, 5]; `what`
/// names an entry in messages from its position.
template <class Name>
std::vector<int> read_labels(const std::string& path, std::size_t expected, int lowest,
                             const Name& name) {
    io::TextReader reader(path);
    std::vector<int> labels;
    labels.reserve(expected);
    while (reader.next_line()) {
        for (const std::string_view token : reader.tokens()) {
            const long long value = reader.to_integer(token, "label");
            if (value < lowest || value > 5) {
                reader.fail("label " + std::to_string(value) + " of " + name(labels.size()) +
                            " is outside [" + std::to_string(lowest) + ", 5]");
            }
            labels.push_back(static_cast<int>(value));
        }
    }
    if (labels.size() != expected) {
        reader.fail_file(std::to_string(labels.size()) + " labels, expected " +
                         std::to_string(expected) + " (" + name(std::size_t(-1)) + ")");
    }
    return labels;
}

}  // namespace

std::vector<int> read_facet_flags(const std::string& path, Index num_tets) {
    if (num_tets < 0) throw InvalidArgumentError("read_facet_flags: negative tetrahedron count");
    const std::size_t expected = 4 * std::size_t(num_tets);
    return read_labels(path, expected, -1, [&](std::size_t i) {
        if (i == std::size_t(-1)) {
            return "4 per tetrahedron for " + std::to_string(num_tets) + " tetrahedra";
        }
        return "tetrahedron " + std::to_string(i / 4) + " facet " + std::to_string(i % 4);
    });
}

std::vector<int> read_triangle_labels(const std::string& path, Index num_triangles) {
    if (num_triangles < 0) {
        throw InvalidArgumentError("read_triangle_labels: negative triangle count");
    }
    return read_labels(path, std::size_t(num_triangles), 0, [&](std::size_t i) {
        if (i == std::size_t(-1)) {
            return "one per triangle of a surface of " + std::to_string(num_triangles);
        }
        return "triangle " + std::to_string(i);
    });
}

void write_facet_flags(const std::string& path, const std::vector<int>& flags) {
    for (std::size_t i = 0; i < flags.size(); ++i) {
        if (flags[i] < -1 || flags[i] > 5) {
            throw InvalidArgumentError("write_facet_flags: label " + std::to_string(flags[i]) +
                                       " at position " + std::to_string(i) + " is outside [-1, 5]");
        }
    }
    AtomicFile file(path);
    std::ostream& out = file.stream();
    for (const int label : flags) out << label << '\n';
    file.commit();
}

}  // namespace sa
