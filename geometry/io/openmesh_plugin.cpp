#include "geometry/openmesh_plugin.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "geometry/io/text_reader.h"
#include "geometry/openmesh_traits.h"
#include "optim/errors.h"

namespace sa {
namespace {

// A polygon mesh, so that a non-triangular face is reported rather than triangulated.
using Mesh = OpenMesh::PolyMesh_ArrayKernelT<OpenMeshDoubleTraits>;

// OpenMesh's streams are global: one capture at a time.
std::mutex& capture_mutex() {
    static std::mutex mutex;
    return mutex;
}

// Redirects omerr(), omout() and omlog() into a string while alive (they write to std::cerr,
// std::cout and std::clog by default), and restores them afterwards.
class OpenMeshCapture {
  public:
    OpenMeshCapture() : lock_(capture_mutex()) {
        for (int s = 0; s < 3; ++s) {
            OpenMesh::mostream& stream = this->stream(s);
            enabled_[s] = stream.is_enabled();
            connected_[s][0] = stream.disconnect(std::cerr);
            connected_[s][1] = stream.disconnect(std::cout);
            connected_[s][2] = stream.disconnect(std::clog);
            stream.connect(text_);
            stream.enable();
        }
    }
    ~OpenMeshCapture() {
        for (int s = 0; s < 3; ++s) {
            OpenMesh::mostream& stream = this->stream(s);
            stream.flush();
            stream.disconnect(text_);
            if (connected_[s][0]) stream.connect(std::cerr);
            if (connected_[s][1]) stream.connect(std::cout);
            if (connected_[s][2]) stream.connect(std::clog);
            if (!enabled_[s]) stream.disable();
        }
    }
    OpenMeshCapture(const OpenMeshCapture&) = delete;
    OpenMeshCapture& operator=(const OpenMeshCapture&) = delete;

    /// The lines written so far.
    std::vector<std::string> lines() {
        for (int s = 0; s < 3; ++s) stream(s).flush();
        std::vector<std::string> result;
        std::istringstream in(text_.str());
        for (std::string line; std::getline(in, line);) {
            while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
            if (!line.empty()) result.push_back(line);
        }
        return result;
    }

  private:
    static OpenMesh::mostream& stream(int s) {
        return s == 0 ? omerr() : s == 1 ? omout() : omlog();
    }

    std::lock_guard<std::mutex> lock_;
    std::ostringstream text_;
    bool enabled_[3] = {};
    bool connected_[3][3] = {};
};

// True for a binary STL: 80 header bytes, a triangle count and 50 bytes per triangle.
bool is_binary_stl(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char header[84] = {};
    if (!in.read(header, 84)) return false;
    const auto size = std::filesystem::file_size(path);
    const std::uint32_t count =
        static_cast<std::uint32_t>(static_cast<unsigned char>(header[80])) |
        static_cast<std::uint32_t>(static_cast<unsigned char>(header[81])) << 8 |
        static_cast<std::uint32_t>(static_cast<unsigned char>(header[82])) << 16 |
        static_cast<std::uint32_t>(static_cast<unsigned char>(header[83])) << 24;
    return size == 84 + 50 * static_cast<std::uintmax_t>(count);
}

// The number of faces the file declares: PLY's `element face N`, a binary STL's triangle count,
// or an ASCII STL's `facet` lines.
long long declared_faces(const std::string& path, bool stl, bool binary) {
    if (stl && binary) {
        std::ifstream in(path, std::ios::binary);
        unsigned char count[4] = {};
        in.seekg(80);
        in.read(reinterpret_cast<char*>(count), 4);
        return static_cast<long long>(count[0]) | static_cast<long long>(count[1]) << 8 |
               static_cast<long long>(count[2]) << 16 | static_cast<long long>(count[3]) << 24;
    }
    std::ifstream in(path, std::ios::binary);
    long long faces = 0;
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string first, second;
        words >> first >> second;
        if (stl) {
            if (first == "facet") ++faces;
        } else if (first == "element" && second == "face") {
            words >> faces;
        } else if (first == "end_header") {
            break;
        }
    }
    return faces;
}

// What a file must start with before OpenMesh reads it (its messages for a file of another kind
// are vague, and an ASCII STL reader takes any text for an empty mesh): PLY's magic line `ply`;
// an STL either ASCII (`solid`) or binary (84 + 50 N bytes).
void check_start(const std::string& path, bool stl, bool binary_stl) {
    if (binary_stl) return;
    std::ifstream in(path, std::ios::binary);
    std::string first;
    std::getline(in, first);
    if (!first.empty() && first.back() == '\r') first.pop_back();
    std::size_t begin = 0;
    while (begin < first.size() && (first[begin] == ' ' || first[begin] == '\t')) ++begin;
    bool text = true;
    for (const char c : first) {
        const auto u = static_cast<unsigned char>(c);
        text = text && !((u < 0x20 && c != '\t') || u == 0x7f);
    }
    const std::string shown = text ? io::quote(first) : std::string("binary data");
    if (!stl && first != "ply")
        throw InputError(path + ":1: not a PLY file: expected 'ply', found " + shown);
    if (stl && first.compare(begin, 5, "solid") != 0) {
        std::error_code error;
        const auto size = std::filesystem::file_size(path, error);
        throw InputError(path + ": not an STL file: neither ASCII ('solid' on line 1, found " +
                         shown + ") nor binary (84 + 50 x the triangle count bytes; the file has " +
                         std::to_string(error ? 0 : size) + ")");
    }
}

// An ASCII PLY body against its header's `layout` (per element its count and per property 0 for
// a scalar or the largest list length its count type allows), read from `in` after the header:
// every scalar a number, every list a length within its type and no longer than what is left
// of the file, then that many numbers. OpenMesh's reader reserves what a list length says before
// reading it (`0 1888...83 1 1` after a short vertex row: an allocation past 2 GB found by
// fuzzing).
void check_ascii_ply_body(const std::string& path, std::istream& in, int header_lines,
                          const std::vector<std::pair<long long, std::vector<long long>>>& layout) {
    std::vector<std::string> tokens;
    for (std::string token; in >> token;) tokens.push_back(std::move(token));
    std::size_t next = 0;
    const auto fail = [&](const std::string& what) {
        throw InputError(path + ": the PLY body (after line " + std::to_string(header_lines) +
                         ") " + what);
    };
    const auto number = [&]() {
        if (next >= tokens.size()) fail("is cut short");
        const std::string& t = tokens[next++];
        char* end = nullptr;
        std::strtod(t.c_str(), &end);
        if (t.empty() || *end != '\0')
            fail("holds '" + t.substr(0, 40) + "' where a number belongs");
        return t;
    };
    for (const auto& [count, properties] : layout) {
        for (long long row = 0; row < count; ++row) {
            for (const long long largest : properties) {
                if (largest == 0) {
                    number();
                    continue;
                }
                const std::string length = number();
                const bool whole = std::all_of(length.begin(), length.end(), [](char c) {
                    return std::isdigit(static_cast<unsigned char>(c));
                });
                if (!whole || length.size() > 10 || std::stoll(length) > largest ||
                    static_cast<unsigned long long>(std::stoll(length)) > tokens.size() - next)
                    fail("has a list of length '" + length.substr(0, 40) +
                         "': not a whole number its type allows, or longer than the file");
                for (long long k = std::stoll(length); k > 0; --k) number();
            }
        }
    }
}

// A PLY header's lines, checked before OpenMesh parses it (its reader writes through a missing
// element when a `property` line comes before any `element` line: a crash found by fuzzing):
// each line a known keyword, one well-formed `format` line, every property after an element, an
// element's count a number, and an `end_header` line.
void check_ply_header(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string line;
    std::getline(in, line);  // `ply`, checked by check_start
    bool element = false, format_seen = false, ascii = false;
    std::set<std::string> elements;
    // Per element: its count and, per property, the largest list length its count type allows
    // (0 for a scalar property).
    std::vector<std::pair<long long, std::vector<long long>>> layout;
    for (int number = 2; std::getline(in, line); ++number) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream words(line);
        std::string keyword, name;
        words >> keyword;
        const auto fail = [&](const std::string& what) {
            throw InputError(path + ":" + std::to_string(number) + ": " + what);
        };
        if (keyword == "end_header") {
            if (ascii) check_ascii_ply_body(path, in, number, layout);
            return;
        }
        if (keyword == "format") {
            // `format FORMAT VERSION`: OpenMesh's reader loops for ever on a version that is not
            // a number (`format ascii float z`: found by fuzzing).
            std::string type, version, extra;
            words >> type >> version;
            char* end = nullptr;
            // PLY has one version, 1.0 (a version of 150 digits made OpenMesh's warnings grow
            // past 2 GB: found by fuzzing).
            const bool number = !version.empty() && version.size() <= 8 &&
                                std::strtod(version.c_str(), &end) == 1.0 && *end == '\0' &&
                                std::isdigit(static_cast<unsigned char>(version[0]));
            if ((type != "ascii" && type != "binary_little_endian" &&
                 type != "binary_big_endian") ||
                !number || (words >> extra))
                fail(
                    "expected 'format ascii|binary_little_endian|binary_big_endian 1.0' in the "
                    "PLY header");
            if (format_seen) fail("a second 'format' line in the PLY header");
            format_seen = true;
            ascii = type == "ascii";
        } else if (keyword == "element") {
            // The count a whole word of digits, nothing after it: `element face 1property ...`
            // read as a count of 1 made OpenMesh allocate without bound (found by fuzzing).
            std::string count, extra;
            words >> name >> count;
            if (name.empty() || count.empty() || count.size() > 18 ||
                !std::all_of(count.begin(), count.end(),
                             [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }) ||
                (words >> extra))
                fail("expected 'element NAME COUNT' in the PLY header");
            if (!elements.insert(name).second) fail("a second PLY element '" + name + "'");
            element = true;
            layout.push_back({std::stoll(count), {}});
        } else if (keyword == "property") {
            if (!element) fail("a PLY property before any element");
            // `property TYPE NAME` or `property list COUNT_TYPE TYPE NAME`, with PLY's types
            // (OpenMesh's reader can run for minutes on a header it half understands: found by
            // fuzzing).
            static const std::set<std::string> kTypes = {
                "char", "uchar", "short", "ushort", "int",   "uint",   "float",   "double",
                "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64"};
            std::vector<std::string> rest;
            for (std::string word; words >> word;) rest.push_back(word);
            const bool list = !rest.empty() && rest[0] == "list";
            const bool well_formed =
                list ? rest.size() == 4 && kTypes.count(rest[1]) != 0 && kTypes.count(rest[2]) != 0
                     : rest.size() == 2 && kTypes.count(rest[0]) != 0;
            if (!well_formed)
                fail(
                    "expected 'property TYPE NAME' or 'property list TYPE TYPE NAME' with PLY "
                    "types (char, uchar, ..., float, double)");
            const std::string& count_type = list ? rest[1] : rest[0];
            const bool small = count_type == "char" || count_type == "uchar" ||
                               count_type == "int8" || count_type == "uint8";
            const bool medium = count_type == "short" || count_type == "ushort" ||
                                count_type == "int16" || count_type == "uint16";
            layout.back().second.push_back(!list ? 0 : small ? 255 : medium ? 65535 : 1LL << 31);
        } else if (keyword != "comment" && keyword != "obj_info" && !keyword.empty()) {
            std::string shown;
            for (const char c : keyword.substr(0, 40)) {
                const auto u = static_cast<unsigned char>(c);
                shown += u < 0x20 || u >= 0x7f ? '?' : c;
            }
            fail("not a PLY header line: '" + shown + "'");
        }
    }
    throw InputError(path + ": the PLY header has no 'end_header' line");
}

MeshFile read_with_openmesh(const std::string& path, const char* format) {
    io::check_readable(path);
    const bool stl = std::string(format) == "STL";
    const bool binary = stl && is_binary_stl(path);
    check_start(path, stl, binary);
    if (!stl) check_ply_header(path);
    Mesh mesh;
    // With status attributes, OpenMesh marks the faces it had to detach to keep the mesh
    // manifold (it re-adds them on duplicated vertices instead of failing).
    mesh.request_vertex_status();
    mesh.request_face_status();
    mesh.request_edge_status();
    OpenMesh::IO::Options options;
    if (binary) options += OpenMesh::IO::Options::Binary;
    bool ok = false;
    std::vector<std::string> messages;
    {
        OpenMeshCapture capture;
        std::ifstream in(path, std::ios::binary);
        ok = OpenMesh::IO::read_mesh(mesh, in, stl ? "stl" : "ply", options);
        messages = capture.lines();
    }
    const std::string said = messages.empty() ? "" : " (OpenMesh: " + messages.front() + ")";
    if (!ok) throw InputError(path + ": cannot read as " + format + said);

    const long long declared = declared_faces(path, stl, binary);
    const auto read = static_cast<long long>(mesh.n_faces());
    if (read < declared) {
        const long long dropped = declared - read;
        throw InputError(path + ": OpenMesh dropped " + std::to_string(dropped) + " of " +
                         std::to_string(declared) + (declared == 1 ? " face" : " faces") + said +
                         "; faces need 3 distinct vertices in range");
    }
    long long detached = 0;
    for (const auto face : mesh.faces())
        if (mesh.status(face).fixed_nonmanifold()) ++detached;
    if (detached > 0) {
        throw InputError(path + ": OpenMesh refused " + std::to_string(detached) + " of " +
                         std::to_string(read) + (read == 1 ? " face" : " faces") +
                         " as non-manifold (complex edge or vertex)" + said +
                         "; only manifold triangle meshes are read");
    }

    MeshFile result;
    result.mesh.vertices.resize(static_cast<Eigen::Index>(mesh.n_vertices()), 3);
    for (const auto vertex : mesh.vertices()) {
        const auto& p = mesh.point(vertex);
        for (int j = 0; j < 3; ++j) result.mesh.vertices(vertex.idx(), j) = p[j];
    }
    result.mesh.simplices.resize(static_cast<Eigen::Index>(mesh.n_faces()), 3);
    for (const auto face : mesh.faces()) {
        const int valence = static_cast<int>(face.valence());
        if (valence != 3)
            throw InputError(path + ": face " + std::to_string(face.idx()) + " with " +
                             std::to_string(valence) + " vertices; only triangles are supported");
        int c = 0;
        for (const auto vertex : face.vertices())
            result.mesh.simplices(face.idx(), c++) = vertex.idx();
    }
    return result;
}

MeshFile read_ply_file(const std::string& path) {
    return read_with_openmesh(path, "PLY");
}

MeshFile read_stl_file(const std::string& path) {
    return read_with_openmesh(path, "STL");
}

}  // namespace

}  // namespace sa

extern "C" const sa::OpenMeshFunctions* sa_openmesh_functions() {
    static const sa::OpenMeshFunctions table{sa::read_ply_file, sa::read_stl_file,
                                             sa::loop_subdivide_with_openmesh};
    return &table;
}
