#include "geometry/io/rawfield_io.h"

#include <algorithm>

#include "geometry/io/text_reader.h"
#include "optim/errors.h"

namespace sa {

namespace {

bool opposite(const Eigen::RowVector3d& a, const Eigen::RowVector3d& b) {
    return (a + b).norm() <= 1e-6 * std::max(a.norm(), b.norm());
}

}  // namespace

FrameFieldFile read_rawfield(const std::string& path, Index num_faces) {
    if (num_faces < 0) {
        throw InvalidArgumentError("read_rawfield: num_faces is " + std::to_string(num_faces) +
                                   "; expected >= 0");
    }
    io::TextReader reader(path, false);
    const std::string expected_header = "the header 'N #F' (vectors per face, faces)";
    if (!reader.next_line()) reader.fail_file("empty file; expected " + expected_header);
    const auto& header = reader.tokens();
    if (header.size() != 2)
        reader.fail("expected " + expected_header + ", found " + io::quote(reader.line()));
    const int n = reader.to_count(header[0], "vector count N");
    const int faces = reader.to_count(header[1], "face count");
    if (n != 4) {
        reader.fail("N = " + std::to_string(n) +
                    " vectors per face; a frame field is written with N = 4 (u, v, -u, -v): "
                    "other fields cannot drive a seamless parameterization");
    }
    if (faces != num_faces) {
        reader.fail("header gives " + std::to_string(faces) + " faces; expected " +
                    std::to_string(num_faces) + " (one per face of the mesh)");
    }
    FrameFieldFile field;
    field.vectors = Eigen::MatrixXd::Zero(faces, 3 * n);
    field.given.assign(static_cast<std::size_t>(faces), 0);
    field.constrained.assign(static_cast<std::size_t>(faces), 0);
    field.layout = ".rawfield: N = 4 vectors per face (u, v, -u, -v)";
    for (int f = 0; f < faces; ++f) {
        if (!reader.next_line()) {
            reader.fail_file("file ends after " + std::to_string(f) + " of " +
                             std::to_string(faces) + " faces");
        }
        const auto& tokens = reader.tokens();
        if (static_cast<int>(tokens.size()) != 3 * n) {
            reader.fail("face " + std::to_string(f) + ": expected " + std::to_string(3 * n) +
                        " numbers (" + std::to_string(n) + " vectors of 3 coordinates), found " +
                        std::to_string(tokens.size()));
        }
        Eigen::RowVectorXd row(3 * n);
        for (int c = 0; c < 3 * n; ++c)
            row[c] = reader.to_double(tokens[static_cast<std::size_t>(c)], "coordinate");
        int zero = 0;
        for (int j = 0; j < n; ++j) zero += (row.segment<3>(3 * j).array() == 0.0).all();
        if (zero == n) continue;  // a free face
        if (zero > 0) {
            reader.fail("face " + std::to_string(f) + ": " + std::to_string(zero) + " of its " +
                        std::to_string(n) + " vectors are zero while the others are not");
        }
        if (!opposite(row.segment<3>(0), row.segment<3>(6)) ||
            !opposite(row.segment<3>(3), row.segment<3>(9))) {
            reader.fail("face " + std::to_string(f) +
                        ": the third and fourth vectors are not -u and -v (the first two): not a "
                        "frame field");
        }
        field.vectors.row(f) = row;
        field.given[static_cast<std::size_t>(f)] = 1;
    }
    if (reader.next_line())
        reader.fail("unexpected data after the " + std::to_string(faces) + " faces");
    if (std::find(field.given.begin(), field.given.end(), 1) == field.given.end())
        reader.fail_file("no face has a nonzero vector");
    field.u = field.vectors.leftCols(3);
    field.v = field.vectors.middleCols(3, 3);
    return field;
}

}  // namespace sa
