#include "geometry/io/medit_io.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "geometry/io/atomic_file.h"
#include "geometry/io/text_reader.h"
#include "geometry/io/write_checks.h"
#include "optim/errors.h"

namespace sa {
namespace {

bool same_keyword(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

// Sections skipped by their number of values per row.
constexpr std::array<std::pair<std::string_view, int>, 17> kSkipped{{
    {"Edges", 3},
    {"Corners", 1},
    {"RequiredVertices", 1},
    {"Ridges", 1},
    {"RequiredEdges", 1},
    {"RequiredTriangles", 1},
    {"RequiredQuadrilaterals", 1},
    {"RequiredTetrahedra", 1},
    {"RequiredHexahedra", 1},
    {"Quadrilaterals", 5},
    {"Hexahedra", 9},
    {"Prisms", 7},
    {"Pyramids", 6},
    {"Normals", 3},
    {"Tangents", 3},
    {"NormalAtVertices", 2},
    {"TangentAtVertices", 2},
}};

struct Elements {
    std::vector<int> indices;  // 1-based, as in the file
    std::vector<int> lines;    // the line of each element
    bool present = false;
};

class MeditReader {
  public:
    explicit MeditReader(const std::string& path) : reader_(path) {}

    MeshFile read() {
        MeshFile result;
        std::string_view keyword;
        while (reader_.next_token(keyword)) {
            if (same_keyword(keyword, "End")) break;
            if (same_keyword(keyword, "MeshVersionFormatted")) {
                const long long version =
                    reader_.to_integer(value("MeshVersionFormatted"), "MeshVersionFormatted");
                if (version < 1 || version > 4)
                    reader_.fail("MeshVersionFormatted " + std::to_string(version) +
                                 "; expected 1 to 4");
            } else if (same_keyword(keyword, "Dimension")) {
                const long long dimension = reader_.to_integer(value("Dimension"), "Dimension");
                if (dimension != 2 && dimension != 3)
                    reader_.fail("Dimension " + std::to_string(dimension) + "; expected 2 or 3");
                dimension_ = static_cast<int>(dimension);
            } else if (same_keyword(keyword, "Vertices")) {
                read_vertices();
            } else if (same_keyword(keyword, "Triangles")) {
                read_elements("Triangles", 3, triangles_);
            } else if (same_keyword(keyword, "Tetrahedra")) {
                if (dimension_ == 2) reader_.fail("Tetrahedra in a 2D mesh (Dimension 2)");
                read_elements("Tetrahedra", 4, tetrahedra_);
            } else {
                const auto skipped = std::find_if(
                    kSkipped.begin(), kSkipped.end(),
                    [&](const auto& entry) { return same_keyword(keyword, entry.first); });
                if (skipped == kSkipped.end())
                    reader_.fail("unknown keyword " + io::quote(keyword));
                const int count = skip(skipped->first, skipped->second);
                if (count > 0 &&
                    (skipped->first == "Quadrilaterals" || skipped->first == "Hexahedra" ||
                     skipped->first == "Prisms" || skipped->first == "Pyramids"))
                    result.warnings.push_back(reader_.path() + ": skipped " +
                                              std::to_string(count) + " " +
                                              std::string(skipped->first));
            }
        }

        const int num_vertices = static_cast<int>(coordinates_.size()) / 3;
        auto& mesh = result.mesh;
        mesh.vertices.resize(num_vertices, dimension_ == 0 ? 3 : dimension_);
        for (int i = 0; i < num_vertices; ++i)
            for (int j = 0; j < mesh.vertices.cols(); ++j)
                mesh.vertices(i, j) = coordinates_[3 * i + j];
        // Every section's rows must name vertices of the file, the section not kept included (the
        // boundary Triangles of a tet mesh): a row out of range is a damaged file.
        check_vertex_range(tetrahedra_, 4, num_vertices);
        check_vertex_range(triangles_, 3, num_vertices);
        const bool use_tets =
            !tetrahedra_.lines.empty() || (tetrahedra_.present && triangles_.lines.empty());
        const Elements& elements = use_tets ? tetrahedra_ : triangles_;
        const int k = use_tets ? 4 : 3;
        const int count = static_cast<int>(elements.lines.size());
        mesh.simplices.resize(count, k);
        for (int e = 0; e < count; ++e) {
            for (int c = 0; c < k; ++c) mesh.simplices(e, c) = elements.indices[k * e + c] - 1;
        }
        return result;
    }

  private:
    void check_vertex_range(const Elements& elements, int k, int num_vertices) const {
        for (std::size_t e = 0; e < elements.lines.size(); ++e) {
            for (int c = 0; c < k; ++c) {
                const int v = elements.indices[k * e + c];
                if (v > num_vertices)
                    reader_.fail_at(elements.lines[e], "vertex " + std::to_string(v) +
                                                           " out of range [1, " +
                                                           std::to_string(num_vertices) + "]");
            }
        }
    }

    // The value after a keyword (possibly on the next line).
    std::string_view value(const char* keyword) {
        std::string_view token;
        if (!reader_.next_token(token))
            reader_.fail(std::string("file ends after '") + keyword + "'; expected its value");
        return token;
    }

    int count(std::string_view keyword) {
        const std::string name(keyword);
        const int n = reader_.to_count(value(name.c_str()), (name + " count").c_str());
        if (!reader_.line_consumed())
            reader_.fail("expected the rows of " + name + " to start on the line after its count");
        return n;
    }

    // Reads the next row, which must have `size` values; returns its tokens.
    const std::vector<std::string_view>& row(std::string_view section, int index, int total,
                                             std::size_t size, const char* layout) {
        if (!reader_.next_line())
            reader_.fail_file("file ends after " + std::to_string(index) + " of " +
                              std::to_string(total) + " " + std::string(section));
        const auto& tokens = reader_.tokens();
        if (tokens.size() != size)
            reader_.fail("expected " + std::to_string(size) + " numbers (" + layout +
                         ") in a row of " + std::string(section) + ", found " +
                         std::to_string(tokens.size()));
        return tokens;
    }

    void read_vertices() {
        if (dimension_ == 0) reader_.fail("Vertices before Dimension");
        const int n = count("Vertices");
        const std::size_t size = static_cast<std::size_t>(dimension_) + 1;
        const char* layout = dimension_ == 3 ? "x y z ref" : "x y ref";
        coordinates_.reserve(coordinates_.size() +
                             3 * static_cast<std::size_t>(reader_.fitting(n, dimension_ + 1)));
        for (int i = 0; i < n; ++i) {
            const auto& tokens = row("Vertices", i, n, size, layout);
            for (int j = 0; j < dimension_; ++j)
                coordinates_.push_back(reader_.to_double(tokens[j], "coordinate"));
            if (dimension_ == 2) coordinates_.push_back(0.0);
            reader_.to_integer(tokens[dimension_], "reference");
        }
    }

    void read_elements(const char* section, int k, Elements& elements) {
        elements.present = true;
        const int n = count(section);
        const char* layout = k == 3 ? "a b c ref" : "a b c d ref";
        elements.indices.reserve(elements.indices.size() +
                                 static_cast<std::size_t>(k * reader_.fitting(n, k + 1)));
        for (int e = 0; e < n; ++e) {
            const auto& tokens = row(section, e, n, static_cast<std::size_t>(k) + 1, layout);
            for (int c = 0; c < k; ++c) {
                const long long v = reader_.to_integer(tokens[c], "vertex index");
                if (v < 1 || v > std::numeric_limits<int>::max())
                    reader_.fail("vertex " + std::to_string(v) + " out of range (indices are " +
                                 "1-based)");
                elements.indices.push_back(static_cast<int>(v));
            }
            reader_.to_integer(tokens[k], "reference");
            elements.lines.push_back(reader_.line_number());
        }
    }

    int skip(std::string_view section, int row_size) {
        const int n = count(section);
        const long long values = static_cast<long long>(n) * row_size;
        std::string_view token;
        for (long long i = 0; i < values; ++i) {
            if (!reader_.next_token(token))
                reader_.fail_file("file ends inside " + std::string(section) + " (" +
                                  std::to_string(n) + " rows of " + std::to_string(row_size) +
                                  " values declared)");
            reader_.to_double(token, "value");
        }
        return n;
    }

    io::TextReader reader_;
    int dimension_ = 0;
    std::vector<double> coordinates_;  // 3 per vertex (z = 0 in 2D)
    Elements triangles_;
    Elements tetrahedra_;
};

}  // namespace

MeshFile read_medit(const std::string& path) {
    return MeditReader(path).read();
}

void write_medit(const std::string& path, const Eigen::MatrixXd& positions,
                 const Eigen::MatrixXi& simplices) {
    constexpr const char* kFunction = "write_medit";
    io::check_positions(kFunction, positions);
    const bool hexahedra = simplices.cols() == 8;
    io::check_simplices(kFunction, hexahedra ? "hexahedra" : "simplices", simplices,
                        positions.rows(), hexahedra ? 8 : 0);
    if (simplices.cols() >= 4 && positions.cols() != 3) {
        throw InvalidArgumentError(std::string(kFunction) + ": " +
                                   (hexahedra ? "hexahedra" : "tetrahedra") + " need 3D positions");
    }
    AtomicFile file(path);
    std::ostream& out = file.stream();
    out << "MeshVersionFormatted 2\nDimension " << positions.cols() << "\n\nVertices\n"
        << positions.rows() << '\n';
    for (Eigen::Index i = 0; i < positions.rows(); ++i) {
        io::write_position(out, positions, i, false);
        out << " 0\n";
    }
    out << '\n'
        << (hexahedra               ? "Hexahedra"
            : simplices.cols() == 4 ? "Tetrahedra"
                                    : "Triangles")
        << '\n'
        << simplices.rows() << '\n';
    for (Eigen::Index e = 0; e < simplices.rows(); ++e) {
        for (Eigen::Index c = 0; c < simplices.cols(); ++c) out << simplices(e, c) + 1 << ' ';
        out << "0\n";
    }
    out << "\nEnd\n";
    file.commit();
}

}  // namespace sa
