#include "frontends/output/map_picture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "frontends/output/layout_picture.h"
#include "frontends/output/pose_picture.h"
#include "optim/errors.h"

namespace sa {

namespace {

LayoutPanel layout_panel(const std::string& caption, const Eigen::MatrixXd& positions,
                         const MapQuality& quality) {
    LayoutPanel panel;
    panel.uv = positions.leftCols(2);
    panel.values.resize(Eigen::Index(quality.per_simplex.size()));
    panel.inverted.resize(quality.per_simplex.size());
    for (std::size_t f = 0; f < quality.per_simplex.size(); ++f) {
        const SimplexQuality& q = quality.per_simplex[f];
        panel.values[Eigen::Index(f)] = q.conformal;
        panel.inverted[f] = q.inverted || q.degenerate;
    }
    char text[256];
    std::snprintf(text, sizeof text, "%s: %ld inverted, %ld degenerate; conformal max %.3g",
                  caption.c_str(), long(quality.inverted), long(quality.degenerate),
                  quality.conformal.max);
    panel.caption = text;
    return panel;
}

}  // namespace

void write_map_png(const std::string& path, const MappingProblem& problem,
                   const SimplexAssemblyResult& result, const MapPicture& picture) {
    const SimplicialMesh& mesh = problem.mesh;
    const int d = mesh.simplex_dimension();
    const std::string name = problem.source.empty()
                                 ? std::string("map")
                                 : std::filesystem::path(problem.source).filename().string();
    if (d == 2 && result.positions.cols() == 2 && problem.initial.cols() >= 2) {
        LayoutPicture layout;
        layout.size = picture.size;
        layout.value_name = "conformal distortion (sigma max / sigma min)";
        layout.low = 1.0;
        // The result's range (the initial map's can be far larger), as sa param's picture.
        layout.high = std::max(1.1, std::min(result.final_quality.conformal.max, 10.0));
        layout.title = name + ": " + std::to_string(mesh.num_simplices()) + " triangles; " +
                       (result.success ? "verified" : "NOT verified");
        write_layouts_png(path, mesh.simplices,
                          {layout_panel("initial map", problem.initial, result.initial_quality),
                           layout_panel("result", result.positions, result.final_quality)},
                          layout);
        return;
    }
    if (d != 3 || mesh.ambient_dimension() != 3) {
        throw InvalidArgumentError(
            "write_map_png: expected triangles mapped to the plane or tetrahedra in space");
    }
    PosePicture pose;
    pose.width = picture.size;
    pose.height = std::max(16, picture.size * 3 / 4);
    const MapQuality& initial = result.initial_quality;
    for (std::size_t s = 0; s < initial.per_simplex.size(); ++s)
        if (initial.per_simplex[s].inverted) pose.marked.push_back(Index(s));
    pose.marked_label = "inverted in the initial map";
    write_pose_png(path, mesh, result.positions, pose);
}

}  // namespace sa
