#include "geometry/io/frame_field_io.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <limits>
#include <sstream>
#include <utility>

#include "geometry/io/dmat_io.h"
#include "geometry/io/rawfield_io.h"
#include "geometry/io/text_reader.h"
#include "optim/errors.h"

namespace sa {
namespace {

constexpr int kMaxVectors = 4;

// Names row `row` of the file in messages: "FILE: row 17" (.dmat) or "FILE:LINE" (.crossfield).
using Where = std::function<std::string(Eigen::Index row)>;

Where dmat_rows(const std::string& path) {
    return [path](Eigen::Index row) { return path + ": row " + std::to_string(row); };
}

[[noreturn]] void fail(const std::string& where, const std::string& what) {
    throw InputError(where + ": " + what);
}

std::string number(double value) {
    std::ostringstream out;
    out << std::setprecision(std::numeric_limits<double>::max_digits10) << value;
    return out.str();
}

std::string shape(Eigen::Index rows, Eigen::Index cols) {
    return std::to_string(rows) + " rows x " + std::to_string(cols) + " columns";
}

const char* ordinal(int j) {
    static const char* const kNames[kMaxVectors] = {"first", "second", "third", "fourth"};
    return kNames[j];
}

FrameFieldFile empty_field(Index num_faces, int k, std::string layout) {
    FrameFieldFile field;
    field.vectors = Eigen::MatrixXd::Zero(num_faces, 3 * k);
    field.given.assign(static_cast<std::size_t>(num_faces), 0);
    field.constrained.assign(static_cast<std::size_t>(num_faces), 0);
    field.layout = std::move(layout);
    return field;
}

// Copies the k vectors `values` (1 x 3k) of row `row` to face `face`; returns whether the face is
// given. The readers have already rejected values that are not finite.
bool set_face(FrameFieldFile& field, Index face, const Eigen::Ref<const Eigen::RowVectorXd>& values,
              const Where& where, Eigen::Index row) {
    const int k = static_cast<int>(values.size() / 3);
    int first_zero = -1;
    int nonzero = 0;
    for (int j = 0; j < k; ++j) {
        if ((values.segment<3>(3 * j).array() == 0.0).all()) {
            if (first_zero < 0) first_zero = j;
        } else {
            ++nonzero;
        }
    }
    if (nonzero == 0) return false;
    if (first_zero >= 0)
        fail(where(row), std::string("the ") + ordinal(first_zero) + " of " + std::to_string(k) +
                             " vectors is zero while the face's other vectors are not");
    field.vectors.row(face) = values;
    field.given[static_cast<std::size_t>(face)] = 1;
    return true;
}

// One row per face: an optional flag column, then the k vectors.
FrameFieldFile read_dense(const Eigen::MatrixXd& matrix, bool flagged, const Where& where,
                          std::string layout) {
    const Eigen::Index first = flagged ? 1 : 0;
    const int k = static_cast<int>((matrix.cols() - first) / 3);
    FrameFieldFile field = empty_field(static_cast<Index>(matrix.rows()), k, std::move(layout));
    for (Eigen::Index row = 0; row < matrix.rows(); ++row) {
        const auto face = static_cast<Index>(row);
        const double flag = flagged ? matrix(row, 0) : 0.0;
        if (flag != 0.0 && flag != 1.0)
            fail(where(row), "flag (column 0) is " + number(flag) + "; expected 0 or 1");
        const bool given = set_face(field, face, matrix.row(row).tail(3 * k), where, row);
        if (flag == 1.0 && !given)
            fail(where(row), "flagged as constrained but its vectors are all zero");
        field.constrained[static_cast<std::size_t>(face)] = flag == 1.0 ? 1 : 0;
    }
    return field;
}

// A list of faces (0-based indices stored as doubles) with their vectors, row by row.
FrameFieldFile read_list(const Eigen::VectorXd& faces, const Eigen::MatrixXd& vectors,
                         Index num_faces, const Where& where_index, const Where& where_vectors,
                         std::string layout) {
    const int k = static_cast<int>(vectors.cols() / 3);
    FrameFieldFile field = empty_field(num_faces, k, std::move(layout));
    std::vector<Eigen::Index> row_of(static_cast<std::size_t>(num_faces), -1);
    for (Eigen::Index row = 0; row < faces.size(); ++row) {
        const double value = faces(row);
        if (value != std::floor(value))
            fail(where_index(row), "face index " + number(value) + " is not an integer");
        if (value < 0 || value >= num_faces)
            fail(where_index(row), "face index " + number(value) +
                                       " is out of range (the mesh has " +
                                       std::to_string(num_faces) + " faces)");
        const auto face = static_cast<Index>(value);
        Eigen::Index& first_row = row_of[static_cast<std::size_t>(face)];
        if (first_row >= 0)
            fail(where_index(row), "face " + std::to_string(face) +
                                       " is listed again (first in row " +
                                       std::to_string(first_row) + ")");
        first_row = row;
        if (!set_face(field, face, vectors.row(row), where_vectors, row))
            fail(where_vectors(row),
                 "the vectors of face " + std::to_string(face) + " are all zero");
        field.constrained[static_cast<std::size_t>(face)] = 1;
    }
    return field;
}

bool opposite(const Eigen::RowVector3d& a, const Eigen::RowVector3d& b) {
    return (a + b).norm() <= 1e-6 * std::max(a.norm(), b.norm());
}

// Sets u and v from the vectors and checks that some face is given.
FrameFieldFile finish(FrameFieldFile field, const std::string& path) {
    const Eigen::Index k = field.vectors.cols() / 3;
    field.u = field.vectors.leftCols(3);
    bool frame = k == 2;
    if (k == 4) {  // u, v, -u, -v: a frame written as a symmetric 4-PolyVector
        frame = true;
        for (Eigen::Index f = 0; f < field.vectors.rows() && frame; ++f) {
            if (!field.given[static_cast<std::size_t>(f)]) continue;
            const auto row = field.vectors.row(f);
            frame = opposite(row.segment<3>(0), row.segment<3>(6)) &&
                    opposite(row.segment<3>(3), row.segment<3>(9));
        }
    }
    if (frame)
        field.v = field.vectors.middleCols(3, 3);
    else
        field.v.resize(0, 3);
    if (std::find(field.given.begin(), field.given.end(), 1) == field.given.end())
        throw InputError(path + ": no face has a nonzero vector");
    return field;
}

void check_face_count(const char* function, Index num_faces) {
    if (num_faces < 0)
        throw InvalidArgumentError(std::string(function) + ": num_faces is " +
                                   std::to_string(num_faces) + "; expected >= 0");
}

// True when `column` holds each of 0 .. size-1 once and some value above 1 (so that it is not a
// column of 0/1 flags).
bool is_index_permutation(const Eigen::VectorXd& column) {
    std::vector<unsigned char> seen(static_cast<std::size_t>(column.size()), 0);
    bool above_one = false;
    for (Eigen::Index i = 0; i < column.size(); ++i) {
        const double value = column(i);
        if (value != std::floor(value) || value < 0 || value >= static_cast<double>(column.size()))
            return false;
        unsigned char& s = seen[static_cast<std::size_t>(value)];
        if (s) return false;
        s = 1;
        above_one = above_one || value > 1;
    }
    return above_one;
}

FrameFieldFile read_crossfield(const std::string& path, Index num_faces) {
    io::TextReader reader(path, false);
    const std::string expected_header = "the header 'k #F' (vectors per face, faces)";
    if (!reader.next_line()) reader.fail_file("empty file; expected " + expected_header);
    const auto& header = reader.tokens();
    if (header.size() != 2)
        reader.fail("expected " + expected_header + ", found " + io::quote(reader.line()));
    const int k = reader.to_count(header[0], "vector count");
    const int faces = reader.to_count(header[1], "face count");
    if (k < 1 || k > kMaxVectors)
        reader.fail("vector count " + std::to_string(k) + "; expected 1 to " +
                    std::to_string(kMaxVectors) + " vectors per face");
    if (faces != num_faces)
        reader.fail("header gives " + std::to_string(faces) + " faces; expected " +
                    std::to_string(num_faces) + " (one per face of the mesh)");
    const int cols = 1 + 3 * k;
    Eigen::MatrixXd matrix(faces, cols);
    std::vector<int> lines(static_cast<std::size_t>(faces));
    for (int f = 0; f < faces; ++f) {
        if (!reader.next_line())
            reader.fail_file("file ends after " + std::to_string(f) + " of " +
                             std::to_string(faces) + " faces");
        const auto& tokens = reader.tokens();
        if (static_cast<int>(tokens.size()) != cols)
            reader.fail("expected " + std::to_string(cols) + " numbers (a flag, then " +
                        std::to_string(k) + " vectors), found " + std::to_string(tokens.size()));
        for (int c = 0; c < cols; ++c)
            matrix(f, c) =
                reader.to_double(tokens[static_cast<std::size_t>(c)], c == 0 ? "flag" : "value");
        lines[static_cast<std::size_t>(f)] = reader.line_number();
    }
    if (reader.next_line())
        reader.fail("unexpected data after the " + std::to_string(faces) + " faces");
    const Where where = [&path, &lines](Eigen::Index row) {
        return path + ":" + std::to_string(lines[static_cast<std::size_t>(row)]);
    };
    return finish(read_dense(matrix, true, where,
                             ".crossfield: flag + " + std::to_string(k) + " vectors per face"),
                  path);
}

}  // namespace

FrameFieldFile read_frame_field(const std::string& path, Index num_faces) {
    check_face_count("read_frame_field", num_faces);
    if (io::lower_extension(path) == ".crossfield") return read_crossfield(path, num_faces);
    if (io::lower_extension(path) == ".rawfield") return read_rawfield(path, num_faces);

    const Eigen::MatrixXd matrix = read_dmat(path);
    const Eigen::Index rows = matrix.rows();
    const Eigen::Index cols = matrix.cols();
    const Where where = dmat_rows(path);
    const bool list = cols == 7 && rows > 0 && rows <= num_faces &&
                      (rows < num_faces || is_index_permutation(matrix.col(0)));
    if (list)
        return finish(read_list(matrix.col(0), matrix.rightCols(6), num_faces, where, where,
                                "face-index list: face, u, v"),
                      path);
    if (rows == num_faces && rows > 0) {
        if (cols == 3) return finish(read_dense(matrix, false, where, "one vector per face"), path);
        if (cols == 6) return finish(read_dense(matrix, false, where, "u, v per face"), path);
        if (cols >= 4 && cols <= 1 + 3 * kMaxVectors && (cols - 1) % 3 == 0)
            return finish(
                read_dense(matrix, true, where,
                           "flag + " + std::to_string((cols - 1) / 3) + " vectors per face"),
                path);
    }
    throw InputError(path + ": " + shape(rows, cols) + "; expected " + std::to_string(num_faces) +
                     " rows (one per face of the mesh) with 3, 6 or 1+3k columns (k = 1 to " +
                     std::to_string(kMaxVectors) + "), or a face-index list of at most " +
                     std::to_string(num_faces) + " rows with 7 columns");
}

FrameFieldFile read_frame_field_constraints(const std::string& b_path, const std::string& bc_path,
                                            Index num_faces) {
    check_face_count("read_frame_field_constraints", num_faces);
    const Eigen::MatrixXd b = read_dmat(b_path);
    if (b.cols() != 1 || b.rows() == 0 || b.rows() > num_faces)
        throw InputError(b_path + ": " + shape(b.rows(), b.cols()) +
                         "; expected one column of 1 to " + std::to_string(num_faces) +
                         " face indices (one per constrained face of the mesh)");
    const Eigen::MatrixXd bc = read_dmat(bc_path);
    if (bc.rows() != b.rows() || (bc.cols() != 3 && bc.cols() != 6))
        throw InputError(bc_path + ": " + shape(bc.rows(), bc.cols()) + "; expected " +
                         std::to_string(b.rows()) + " rows (one per face listed in " + b_path +
                         ") with 3 or 6 columns");
    const std::string layout =
        bc.cols() == 3 ? "face list + one vector per face" : "face list + u, v per face";
    return finish(read_list(b.col(0), bc, num_faces, dmat_rows(b_path), dmat_rows(bc_path), layout),
                  bc_path);
}

}  // namespace sa
