#include "geometry/io/write_checks.h"

#include <charconv>
#include <cmath>
#include <sstream>
#include <string>

#include "optim/errors.h"

namespace sa::io {

void check_positions(const char* function, const Eigen::MatrixXd& positions, int min_cols,
                     int max_cols) {
    const auto cols = positions.cols();
    if (cols < min_cols || cols > max_cols) {
        std::ostringstream message;
        message << function << ": positions have " << cols << " columns; expected ";
        if (min_cols == max_cols)
            message << min_cols;
        else
            message << min_cols << " to " << max_cols;
        throw InvalidArgumentError(message.str());
    }
    for (Eigen::Index i = 0; i < positions.rows(); ++i) {
        for (Eigen::Index j = 0; j < cols; ++j) {
            if (!std::isfinite(positions(i, j))) {
                std::ostringstream message;
                message << function << ": positions row " << i << " column " << j
                        << " is not finite (" << positions(i, j) << ")";
                throw InvalidArgumentError(message.str());
            }
        }
    }
}

void check_simplices(const char* function, const char* name, const Eigen::MatrixXi& simplices,
                     Eigen::Index num_vertices, int cols) {
    const auto actual = simplices.cols();
    if (cols != 0 ? actual != cols : actual != 3 && actual != 4) {
        std::ostringstream message;
        message << function << ": " << name << " have " << actual << " columns; expected "
                << (cols != 0 ? std::to_string(cols) : std::string("3 or 4"));
        throw InvalidArgumentError(message.str());
    }
    for (Eigen::Index i = 0; i < simplices.rows(); ++i) {
        for (Eigen::Index j = 0; j < actual; ++j) {
            const int v = simplices(i, j);
            if (v < 0 || v >= num_vertices) {
                std::ostringstream message;
                message << function << ": " << name << " row " << i << " refers to vertex " << v
                        << ", out of range [0, " << num_vertices - 1 << "]";
                throw InvalidArgumentError(message.str());
            }
        }
    }
}

void write_number(std::ostream& out, double value) {
    char text[32];
    const std::to_chars_result r = std::to_chars(text, text + sizeof text, value);
    out.write(text, r.ptr - text);
}

void write_position(std::ostream& out, const Eigen::MatrixXd& positions, Eigen::Index row,
                    bool pad_to_3) {
    for (Eigen::Index j = 0; j < positions.cols(); ++j) {
        if (j > 0) out << ' ';
        write_number(out, positions(row, j));
    }
    if (pad_to_3) {
        for (Eigen::Index j = positions.cols(); j < 3; ++j) out << " 0";
    }
}

}  // namespace sa::io
