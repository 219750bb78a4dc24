#include "frontends/seamless/local_field_repair.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "frontends/seamless/frame_field.h"
#include "frontends/seamless/seamless_parameterization.h"
#include "geometry/mesh/submesh.h"
#include "optim/stopwatch.h"
#include "optim/time_budget.h"

namespace sa {

namespace {

struct Schedule {
    int rings, steps;
};
constexpr Schedule kAttempts[] = {{2, 5}, {4, 10}, {8, 20}};

/// Uniform Laplacian smoothing of the `movable` vertices, `steps` Jacobi steps of half a step
/// each; returns the smoothed positions.
Eigen::MatrixXd smooth(const SimplicialMesh& mesh, const std::vector<Index>& faces,
                       const std::vector<unsigned char>& movable, int steps) {
    std::vector<std::vector<Index>> neighbours(mesh.num_vertices());
    for (Index f : faces) {
        for (int k = 0; k < 3; ++k) {
            const Index a = mesh.simplices(f, k), b = mesh.simplices(f, (k + 1) % 3);
            neighbours[a].push_back(b);
            neighbours[b].push_back(a);
        }
    }
    for (auto& n : neighbours) {
        std::sort(n.begin(), n.end());
        n.erase(std::unique(n.begin(), n.end()), n.end());
    }
    Eigen::MatrixXd x = mesh.vertices;
    for (int step = 0; step < steps; ++step) {
        Eigen::MatrixXd next = x;
        for (Index v = 0; v < mesh.num_vertices(); ++v) {
            if (!movable[v] || neighbours[v].empty()) continue;
            Eigen::RowVectorXd mean = Eigen::RowVectorXd::Zero(x.cols());
            for (Index w : neighbours[v]) mean += x.row(w);
            mean /= double(neighbours[v].size());
            next.row(v) = x.row(v) + 0.5 * (mean - x.row(v));
        }
        x.swap(next);
    }
    return x;
}

bool same_cones(std::vector<Singularity> a, std::vector<Singularity> b) {
    auto by_vertex = [](const Singularity& p, const Singularity& q) { return p.vertex < q.vertex; };
    std::sort(a.begin(), a.end(), by_vertex);
    std::sort(b.begin(), b.end(), by_vertex);
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i].vertex != b[i].vertex || a[i].index != b[i].index) return false;
    }
    return true;
}

}  // namespace

std::string FieldRepair::describe() const {
    std::ostringstream out;
    if (!ran) return "no local repair";
    out << "local repair of " << folded_faces << " folded faces";
    out << ": " << attempts.size() << " attempt" << (attempts.size() == 1 ? "" : "s");
    if (!attempts.empty()) {
        const FieldRepairAttempt& a = attempts.back();
        out << ", the last smoothing " << a.vertices_moved << " vertices of a region of "
            << a.region_faces << " faces (" << a.rings << " rings) by " << a.smoothing_steps
            << " Laplacian steps for the field only (largest move " << a.largest_move
            << " of the diagonal; the surface keeps its positions): " << a.inverted << " inverted, "
            << a.degenerate << " degenerate, " << (a.assembled ? "assembled" : "not assembled")
            << ", singularities " << (a.singularities_kept ? "kept" : "NOT kept");
    }
    out << (success ? "; repaired" : "; not repaired");
    return out.str();
}

SeamlessResult repair_folded_field(const SeamlessResult& failed, const SeamlessOptions& options,
                                   const Logger& logger) {
    const SimplicialMesh& mesh = failed.surface;
    const MeshTopology topology = mesh_topology(mesh, "mesh");
    const RestFrames<2> frames = rest_frames<2>(mesh);
    const Index nf = mesh.num_simplices();
    FieldRepair repair;
    repair.ran = true;

    // Seeds: the folded faces (the paper's "tangled triangles").
    std::vector<unsigned char> seed(nf, 0);
    for (Index f = 0; f < nf; ++f) {
        const SimplexQuality& q = failed.result.quality.per_simplex[f];
        if (q.inverted || q.degenerate) {
            seed[f] = 1;
            ++repair.folded_faces;
        }
    }
    std::vector<Index> seeds;
    for (Index f = 0; f < nf; ++f) {
        if (seed[f]) seeds.push_back(f);
    }
    // The input field phi as vectors in space, to be projected onto the smoothed faces.
    const auto [u, v] = frame_vectors(frames, failed.field_before);
    const double diagonal =
        (mesh.vertices.colwise().maxCoeff() - mesh.vertices.colwise().minCoeff()).norm();
    SeamlessOptions inner = options;
    inner.local_repair = false;
    inner.scale = failed.scale;

    const TimeBudget budget(options.integrable.max_time_seconds);  // for all the attempts

    SeamlessResult best = failed;
    for (const Schedule& schedule : kAttempts) {
        if (seeds.empty() || budget.exhausted()) break;
        inner.integrable.max_time_seconds = budget.remaining();
        Stopwatch watch;
        FieldRepairAttempt attempt;
        attempt.rings = schedule.rings;
        attempt.smoothing_steps = schedule.steps;
        const std::vector<Index> region = grow_rings(mesh, topology, seeds, schedule.rings);
        attempt.region_faces = static_cast<Index>(region.size());
        // Movable: every face around the vertex is in the region, and it is not on the boundary.
        std::vector<int> inside(mesh.num_vertices(), 0), around(mesh.num_vertices(), 0);
        std::vector<unsigned char> in_region(nf, 0);
        for (Index f : region) in_region[f] = 1;
        for (Index f = 0; f < nf; ++f) {
            for (int k = 0; k < 3; ++k) {
                ++around[mesh.simplices(f, k)];
                inside[mesh.simplices(f, k)] += in_region[f];
            }
        }
        std::vector<unsigned char> movable(mesh.num_vertices(), 0);
        for (Index w = 0; w < mesh.num_vertices(); ++w) {
            movable[w] = around[w] > 0 && inside[w] == around[w] && !topology.boundary_vertex[w];
            attempt.vertices_moved += movable[w];
        }
        SimplicialMesh smoothed = mesh;
        smoothed.vertices = smooth(mesh, region, movable, schedule.steps);
        attempt.largest_move =
            (smoothed.vertices - mesh.vertices).rowwise().norm().maxCoeff() / diagonal;
        char line[200];
        std::snprintf(line, sizeof line,
                      "local repair: %ld faces of %d rings around %ld seeds, %ld vertices "
                      "smoothed by %d steps (largest move %.3g of the diagonal)",
                      long(region.size()), schedule.rings, long(seeds.size()),
                      long(attempt.vertices_moved), schedule.steps, attempt.largest_move);
        log_line(logger, line);

        SeamlessResult r =
            seamless_parameterization(smoothed, FrameFieldInput{u, v, {}}, inner, logger);
        // Back on the input surface: the same (u, v) per corner, the input positions.
        CutMesh& cut = r.result.map.cut;
        for (Index c = 0; c < cut.mesh.num_vertices(); ++c)
            cut.mesh.vertices.row(c) = mesh.vertices.row(cut.original_vertex[c]);
        const RestFrames<2> cut_frames = rest_frames<2>(cut.mesh);
        r.result.quality = map_quality<2>(linear_parts<2>(cut.mesh, cut_frames, r.result.map.uv),
                                          cut_frames.volume);
        const RestFrames<2> smoothed_frames = rest_frames<2>(smoothed);
        const auto [u_after, v_after] = frame_vectors(smoothed_frames, r.field_after);
        r.field_after = frame_matrices(frames, u_after, v_after);
        r.surface = mesh;
        r.field_source = failed.field_source;
        r.field_before = failed.field_before;
        r.singularities_before = failed.singularities_before;
        r.plain = failed.plain;
        r.curl_stats_before = failed.curl_stats_before;
        r.face_curl_before = failed.face_curl_before;
        r.singularities_kept = same_cones(failed.singularities_before, r.singularities_after) &&
                               r.cone_deviation <= options.cone_tolerance;
        const MapQuality& q = r.result.quality;
        const double mismatch = r.result.map.max_seam_mismatch;
        r.success = r.integrable.assembled && q.inverted == 0 && q.degenerate == 0 &&
                    mismatch <= options.seam_tolerance && r.singularities_kept;
        attempt.inverted = q.inverted;
        attempt.degenerate = q.degenerate;
        attempt.assembled = r.integrable.assembled;
        attempt.singularities_kept = r.singularities_kept;
        attempt.success = r.success;
        attempt.time = watch.seconds();
        repair.attempts.push_back(attempt);
        if (r.success) {
            repair.success = true;
            r.times.total += failed.times.total;
            std::ostringstream m;
            m << "success: verified from the (u, v) of the " << q.simplices
              << " faces on the input surface: " << q.inverted << " inverted, " << q.degenerate
              << " degenerate, largest seam mismatch " << mismatch << " (tolerance "
              << options.seam_tolerance << "), " << r.singularities_after.size()
              << " cone points measured from the (u, v) angle sums (the field's singularities, "
                 "angle sums within "
              << r.cone_deviation << " rad of quarter turns); edge curl max "
              << r.curl_stats_before.max << " -> " << r.curl_stats_after.max
              << " on the field's smoothed geometry; the plain Poisson map of the input field "
                 "has "
              << r.plain.quality.inverted
              << " inverted faces; without the repair: " << failed.result.quality.inverted
              << " inverted, " << (failed.integrable.assembled ? "assembled" : "not assembled")
              << ".";
            r.message = m.str();
            best = std::move(r);
            break;
        }
    }
    best.repair = repair;
    if (!repair.success) best.message += " " + repair.describe() + ".";
    log_line(logger, repair.describe());
    return best;
}

}  // namespace sa
