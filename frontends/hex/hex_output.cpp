#include "frontends/hex/hex_output.h"

#include <algorithm>
#include <vector>

#include "frontends/output/surface_value_picture.h"
#include "geometry/io/medit_io.h"
#include "geometry/io/vtk_io.h"

namespace sa {

void write_hex_medit(const std::string& path, const HexMesh& mesh) {
    write_medit(path, mesh.positions, mesh.hexes);
}

void write_hex_vtu(const std::string& path, const HexMesh& mesh, const HexQuality& quality) {
    const Index n = mesh.num_hexes();
    DataArray scaled{"scaled_jacobian", Eigen::MatrixXd(n, 1)};
    DataArray corner{"min_corner_jacobian", Eigen::MatrixXd(n, 1)};
    for (Index h = 0; h < n; ++h) {
        scaled.values(h, 0) = quality.scaled_jacobian[h];
        corner.values(h, 0) = hex_min_corner_jacobian(mesh, h);
    }
    const std::vector<DataArray> cells = {scaled, corner};
    if (path.size() >= 4 && path.compare(path.size() - 4, 4, ".vtk") == 0) {
        write_vtk(path, mesh.positions, mesh.hexes, {}, cells);
    } else {
        write_vtu(path, mesh.positions, mesh.hexes, {}, cells);
    }
}

void write_hex_png(const std::string& path, const HexMesh& mesh, const HexQuality& quality,
                   const std::string& title) {
    // The hexes whose centre lies below the middle of z: the camera looks down z
    // (vtk_scene.h), so the cut faces it and shows the inside.
    constexpr int axis = 2;
    const double middle =
        0.5 * (mesh.positions.col(axis).minCoeff() + mesh.positions.col(axis).maxCoeff());
    std::vector<Index> kept;
    for (Index h = 0; h < mesh.num_hexes(); ++h) {
        double centre = 0.0;
        for (int c = 0; c < 8; ++c) centre += mesh.positions(mesh.hexes(h, c), axis) / 8.0;
        if (centre <= middle) kept.push_back(h);
    }
    if (kept.empty()) {
        for (Index h = 0; h < mesh.num_hexes(); ++h) kept.push_back(h);
    }
    HexMesh half;
    half.positions = mesh.positions;
    half.hexes.resize(static_cast<Eigen::Index>(kept.size()), 8);
    for (std::size_t i = 0; i < kept.size(); ++i)
        half.hexes.row(Eigen::Index(i)) = mesh.hexes.row(kept[i]);
    const HexBoundary boundary = hex_boundary(half);

    // Which hex each boundary quad belongs to: its face key.
    std::vector<std::pair<std::array<int, 4>, Index>> owner;
    for (std::size_t i = 0; i < kept.size(); ++i) {
        for (const auto& f : kHexFaces) {
            std::array<int, 4> key;
            for (int k = 0; k < 4; ++k) key[k] = half.hexes(Eigen::Index(i), f[k]);
            std::sort(key.begin(), key.end());
            owner.push_back({key, kept[i]});
        }
    }
    std::sort(owner.begin(), owner.end());
    const Eigen::Index quads = boundary.quads.rows();
    Eigen::MatrixXi triangles(2 * quads, 3);
    Eigen::VectorXd values(2 * quads);
    std::vector<unsigned char> inverted(static_cast<std::size_t>(2 * quads), 0);
    double worst = 0.2;
    for (Eigen::Index q = 0; q < quads; ++q) {
        std::array<int, 4> key;
        for (int k = 0; k < 4; ++k) key[k] = boundary.quads(q, k);
        std::sort(key.begin(), key.end());
        const auto it =
            std::lower_bound(owner.begin(), owner.end(), std::make_pair(key, Index(-1)));
        const Index h = it->second;
        const double value = 1.0 - quality.scaled_jacobian[h];
        const bool bad = !(hex_min_corner_jacobian(mesh, h) > 0.0);
        if (!bad) worst = std::max(worst, value);
        triangles.row(2 * q) << boundary.quads(q, 0), boundary.quads(q, 1), boundary.quads(q, 2);
        triangles.row(2 * q + 1) << boundary.quads(q, 0), boundary.quads(q, 2),
            boundary.quads(q, 3);
        values[2 * q] = values[2 * q + 1] = value;
        inverted[2 * q] = inverted[2 * q + 1] = bad;
    }
    SurfaceValuePicture picture;
    picture.title = title;
    picture.value_name = "1 - scaled Jacobian";
    picture.low = 0.0;
    picture.high = std::min(worst, 1.0);
    write_surface_value_png(path, mesh.positions, triangles, values, picture, inverted);
}

}  // namespace sa
