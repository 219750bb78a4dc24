#include "frontends/cli/cli_support.h"

#include <sys/resource.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>

#include "frontends/cli/out_of_memory.h"
#include "geometry/io/mesh_file.h"
#include "geometry/io/problem_io.h"
#include "optim/errors.h"

namespace sa::cli {

Eigen::MatrixXd read_positions(const std::string& path, Index expected_rows, int dimension) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    static const std::set<std::string> mesh_extensions = {".obj", ".off",  ".ply",  ".stl", ".vtk",
                                                          ".vtu", ".mesh", ".node", ".ele"};
    check_input_file(path);
    Eigen::MatrixXd positions;
    if (mesh_extensions.count(ext)) {
        positions = read_mesh_file(path).mesh.vertices;
    } else {
        std::ifstream in(path);
        if (!in) throw InputError(path + ": cannot open");
        const std::string text((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
        if (text.find("resV") != std::string::npos) {
            positions = read_result_positions(path);
        } else {
            const MeshFile problem = read_problem(path);
            positions = *problem.initial;
        }
    }
    if (positions.rows() != expected_rows) {
        throw InputError(path + ": " + std::to_string(positions.rows()) +
                         " positions, the mesh has " + std::to_string(expected_rows) + " vertices");
    }
    if (positions.cols() < dimension) {
        throw InputError(path + ": positions have " + std::to_string(positions.cols()) +
                         " coordinates, the map needs " + std::to_string(dimension));
    }
    if (positions.cols() > dimension &&
        positions.rightCols(positions.cols() - dimension).cwiseAbs().maxCoeff() > 0.0) {
        throw InputError(path + ": positions have " + std::to_string(positions.cols()) +
                         " non-zero coordinates; a map of triangles is planar (" +
                         std::to_string(dimension) + " coordinates)");
    }
    return positions.leftCols(dimension);
}

void check_output_format(const std::string& path, int dimension) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if ((ext == ".obj" || ext == ".off") && dimension != 2) {
        throw InvalidArgumentError(
            path + ": " + ext + " holds triangles; write tetrahedra as .vtu, .vtk, .mesh or .node");
    }
    if ((ext == ".node" || ext == ".ele") && dimension != 3) {
        throw InvalidArgumentError(
            path + ": " + ext +
            " holds tetrahedra; write triangles as .vtu, .vtk, .obj, .off or .mesh");
    }
    if (ext == ".ply" || ext == ".stl") {
        throw InvalidArgumentError(
            path + ": " + ext +
            " is read, not written; use .vtu, .vtk, .obj, .off, .mesh or .node");
    }
}

void require_simplices(const SimplicialMesh& mesh, const std::string& path) {
    if (mesh.num_vertices() == 0) throw InputError(path + ": the mesh has no vertices");
    if (mesh.num_simplices() == 0)
        throw InputError(path + ": the mesh has no triangles or tetrahedra");
}

MeshFile read_input_mesh(const std::string& option, const std::string& path,
                         const std::string& triangles_for) {
    set_activity("reading " + option + " " + path);
    MeshFile file = read_mesh_file(path);
    for (const std::string& warning : file.warnings)
        std::cerr << "sa: warning: " << one_line(warning) << '\n';
    require_simplices(file.mesh, path);
    if (!triangles_for.empty() && file.mesh.simplex_dimension() != 2)
        throw InputError(path + ": " + triangles_for + " needs a triangle mesh");
    return file;
}

std::string one_line(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    auto escape = [&out](unsigned char c) {
        static const char* kHex = "0123456789abcdef";
        out += "\\x";
        out.push_back(kHex[c >> 4]);
        out.push_back(kHex[c & 15]);
    };
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c == '\n' || c == '\r') {
            while (i < text.size() && (text[i] == '\n' || text[i] == '\r')) ++i;
            if (i < text.size() && !out.empty()) out += "; ";
            continue;
        }
        if (c == '\t') {
            out.push_back(' ');
            ++i;
            continue;
        }
        if (c < 0x20 || c == 0x7f) {
            escape(c);
            ++i;
            continue;
        }
        if (c < 0x80) {
            out.push_back(static_cast<char>(c));
            ++i;
            continue;
        }
        // A UTF-8 sequence: a lead byte and its continuation bytes, kept whole when well formed.
        const int length = c >= 0xf0 && c <= 0xf4  ? 4
                           : c >= 0xe0             ? 3
                           : c >= 0xc2 && c < 0xe0 ? 2
                                                   : 0;
        bool valid = length > 0 && i + length <= text.size();
        for (int k = 1; valid && k < length; ++k)
            valid = (static_cast<unsigned char>(text[i + k]) & 0xc0) == 0x80;
        if (valid) {
            out.append(text, i, length);
            i += length;
        } else {
            escape(c);
            ++i;
        }
    }
    return out;
}

std::string extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    return ext;
}

std::string with_extension(const std::string& path, const std::string& ext) {
    return std::filesystem::path(path).replace_extension(ext).string();
}

double peak_memory_gb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024.0 / 1024.0;
}

Logger stderr_logger(bool quiet) {
    if (quiet) return {};
    return [](const std::string& line) { std::cerr << line << '\n' << std::flush; };
}

DistortionType parse_distortion_among(const std::string& option, const std::string& value,
                                      const std::vector<DistortionType>& allowed) {
    std::string names;
    for (std::size_t i = 0; i < allowed.size(); ++i) {
        if (to_string(allowed[i]) == value) return allowed[i];
        names += (i == 0 ? "" : i + 1 == allowed.size() ? " or " : ", ") + to_string(allowed[i]);
    }
    throw InvalidArgumentError(option + " " + value + ": expected " + names);
}

}  // namespace sa::cli
