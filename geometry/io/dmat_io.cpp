#include "geometry/io/dmat_io.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/io/atomic_file.h"
#include "geometry/io/text_reader.h"
#include "optim/errors.h"

namespace sa {
namespace {

std::string shape(long long rows, long long cols) {
    return std::to_string(rows) + " x " + std::to_string(cols);
}

// The whitespace-separated tokens of `line`.
std::vector<std::string_view> split(std::string_view line) {
    std::vector<std::string_view> tokens;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        const std::size_t start = i;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i > start) tokens.push_back(line.substr(start, i - start));
    }
    return tokens;
}

// A count in [0, INT_MAX], or -1 when `token` is not one.
long long parse_count(std::string_view token) {
    long long value = -1;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size() || value < 0 ||
        value > std::numeric_limits<int>::max())
        return -1;
    return value;
}

static_assert(std::numeric_limits<double>::is_iec559 && sizeof(double) == 8,
              "binary .dmat holds IEEE doubles");

// The binary layout, once read_dmat has seen the first line `0 0` and data after it.
Eigen::MatrixXd read_binary_dmat(const std::string& path) {
    io::check_readable(path);
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw InputError(path + ": cannot read");
    const std::size_t first_end = bytes.find('\n');
    const std::size_t second_end =
        first_end == std::string::npos ? std::string::npos : bytes.find('\n', first_end + 1);
    if (second_end == std::string::npos)
        throw InputError(path + ":2: binary .dmat (header '0 0') without a second header line " +
                         "'cols rows'");
    const std::string_view second(bytes.data() + first_end + 1, second_end - first_end - 1);
    const std::vector<std::string_view> header = split(second);
    const long long cols = header.size() == 2 ? parse_count(header[0]) : -1;
    const long long rows = header.size() == 2 ? parse_count(header[1]) : -1;
    if (cols < 0 || rows < 0)
        throw InputError(path + ":2: expected the binary .dmat header 'cols rows', found " +
                         io::quote(second));

    const unsigned long long total = static_cast<unsigned long long>(rows * cols);
    const std::size_t available = bytes.size() - (second_end + 1);
    if (total > available / 8)
        throw InputError(path + ": binary data ends after " + std::to_string(available / 8) +
                         " of " + std::to_string(total) + " values (" + shape(rows, cols) + ")");
    if (available > total * 8)
        throw InputError(path + ": " + std::to_string(available - total * 8) + " bytes after the " +
                         std::to_string(total) + " values of a " + shape(rows, cols) +
                         " binary matrix");

    Eigen::MatrixXd matrix(rows, cols);
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data() + second_end + 1);
    for (unsigned long long i = 0; i < total; ++i) {
        std::uint64_t bits = 0;
        for (int b = 0; b < 8; ++b) bits |= static_cast<std::uint64_t>(data[8 * i + b]) << (8 * b);
        double value = 0;
        std::memcpy(&value, &bits, sizeof value);
        const auto row = static_cast<Eigen::Index>(i % rows);
        const auto col = static_cast<Eigen::Index>(i / rows);
        if (!std::isfinite(value)) {
            std::ostringstream message;
            message << path << ": value (" << row << ", " << col << ") is not finite (" << value
                    << ")";
            throw InputError(message.str());
        }
        matrix(row, col) = value;
    }
    return matrix;
}

}  // namespace

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
        if (reader.next_line()) return read_binary_dmat(path);
        return Eigen::MatrixXd(0, 0);
    }
    const long long total = static_cast<long long>(rows) * cols;
    // A count the file cannot hold is read without storing: it fails as the file ends.
    const bool fits = reader.fitting(total, 1) == total;
    Eigen::MatrixXd matrix(fits ? rows : 0, fits ? cols : 0);
    std::string_view token;
    for (long long i = 0; i < total; ++i) {
        if (!reader.next_token(token))
            reader.fail_file("file ends after " + std::to_string(i) + " of " +
                             std::to_string(total) + " values (" + std::to_string(rows) + " x " +
                             std::to_string(cols) + ")");
        const double value = reader.to_double(token, "value");
        if (fits)
            matrix(static_cast<Eigen::Index>(i % rows), static_cast<Eigen::Index>(i / rows)) =
                value;
    }
    if (!fits) reader.check_room(total, total, "values");  // never reached: the file ended
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
