#include "frontends/deform/deform_start.h"

#include <cstdio>

#include "optim/errors.h"
#include "optim/stopwatch.h"

namespace sa {

namespace {

template <int D>
DeformStart start_in(const SimplicialMesh& mesh, const HandleTargets& handle_targets,
                     ArapOptions options, const Logger& logger) {
    const Stopwatch watch;
    auto user = options.after_iteration;
    options.after_iteration = [&](const ArapIterate& it) {
        if (it.iteration % 10 == 0) {
            char row[160];
            std::snprintf(row, sizeof row, "  ARAP %5d  Q %.6e  largest move %.3e%s", it.iteration,
                          it.energy, it.max_move, it.accelerated ? "" : "  (plain step)");
            log_line(logger, row);
        }
        return user && user(it);
    };
    DeformStart start;
    start.arap = arap_deformation<D>(mesh, handle_targets.handles, handle_targets.targets, options);
    start.positions = std::move(start.arap.positions);
    start.arap.positions.resize(0, 0);
    const RestFrames<D> frames = rest_frames<D>(mesh);
    start.quality = map_quality<D>(linear_parts<D>(mesh, frames, start.positions), frames.volume);
    for (std::size_t k = 0; k < handle_targets.handles.size(); ++k) {
        start.handle_error = std::max(
            start.handle_error,
            (start.positions.row(handle_targets.handles[k]) - handle_targets.targets.row(k))
                .norm());
    }
    start.seconds = watch.seconds();
    log_line(logger, "  " + describe(start));
    return start;
}

}  // namespace

DeformStart deform_start(const SimplicialMesh& mesh, const HandleTargets& handle_targets,
                         const ArapOptions& options, const Logger& logger) {
    const int d = mesh.simplex_dimension();
    if (mesh.ambient_dimension() != d || (d != 2 && d != 3)) {
        throw InvalidArgumentError(
            "deform_start: deformation needs planar triangles or tetrahedra; the mesh has "
            "simplices of dimension " +
            std::to_string(d) + " in " + std::to_string(mesh.ambient_dimension()) + "D");
    }
    check_target_reach(mesh.vertices, handle_targets);
    return d == 2 ? start_in<2>(mesh, handle_targets, options, logger)
                  : start_in<3>(mesh, handle_targets, options, logger);
}

std::string describe(const DeformStart& start) {
    const MapQuality& q = start.quality;
    const bool tets = !q.per_simplex.empty() && start.positions.cols() == 3;
    char line[400];
    std::snprintf(line, sizeof line,
                  "ARAP start: %d iterations (%s), %ld inverted and %ld degenerate of %ld %s; "
                  "isometric max %.4g mean %.4g, conformal max %.4g mean %.4g, volumetric max "
                  "%.4g mean %.4g; %.3f s",
                  start.arap.iterations, start.arap.stop.c_str(), long(q.inverted),
                  long(q.degenerate), long(q.simplices), tets ? "tetrahedra" : "triangles",
                  q.isometric.max, q.isometric.mean, q.conformal.max, q.conformal.mean,
                  q.volumetric.max, q.volumetric.mean, start.seconds);
    return line;
}

}  // namespace sa
