#include "geometry/io/openmesh_plugin.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include "geometry/io/openmesh_traits.h"
#include "geometry/io/text_reader.h"
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

// The number of faces an STL file declares: a binary STL's triangle count, or an ASCII STL's
// `facet` lines.
long long declared_faces(const std::string& path, bool binary) {
    if (binary) {
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
        std::string first;
        words >> first;
        if (first == "facet") ++faces;
    }
    return faces;
}

// What an STL file must start with before OpenMesh reads it (its messages for a file of another
// kind are vague, and its ASCII reader takes any text for an empty mesh): ASCII (`solid`) or
// binary (84 + 50 N bytes).
void check_stl_start(const std::string& path, bool binary) {
    if (binary) return;
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
    if (first.compare(begin, 5, "solid") != 0) {
        std::error_code error;
        const auto size = std::filesystem::file_size(path, error);
        throw InputError(path + ": not an STL file: neither ASCII ('solid' on line 1, found " +
                         shown + ") nor binary (84 + 50 x the triangle count bytes; the file has " +
                         std::to_string(error ? 0 : size) + ")");
    }
}

MeshFile read_stl_file(const std::string& path) {
    io::check_readable(path);
    const bool binary = is_binary_stl(path);
    check_stl_start(path, binary);
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
        ok = OpenMesh::IO::read_mesh(mesh, in, "stl", options);
        messages = capture.lines();
    }
    const std::string said = messages.empty() ? "" : " (OpenMesh: " + messages.front() + ")";
    if (!ok) throw InputError(path + ": cannot read as STL" + said);

    const long long declared = declared_faces(path, binary);
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

}  // namespace

}  // namespace sa

extern "C" const sa::OpenMeshFunctions* sa_openmesh_functions() {
    static const sa::OpenMeshFunctions table{sa::read_stl_file, sa::loop_subdivide_with_openmesh};
    return &table;
}
