// read_ply (ply_io.h). The format (Greg Turk's PLY description, as written by Blender, MeshLab,
// libigl, Open3D, ...):
//   ply
//   format ascii|binary_little_endian|binary_big_endian 1.0
//   comment ... / obj_info ...
//   element NAME COUNT
//   property TYPE NAME | property list COUNT_TYPE ITEM_TYPE NAME
//   ...
//   end_header
// then, element by element in header order, COUNT rows of the element's properties (a list: its
// length, then that many items). Types: char/int8, uchar/uint8, short/int16, ushort/uint16,
// int/int32, uint/uint32, float/float32, double/float64.
#include "geometry/io/ply_io.h"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/io/byte_cursor.h"
#include "optim/errors.h"

namespace sa {
namespace {

struct PlyType {
    const char* name;
    const char* alias;
    io::BinaryType binary;
};

constexpr PlyType kPlyTypes[] = {
    {"char", "int8", {1, false, true}},    {"uchar", "uint8", {1, false, false}},
    {"short", "int16", {2, false, true}},  {"ushort", "uint16", {2, false, false}},
    {"int", "int32", {4, false, true}},    {"uint", "uint32", {4, false, false}},
    {"float", "float32", {4, true, true}}, {"double", "float64", {8, true, true}}};

/// Element counts above this are refused (a vertex or face count must fit an int).
constexpr long long kMaxCount = 2147483647;

struct Property {
    std::string name;
    io::BinaryType type;                      // the item type of a list
    std::optional<io::BinaryType> list_size;  // set for a list
};

struct Element {
    std::string name;
    long long count = 0;
    int line = 0;
    std::vector<Property> properties;
};

std::vector<std::string_view> words_of(std::string_view line) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (true) {
        i = line.find_first_not_of(" \t\r\f\v", i);
        if (i == std::string_view::npos) break;
        const std::size_t end = std::min(line.find_first_of(" \t\r\f\v", i), line.size());
        words.push_back(line.substr(i, end - i));
        i = end;
    }
    return words;
}

const PlyType* ply_type(std::string_view name) {
    for (const PlyType& type : kPlyTypes) {
        if (name == type.name || name == type.alias) return &type;
    }
    return nullptr;
}

class PlyParser {
  public:
    explicit PlyParser(std::string path) : in_(std::move(path)) {}

    MeshFile read() {
        read_header();
        const auto vertex_element =
            std::find_if(elements_.begin(), elements_.end(),
                         [](const Element& e) { return e.name == "vertex"; });
        if (vertex_element == elements_.end())
            throw InputError(in_.path() + ": no 'vertex' element in the PLY header");
        num_vertices_ = vertex_element->count;
        MeshFile result;
        for (const Element& element : elements_) read_element(element, result);
        check_end_of_body();
        result.mesh.simplices.resize(static_cast<Eigen::Index>(triangles_.size() / 3), 3);
        for (std::size_t i = 0; i < triangles_.size(); ++i)
            result.mesh.simplices(static_cast<Eigen::Index>(i / 3), static_cast<int>(i % 3)) =
                triangles_[i];
        return result;
    }

  private:
    void read_header() {
        const std::string_view first = in_.rest_of_line();
        const bool text = io::first_control_byte(first) == std::string_view::npos;
        const std::string_view magic = first.substr(0, first.find_last_not_of(" \t\r") + 1);
        if (magic != "ply")
            fail("not a PLY file: expected 'ply', found " +
                 (text ? io::quoted_bytes(first) : std::string("binary data")));
        bool format_seen = false;
        while (true) {
            in_.skip_line();
            if (in_.remaining() == 0)
                throw InputError(in_.path() + ": the PLY header has no 'end_header' line");
            const std::string_view line = in_.rest_of_line();
            const std::vector<std::string_view> words = words_of(line);
            const std::string_view keyword = words.empty() ? "" : words[0];
            if (keyword == "end_header") {
                if (words.size() != 1) fail("'end_header' with more on its line");
                if (!format_seen) fail("the PLY header has no 'format' line");
                break;
            }
            if (keyword == "format") {
                const bool known = words.size() == 3 &&
                                   (words[1] == "ascii" || words[1] == "binary_little_endian" ||
                                    words[1] == "binary_big_endian") &&
                                   (words[2] == "1.0" || words[2] == "1");
                if (!known)
                    fail(
                        "expected 'format ascii|binary_little_endian|binary_big_endian 1.0' in "
                        "the PLY header");
                if (format_seen) fail("a second 'format' line in the PLY header");
                format_seen = true;
                binary_ = words[1] != "ascii";
                big_endian_ = words[1] == "binary_big_endian";
            } else if (keyword == "element") {
                long long count = -1;
                if (words.size() == 3) {
                    try {
                        count = in_.to_integer(words[2], "element");
                    } catch (const InputError&) {
                    }
                }
                if (count < 0 || count > kMaxCount)
                    fail("expected 'element NAME COUNT' in the PLY header (COUNT from 0 to " +
                         std::to_string(kMaxCount) + ")");
                for (const Element& element : elements_) {
                    if (element.name == words[1])
                        fail("a second PLY element " + io::quoted_bytes(words[1]));
                }
                elements_.push_back({std::string(words[1]), count, in_.line(), {}});
            } else if (keyword == "property") {
                if (elements_.empty()) fail("a PLY property before any element");
                const bool list = words.size() == 5 && words[1] == "list";
                const PlyType* size = list ? ply_type(words[2]) : nullptr;
                const PlyType* type = list                ? ply_type(words[3])
                                      : words.size() == 3 ? ply_type(words[1])
                                                          : nullptr;
                if (type == nullptr || (list && (size == nullptr || size->binary.floating)))
                    fail(
                        "expected 'property TYPE NAME' or 'property list TYPE TYPE NAME' with "
                        "PLY types (char, uchar, ..., float, double; a list's length a whole "
                        "number type)");
                Property property{std::string(words.back()), type->binary, std::nullopt};
                if (list) property.list_size = size->binary;
                elements_.back().properties.push_back(property);
            } else if (keyword != "comment" && keyword != "obj_info" && !keyword.empty()) {
                fail("not a PLY header line: " + io::quoted_bytes(keyword));
            }
        }
        in_.skip_line();
        if (binary_) in_.set_binary();
    }

    /// Reads the rows of `element`, keeping the vertex positions and the face triangles.
    void read_element(const Element& element, MeshFile& result) {
        const bool vertices = element.name == "vertex";
        const bool faces = element.name == "face";
        // Where each property goes: a coordinate (0, 1, 2), the face's indices (3), nowhere (-1).
        std::vector<int> role(element.properties.size(), -1);
        std::size_t min_row = 0;  // bytes (binary) or numbers (ASCII) a row takes at least
        for (std::size_t p = 0; p < element.properties.size(); ++p) {
            const Property& property = element.properties[p];
            const bool list = property.list_size.has_value();
            if (vertices && !list && property.name.size() == 1 && property.name[0] >= 'x' &&
                property.name[0] <= 'z')
                role[p] = property.name[0] - 'x';
            if (faces && list &&
                (property.name == "vertex_indices" || property.name == "vertex_index"))
                role[p] = 3;
            min_row += binary_ ? static_cast<std::size_t>(list ? property.list_size->bytes
                                                               : property.type.bytes)
                               : 1;
        }
        for (int axis = 0; vertices && axis < 3; ++axis) {
            if (std::find(role.begin(), role.end(), axis) == role.end())
                throw InputError(in_.path() + ":" + std::to_string(element.line) +
                                 ": the vertex element has no property " +
                                 std::string(1, static_cast<char>('x' + axis)));
        }
        if (faces && std::find(role.begin(), role.end(), 3) == role.end())
            throw InputError(in_.path() + ":" + std::to_string(element.line) +
                             ": the face element has no list property vertex_indices");
        // A count the rest of the file cannot hold is refused before anything is allocated (an
        // ASCII number takes a character and a separator).
        const std::size_t room = binary_ ? in_.remaining() : in_.remaining() / 2 + 1;
        if (min_row > 0 && static_cast<unsigned long long>(element.count) > room / min_row)
            fail("the PLY body is cut short: element '" + element.name + "' declares " +
                 std::to_string(element.count) + " rows, " + std::to_string(in_.remaining()) +
                 " bytes are left");
        if (vertices) result.mesh.vertices.setZero(element.count, 3);
        if (faces) triangles_.reserve(3 * static_cast<std::size_t>(element.count));
        if (element.properties.empty()) return;
        const std::string what = "the PLY body's element '" + element.name + "'";
        for (long long row = 0; row < element.count; ++row) {
            for (std::size_t p = 0; p < element.properties.size(); ++p) {
                const Property& property = element.properties[p];
                if (!property.list_size) {
                    const double value = number(property.type, what);
                    if (role[p] >= 0) result.mesh.vertices(row, role[p]) = value;
                    continue;
                }
                const long long length = integer(*property.list_size, what + " (a list length)");
                if (role[p] == 3 && length != 3)
                    fail("face " + std::to_string(row) + " with " + std::to_string(length) +
                         " vertices; only triangles are supported");
                const std::size_t item_room =
                    binary_ ? in_.remaining() / static_cast<std::size_t>(property.type.bytes)
                            : in_.remaining() / 2 + 1;
                if (length < 0 || static_cast<unsigned long long>(length) > item_room)
                    fail(what + " has a list of length " + std::to_string(length) +
                         ", longer than the rest of the file");
                for (long long k = 0; k < length; ++k) {
                    if (role[p] != 3) {
                        number(property.type, what);
                        continue;
                    }
                    const long long v = integer(property.type, what);
                    const long long n = num_vertices_;
                    if (v < 0 || v >= n)
                        fail("face " + std::to_string(row) + " refers to vertex " +
                             std::to_string(v) + ", out of range [0, " + std::to_string(n - 1) +
                             "]");
                    for (long long j = 0; j < k; ++j) {
                        if (triangles_[triangles_.size() - 1 - static_cast<std::size_t>(j)] == v)
                            fail("face " + std::to_string(row) + " repeats vertex " +
                                 std::to_string(v));
                    }
                    triangles_.push_back(static_cast<int>(v));
                }
            }
        }
    }

    /// Nothing but whitespace may follow the last element's rows: rows beyond the header's count
    /// (a face element whose count was not updated, text appended to the file) would otherwise
    /// be dropped without a word, and the mesh read with a hole.
    void check_end_of_body() {
        const std::string_view rest = in_.bytes().substr(in_.position());
        const std::size_t data = rest.find_first_not_of(" \t\r\n\f\v");
        if (data == std::string_view::npos) return;
        const Element& last = elements_.back();
        const std::string declared = "unexpected data after the PLY body (element '" + last.name +
                                     "' declares " + std::to_string(last.count) +
                                     (last.count == 1 ? " row)" : " rows)");
        if (binary_) fail(declared + ": " + std::to_string(rest.size() - data) + " more bytes");
        fail(declared + ": " + io::quoted_bytes(in_.next_token()));
    }

    double number(const io::BinaryType& type, const std::string& what) {
        if (binary_) {
            if (in_.remaining() < static_cast<std::size_t>(type.bytes))
                fail(what + ": the PLY body is cut short");
            return in_.binary_double(type, big_endian_);
        }
        const std::string_view text = in_.next_token();
        if (text.empty()) fail(what + ": the PLY body is cut short");
        return in_.to_double(text, what);
    }

    long long integer(const io::BinaryType& type, const std::string& what) {
        if (binary_) {
            if (in_.remaining() < static_cast<std::size_t>(type.bytes))
                fail(what + ": the PLY body is cut short");
            return in_.binary_integer(type, big_endian_, what);
        }
        const std::string_view text = in_.next_token();
        if (text.empty()) fail(what + ": the PLY body is cut short");
        return in_.to_integer(text, what);
    }

    [[noreturn]] void fail(const std::string& what) const { in_.fail(what); }

    io::ByteCursor in_;
    bool binary_ = false;
    bool big_endian_ = false;
    std::vector<Element> elements_;
    long long num_vertices_ = 0;
    std::vector<int> triangles_;
};

}  // namespace

MeshFile read_ply(const std::string& path) {
    return PlyParser(path).read();
}

}  // namespace sa
