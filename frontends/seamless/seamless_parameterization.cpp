#include "frontends/seamless/seamless_parameterization.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "frontends/seamless/cone_obstruction.h"
#include "frontends/seamless/cut_graph.h"
#include "frontends/seamless/frame_field.h"
#include "geometry/mesh/mesh_topology.h"
#include "optim/errors.h"
#include "optim/stopwatch.h"
#include "optim/time_budget.h"

namespace sa {

namespace {

/// Per face, the largest of the curls of its interior edges.
Eigen::VectorXd largest_per_face(const MeshTopology& topology, Index faces,
                                 const Eigen::VectorXd& curl) {
    Eigen::VectorXd out = Eigen::VectorXd::Zero(faces);
    for (std::size_t i = 0; i < topology.interior_facets.size(); ++i) {
        for (Index f : topology.interior_facets[i].simplex) out[f] = std::max(out[f], curl[i]);
    }
    return out;
}

CurlStats curl_stats(const Eigen::VectorXd& curl) {
    if (curl.size() == 0) return {};
    return {curl.maxCoeff(), curl.mean()};
}

/// The (u, v) map's quality per face, measured on its cut mesh in space with (u, v) times
/// `uv_scale`.
MapQuality measured_quality(const SeamlessMap& map, double uv_scale = 1.0) {
    const RestFrames<2> frames = rest_frames<2>(map.cut.mesh);
    return map_quality<2>(linear_parts<2>(map.cut.mesh, frames, uv_scale * map.uv), frames.volume);
}

VerifiedSeamlessMap poisson_verified(const SimplicialMesh& mesh, const MeshTopology& topology,
                                     const SeamlessResult& r, const std::vector<Mat<2>>& field,
                                     double to_jacobian) {
    std::vector<Mat<2>> jacobians(field.size());
    for (std::size_t f = 0; f < field.size(); ++f) jacobians[f] = to_jacobian * field[f];
    VerifiedSeamlessMap out;
    out.map = seamless_poisson(mesh, topology, r.cut, r.matching, jacobians);
    out.quality = measured_quality(out.map);
    return out;
}

/// The cone points of a map, measured from its (u, v): per interior vertex, index = 1 - (sum of
/// its corner angles in (u, v)) / 2 pi, rounded to a quarter; `deviation` receives the largest
/// distance of an angle sum from its rounded value, in radians.
std::vector<Singularity> cone_singularities(const SimplicialMesh& mesh,
                                            const MeshTopology& topology, const SeamlessMap& map,
                                            double& deviation) {
    std::vector<double> angle_sum(mesh.num_vertices(), 0.0);
    const Eigen::MatrixXi& faces = map.cut.mesh.simplices;
    for (Index f = 0; f < faces.rows(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const Eigen::RowVector2d p = map.uv.row(faces(f, k)),
                                     a = map.uv.row(faces(f, (k + 1) % 3)) - p,
                                     b = map.uv.row(faces(f, (k + 2) % 3)) - p;
            angle_sum[map.cut.original_vertex[faces(f, k)]] +=
                std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
        }
    }
    std::vector<Singularity> cones;
    deviation = 0.0;
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        if (!topology.used_vertex[v] || topology.boundary_vertex[v]) continue;
        const double quarters = 4.0 * (1.0 - angle_sum[v] / (2.0 * M_PI));
        deviation = std::max(deviation, std::abs(quarters - std::round(quarters)) * 0.5 * M_PI);
        if (std::round(quarters) != 0.0) cones.push_back({v, std::round(quarters) / 4.0});
    }
    return cones;
}

bool same_singularities(const std::vector<Singularity>& a, const std::vector<Singularity>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i].vertex != b[i].vertex || a[i].index != b[i].index) return false;
    }
    return true;
}

/// The pipeline on `input` as given; seamless_parameterization() calls it at unit scale.
SeamlessResult seamless_in_mesh_units(const SimplicialMesh& input,
                                      const std::optional<FrameFieldInput>& field,
                                      const SeamlessOptions& options, const Logger& logger) {
    Stopwatch total, stage;
    // options.integrable.max_time_seconds holds for the whole run: the assembly and the repairs
    // take what is left.
    const TimeBudget budget(options.integrable.max_time_seconds);
    if (input.simplex_dimension() != 2)
        throw InputError("seamless parameterization needs a triangle mesh");
    SeamlessResult r;
    r.surface = input;
    if (r.surface.vertices.cols() == 2) {
        r.surface.vertices.conservativeResize(Eigen::NoChange, 3);
        r.surface.vertices.col(2).setZero();
    }
    const SimplicialMesh& mesh = r.surface;
    // Also rejects a non-manifold or inconsistently oriented surface, and a pinched one.
    const MeshTopology topology = mesh_topology(mesh, "mesh");
    require_no_pinched_vertex(mesh, topology, "mesh", kSeamlessSurface);
    const RestFrames<2> frames = rest_frames<2>(mesh);
    const Index nf = mesh.num_simplices();

    // 1. The field.
    if (field && field->given.empty()) {
        r.field_source = "file";
        r.field_before = frame_matrices(frames, field->u, field->v);
    } else {
        std::vector<CrossFieldConstraint> constraints;
        if (field) {
            for (Index f = 0; f < nf; ++f) {
                if (field->given[f]) constraints.push_back({f, field->u.row(f).transpose()});
            }
        }
        r.field_source = field ? "cross field interpolating the file's " +
                                     std::to_string(constraints.size()) + " given faces"
                               : "smoothest cross field";
        r.field_before = frame_matrices(frames, smoothest_cross_field(mesh, topology, constraints));
    }
    const Eigen::MatrixXd directions = frame_cross_directions(frames, r.field_before);
    r.singularities_before = cross_field_singularities(mesh, topology, directions);
    r.times.field = stage.lap();
    r.infeasible = seamless_cone_obstruction(mesh, topology, r.singularities_before);
    if (!r.infeasible.empty()) {
        r.message = "INFEASIBLE: " + r.infeasible + "; nothing was optimized.";
        r.times.total = total.seconds();
        return r;
    }

    // 2. Matchings and the cut.
    r.matching = cross_field_matchings(mesh, topology, directions);
    std::vector<Index> through;
    for (const Singularity& s : r.singularities_before) through.push_back(s.vertex);
    r.cut = cut_graph(mesh, topology, through);
    r.cut_edges = std::count(r.cut.begin(), r.cut.end(), 1);
    r.times.cut = stage.lap();

    const double row_norm = mean_row_norm(r.field_before);
    r.scale =
        options.scale > 0.0
            ? options.scale
            : (mesh.vertices.colwise().maxCoeff() - mesh.vertices.colwise().minCoeff()).norm() /
                  30.0;
    const double to_jacobian = 1.0 / (row_norm * r.scale);
    const Eigen::VectorXd curl_before =
        edge_curl(mesh, topology, frames, r.field_before, r.matching) / row_norm;
    r.curl_stats_before = curl_stats(curl_before);
    r.face_curl_before = largest_per_face(topology, nf, curl_before);

    // 3. The plain Poisson map of phi, for comparison.
    r.plain = poisson_verified(mesh, topology, r, r.field_before, to_jacobian);
    r.times.plain_poisson = stage.lap();

    // 4. phi' by Simplex Assembly.
    IntegrableFieldOptions integrable = options.integrable;
    integrable.max_time_seconds = std::max(budget.remaining(), 1e-3);
    r.integrable =
        integrable_field(mesh, topology, frames, r.field_before, r.matching, integrable, logger);
    r.field_after = r.integrable.matrices;
    r.times.integrable = stage.lap();

    // 5. Its Poisson map, verified.
    r.result = poisson_verified(mesh, topology, r, r.field_after, to_jacobian);
    r.times.poisson = stage.lap();
    const Eigen::VectorXd curl_after =
        edge_curl(mesh, topology, frames, r.field_after, r.matching) / row_norm;
    r.curl_stats_after = curl_stats(curl_after);
    r.face_curl_after = largest_per_face(topology, nf, curl_after);
    r.singularities_after = cone_singularities(mesh, topology, r.result.map, r.cone_deviation);
    r.singularities_kept = same_singularities(r.singularities_before, r.singularities_after) &&
                           r.cone_deviation <= options.cone_tolerance;
    r.matchings_kept =
        cross_field_matchings(mesh, topology, frame_cross_directions(frames, r.field_after)) ==
        r.matching;
    const MapQuality& q = r.result.quality;
    const double mismatch = r.result.map.max_seam_mismatch;
    r.success = r.integrable.assembled && q.inverted == 0 && q.degenerate == 0 &&
                mismatch <= options.seam_tolerance && r.singularities_kept;
    r.times.verification = stage.lap();
    r.times.total = total.seconds();

    std::ostringstream m;
    m << (r.success ? "success: " : "FAILED: ") << "verified from the (u, v) of the " << q.simplices
      << " faces: " << q.inverted << " inverted, " << q.degenerate
      << " degenerate, largest seam mismatch " << mismatch << " (tolerance "
      << options.seam_tolerance << "), " << r.singularities_after.size()
      << " cone points measured from the (u, v) angle sums "
      << (r.singularities_kept
              ? "(the field's singularities"
              : "(NOT the field's " + std::to_string(r.singularities_before.size()) +
                    " singularities")
      << ", angle sums within " << r.cone_deviation << " rad of quarter turns)"
      << "; edge curl max " << r.curl_stats_before.max << " -> " << r.curl_stats_after.max
      << (r.integrable.assembled ? "" : " (not assembled)") << "; the plain Poisson map of the "
      << "input field has " << r.plain.quality.inverted << " inverted faces.";
    r.message = m.str();
    if (!r.success && options.local_repair && !budget.exhausted()) {
        SeamlessOptions left = options;
        left.integrable.max_time_seconds = budget.remaining();
        return repair_folded_field(r, left, logger);
    }
    return r;
}

}  // namespace

SeamlessResult seamless_parameterization(const SimplicialMesh& input,
                                         const std::optional<FrameFieldInput>& field,
                                         const SeamlessOptions& options, const Logger& logger) {
    // At unit scale (simplicial_mesh.h, scale_exponent): a surface at 1e100 or 1e-100 is solved
    // as at 1, with the same bits; (u, v) are in units of H, so lengths are scaled back. The
    // maps' qualities (isometric and volumetric distortions see the scale) are measured again as
    // the input's: (u, v) over the input surface, both sides times 2^-k so that the measure
    // neither overflows nor underflows (as the mesh driver's verification does).
    const int k = scale_exponent(input.vertices);
    if (k == 0) return seamless_in_mesh_units(input, field, options, logger);
    SimplicialMesh unit = input;
    unit.vertices *= std::ldexp(1.0, -k);
    SeamlessOptions in_unit = options;
    in_unit.scale = std::ldexp(options.scale, -k);
    SeamlessResult r = seamless_in_mesh_units(unit, field, in_unit, logger);
    const double back = std::ldexp(1.0, k);
    for (VerifiedSeamlessMap* m : {&r.plain, &r.result}) {
        if (m->map.cut.mesh.num_simplices() > 0) m->quality = measured_quality(m->map, 1.0 / back);
        m->map.cut.mesh.vertices *= back;
    }
    r.surface.vertices *= back;
    r.scale *= back;
    return r;
}

}  // namespace sa
