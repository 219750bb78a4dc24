#include "geometry/io/indexed_positions_io.h"

#include <limits>
#include <unordered_map>

#include "geometry/io/text_reader.h"
#include "optim/errors.h"

namespace sa {

PositionRows read_position_rows(const std::string& path, int dimension, Index num_vertices,
                                RowLayout layout) {
    if (dimension != 2 && dimension != 3) {
        throw InvalidArgumentError("read_position_rows: dimension " + std::to_string(dimension) +
                                   " (expected 2 or 3)");
    }
    io::TextReader reader(path);
    const std::string plain = dimension == 3 ? "`x y z`" : "`x y`";
    const std::string indexed = dimension == 3 ? "`index x y z`" : "`index x y`";
    int columns = 0;  // of the layout, fixed by the first row
    long long count = -1;
    int count_line = 0;
    std::vector<long long> indices;
    std::vector<double> values;
    std::vector<int> lines;
    std::unordered_map<long long, std::size_t> row_of;  // indexed: a vertex's first row
    long long file_rows = 0;                            // every row, repeats included
    bool first_line = true;
    while (reader.next_line()) {
        const auto& tokens = reader.tokens();
        if (first_line && tokens.size() == 1) {
            count = reader.to_count(tokens[0], "count of rows");
            count_line = reader.line_number();
            first_line = false;
            continue;
        }
        first_line = false;
        const int n = static_cast<int>(tokens.size());
        if (columns == 0) {
            // d + 1 numbers: `index x y (z)` by count, `x y 0` in the plain layout in 2D.
            const bool one_more = layout == RowLayout::by_count || dimension == 2;
            if (n != dimension && !(n == dimension + 1 && one_more)) {
                reader.fail(std::to_string(n) + " numbers; expected rows of " +
                            (layout == RowLayout::by_count ? indexed + " or " + plain : plain));
            }
            columns = n;
        } else if (n != columns) {
            reader.fail(std::to_string(n) + " numbers, the rows before have " +
                        std::to_string(columns) + " (" +
                        (columns == dimension || layout == RowLayout::plain ? plain : indexed) +
                        ")");
        }
        ++file_rows;
        const bool with_index = columns == dimension + 1 && layout == RowLayout::by_count;
        if (columns == dimension + 1 && !with_index) {  // `x y 0`: a planar position
            const double z = reader.to_double(tokens[dimension], "coordinate");
            if (z != 0.0)
                reader.fail("z = " + std::string(tokens[dimension]) + "; rows " + plain +
                            " of a planar map may have a third coordinate only when it is 0");
        }
        long long index = -1;
        if (with_index) {
            index = reader.to_integer(tokens[0], "vertex index");
            if (index < 0) reader.fail("vertex index " + std::to_string(index) + " is negative");
            if (num_vertices >= 0 && index >= num_vertices) {
                reader.fail("vertex index " + std::to_string(index) + " outside [0, " +
                            std::to_string(num_vertices) + ") (the mesh has " +
                            std::to_string(num_vertices) + " vertices)");
            }
            if (index > std::numeric_limits<Index>::max())
                reader.fail("vertex index " + std::to_string(index) + " is too large");
        }
        double row[3];
        for (int c = 0; c < dimension; ++c)
            row[c] = reader.to_double(tokens[c + (with_index ? 1 : 0)], "coordinate");
        if (with_index) {
            const auto [it, inserted] = row_of.emplace(index, lines.size());
            if (!inserted) {
                const std::size_t first = it->second;
                bool same = true;
                for (int c = 0; c < dimension; ++c)
                    same = same && values[first * dimension + c] == row[c];
                if (same) continue;  // listed twice at the same position: harmless
                reader.fail("vertex " + std::to_string(index) +
                            " listed twice with two targets (first on line " +
                            std::to_string(lines[first]) + ")");
            }
            indices.push_back(index);
        }
        values.insert(values.end(), row, row + dimension);
        lines.push_back(reader.line_number());
    }
    if (lines.empty()) {
        reader.fail_file("no rows of " + indexed + " or " + plain);
    }
    if (count >= 0 && count != file_rows) {
        reader.fail_at(count_line, "count line says " + std::to_string(count) + " but " +
                                       std::to_string(file_rows) + " rows follow");
    }
    PositionRows result;
    result.indices.assign(indices.begin(), indices.end());
    result.lines = std::move(lines);
    const Eigen::Index rows = static_cast<Eigen::Index>(result.lines.size());
    result.positions =
        Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
            values.data(), rows, dimension);
    return result;
}

}  // namespace sa
