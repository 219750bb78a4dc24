#include "geometry/io/dmat_io.h"

#include <cmath>
#include <sstream>
#include <string>

#include "geometry/io/atomic_file.h"
#include "geometry/io/text_reader.h"
#include "optim/errors.h"

namespace sa {

Eigen::MatrixXd read_dmat(const std::string& path) {
    // No comments: '#' has no meaning in .dmat, and binary data after the header may hold any byte.
    io::TextReader reader(path, false);
    if (!reader.next_line()) reader.fail_file("empty file; expected the header 'cols rows'");
    const auto& header = reader.tokens();
    if (header.size() != 2)
        reader.fail("expected the header 'cols rows', found " + io::quote(reader.line()));
    const int cols = reader.to_count(header[0], "column count");
    const int rows = reader.to_count(header[1], "row count");
    if (rows == 0 && cols == 0) {
        if (reader.next_line())
            reader.fail_file("binary .dmat (header '0 0'); only ASCII .dmat is supported");
        return Eigen::MatrixXd(0, 0);
    }
    Eigen::MatrixXd matrix(rows, cols);
    const long long total = static_cast<long long>(rows) * cols;
    std::string_view token;
    for (long long i = 0; i < total; ++i) {
        if (!reader.next_token(token))
            reader.fail_file("file ends after " + std::to_string(i) + " of " +
                             std::to_string(total) + " values (" + std::to_string(rows) + " x " +
                             std::to_string(cols) + ")");
        matrix(static_cast<Eigen::Index>(i % rows), static_cast<Eigen::Index>(i / rows)) =
            reader.to_double(token, "value");
    }
    if (reader.next_token(token))
        reader.fail("unexpected data " + io::quote(token) + " after the " + std::to_string(total) +
                    " values of a " + std::to_string(rows) + " x " + std::to_string(cols) +
                    " matrix");
    return matrix;
}

void write_dmat(const std::string& path, const Eigen::MatrixXd& matrix) {
    for (Eigen::Index j = 0; j < matrix.cols(); ++j) {
        for (Eigen::Index i = 0; i < matrix.rows(); ++i) {
            if (!std::isfinite(matrix(i, j))) {
                std::ostringstream message;
                message << "write_dmat: entry (" << i << ", " << j << ") is not finite ("
                        << matrix(i, j) << ")";
                throw InvalidArgumentError(message.str());
            }
        }
    }
    AtomicFile file(path);
    std::ostream& out = file.stream();
    out << matrix.cols() << ' ' << matrix.rows() << '\n';
    for (Eigen::Index j = 0; j < matrix.cols(); ++j)
        for (Eigen::Index i = 0; i < matrix.rows(); ++i) out << matrix(i, j) << '\n';
    file.commit();
}

}  // namespace sa
