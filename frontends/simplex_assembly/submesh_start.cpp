#include "frontends/simplex_assembly/detail/submesh_start.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "energies/barrier.h"
#include "frontends/simplex_assembly/detail/forced_distortion.h"
#include "frontends/simplex_assembly/detail/untangle_fallback.h"
#include "frontends/simplex_assembly/disassembly.h"
#include "frontends/simplex_assembly/map_rank.h"
#include "geometry/maps/arap_local_step.h"
#include "geometry/maps/handle_rotation_start.h"
#include "geometry/mesh/submesh.h"
#include "geometry/quality/branch_points.h"
#include "geometry/quality/local_injectivity.h"
#include "geometry/quality/map_quality.h"
#include "optim/anderson_acceleration.h"
#include "optim/stopwatch.h"

namespace sa {

namespace {

/// Differences kept by the Anderson acceleration (Peng et al. use 5 to 10).
constexpr int kAndersonHistory = 6;
/// The local/global iterations have converged when Q falls by less than this (relative) over
/// kStallWindow iterations.
constexpr double kStallDecrease = 1e-3;
constexpr std::size_t kStallWindow = 10;

Eigen::VectorXd flatten(const Eigen::MatrixXd& m) {
    return Eigen::Map<const Eigen::VectorXd>(m.data(), m.size());
}

Eigen::MatrixXd unflatten(const Eigen::VectorXd& v, Index rows) {
    return Eigen::Map<const Eigen::MatrixXd>(v.data(), rows, v.size() / rows);
}

}  // namespace

template <int D>
void untangle_start(PreparedProblem<D>& p, const SimplexAssemblyOptions& options,
                    const TimeBudget& budget, const Logger& logger, SubmeshStart& start) {
    const Eigen::MatrixXd from = (start.positions.rowwise() - p.map_center) * p.scale;
    Stopwatch watch;
    const UntangleResult u = untangle_prepared<D>(p, options, budget, from, logger);
    start.untangle_iterations = u.iterations;
    start.untangle = u.outcome;
    start.untangle_stop = u.stop;
    start.untangle_seconds = watch.seconds();
    // Simplices beyond the barrier's exponent cap are not bad here: what the untangling left
    // there, which minimized its own distortion, is mostly what the handles force (on
    // tlc/armadillo-598, 81 simplices with a free vertex, next to 83 whose vertices are all
    // handles), and no region solve on E_C can rank them.
    const std::vector<Mat<D>> A = linear_parts<D>(p.mesh, p.frames, u.positions);
    std::vector<Index> bad = bad_simplices<D>(p, A, true);
    if (bad.size() < start.bad.size()) {
        start.positions = p.to_original(u.positions);
        start.bad.swap(bad);
        start.recovered = true;
        start.untangled = true;
        start.choice.untangled = true;
    }
}

template <int D>
std::vector<Index> bad_simplices(const PreparedProblem<D>& p, const std::vector<Mat<D>>& A,
                                 bool beyond_cap_allowed) {
    const Index n = static_cast<Index>(A.size());
    std::vector<unsigned char> is_handle(p.mesh.num_vertices(), 0);
    for (Index h : p.input->handles) is_handle[h] = 1;
    std::vector<double> det_volume(n);
    std::vector<unsigned char> rejected(n, 0);
    tbb::parallel_for(Index(0), n, [&](Index s) {
        const double det = A[s].determinant();
        det_volume[s] = std::abs(det) * p.frames.volume[s];
        rejected[s] = !std::isfinite(det);
    });
    for (const auto& energy : p.assembly.energies) energy->mark_infeasible(A, rejected);
    if (!beyond_cap_allowed) {
        tbb::parallel_for(Index(0), n, [&](Index s) {
            if (rejected[s]) return;
            bool free = false;
            for (int k = 0; k <= D; ++k) free |= !is_handle[p.mesh.simplices(s, k)];
            if (!free) return;
            for (const auto& energy : p.assembly.energies)
                if (energy->beyond_exponent_cap(A[s])) rejected[s] = 1;
        });
    }
    for (Index s : wrapped_simplices<D>(p.mesh, p.topology, p.frames, A, &p.tet_edges))
        rejected[s] = 1;
    double largest = 0.0;
    for (double v : det_volume) {
        if (std::isfinite(v)) largest = std::max(largest, v);
    }
    std::vector<Index> bad;
    for (Index s = 0; s < n; ++s) {
        if (rejected[s] || det_volume[s] <= 1e-14 * largest) bad.push_back(s);
    }
    return bad;
}

template <int D>
SubmeshStart submesh_start(PreparedProblem<D>& p, const SimplexAssemblyOptions& options,
                           const TimeBudget& budget, const Logger& logger) {
    const MappingProblem& input = *p.input;
    const Index rows = p.mesh.num_vertices();
    SubmeshStart start;
    Eigen::MatrixXd x = p.start;  // normalized
    for (std::size_t k = 0; k < input.handles.size(); ++k)
        x.row(input.handles[k]) = p.assembly.targets[k].transpose();
    std::vector<Mat<D>> A = linear_parts<D>(p.mesh, p.frames, x);
    start.positions = p.to_original(x);
    start.bad = bad_simplices<D>(p, A);
    // Fewer bad simplices win (map_rank.h); with as many, the later iterate (lower Q) wins,
    // except when only a valid map is asked for.
    auto keep_if_better = [&](const Eigen::MatrixXd& candidate, const std::vector<Mat<D>>& parts,
                              const StartChoice& choice) {
        std::vector<Index> bad = bad_simplices<D>(p, parts);
        const MapRank rank{Index(bad.size())}, current{Index(start.bad.size())};
        const bool fewer = rank.better_than(current);
        if (!fewer && (rank.failing != current.failing || options.until_valid)) return false;
        start.positions = p.to_original(candidate);
        start.bad.swap(bad);
        start.choice = choice;
        start.recovered = true;
        return fewer;
    };
    auto done = [&] { return start.bad.empty() && options.until_valid; };
    if (start.bad.empty() || options.start_iterations <= 0) return start;
    if constexpr (D == 2) {
        // Folds that are discrete branch points (loops around them turn twice) cannot be repaired
        // by any region with fixed outer vertices; without handles and with a barrier that
        // ignores scale, the map composed with a conformal map of the plane loses them
        // (geometry/quality/branch_points.h). Every vertex moves but the map keeps its distortion,
        // so the vertex stage stays on the repaired regions, as for the initial map.
        if (input.handles.empty() && options.distortion == DistortionType::kConformal) {
            const std::vector<BranchPoint> points =
                find_branch_points(p.mesh, p.topology, x, start.bad, options.rings);
            if (!points.empty()) {
                const Eigen::MatrixXd composed =
                    remove_branch_points(p.mesh, p.topology, x, points);
                const std::vector<Mat<D>> parts = linear_parts<D>(p.mesh, p.frames, composed);
                std::vector<Index> bad = bad_simplices<D>(p, parts);
                // Kept when fewer folds are beyond repair; it may have more bad simplices.
                const Index before = count_unrepairable_folds(p.mesh, p.topology, x, start.bad,
                                                              options.rings),
                            after = count_unrepairable_folds(p.mesh, p.topology, composed, bad,
                                                             options.rings);
                if (after < before || (after == before && bad.size() < start.bad.size())) {
                    x = composed;
                    A = parts;
                    start.positions = p.to_original(x);
                    start.bad.swap(bad);
                    start.choice.branch_points_removed = static_cast<Index>(points.size());
                }
            }
        }
    }
    // Handles turned far from their rest orientation (the end slabs of a bar twisted by half a
    // turn): the simplices between them and the rest of an initial map are folded across the
    // turn, and region solves, M^0 and the local/global iterations from it settle with simplices
    // wrapped around an edge, which the untangling makes positive without unwrapping (branch
    // points: every simplex positive, the map not locally injective). The handles' rotations
    // carried through the mesh (handle_rotation_start.h, the start of `sa deform`) are the other
    // start, taken when it has fewer bad simplices; M^0 and the local/global iterations then go
    // on from it, whatever the size of its regions: their lower Q shortens the vertex stage
    // (deform/botijo, docs/measurements.md).
    bool rotations = false;
    if (!input.handles.empty()) {
        HandleRotationStart rotated = handle_rotation_start<D>(p.mesh, p.frames, p.recovery(), x);
        std::vector<Mat<D>> parts = linear_parts<D>(p.mesh, p.frames, rotated.positions);
        if (rotated.rotation_groups > 0 &&
            keep_if_better(rotated.positions, parts,
                           StartChoice{.iterate = StartIterate::kHandleRotations})) {
            x = std::move(rotated.positions);
            A = std::move(parts);
            rotations = true;
        }
        if (done()) return start;
    }
    // Local defects: regions no larger than what the auto mode solves in full are solved as they
    // are. The iterations below move every vertex (then the vertex stage covers the whole mesh)
    // and find nothing better there: on tlc/stgc-3d (2 bad tetrahedra of 1,722, regions of 480)
    // 126 iterations never improved on the initial map.
    // Not when the handles put a simplex beyond the barrier's exponent cap (forced_distortion.h,
    // barrier.h): no region solve on E_C can rank the simplices around it (the generated
    // fixed-boundary problems of bench/map_benchmarks.py with --flatten).
    const bool forced_beyond_cap =
        !barrier_forced_simplices<D>(p, options, kBarrierExponentCap).empty();
    const Index regions =
        static_cast<Index>(grow_rings(p.mesh, p.topology, start.bad, options.rings).size());
    if (!rotations &&
        regions <= (D == 2 ? options.auto_full_triangles : options.auto_full_tetrahedra) &&
        !forced_beyond_cap) {
        start.choice.small_regions = true;
        return start;
    }

    // M^0.
    const Initialization projection = options.effective_initialization();
    project_linear_parts<D>(A, projection, options.seed);
    x = p.recovery().recover(A, p.pinned);
    A = linear_parts<D>(p.mesh, p.frames, x);
    keep_if_better(x, A,
                   StartChoice{.iterate = StartIterate::kM0, .from_handle_rotations = rotations});

    // Accelerated local/global iterations from M^0.
    const bool similarity = projection == Initialization::kClosestSimilarity;
    AndersonAcceleration anderson(kAndersonHistory);
    std::vector<Mat<D>> M;
    double previous = fit_rigid_parts<D>(p.frames, A, similarity, M);
    Eigen::MatrixXd plain = p.recovery().recover(M, p.pinned);
    x = unflatten(anderson.next(flatten(x), flatten(plain)), rows);
    int last_improvement = 0;
    const int patience = std::max(1, options.start_iterations / 4);
    std::vector<double> history{previous};  // Q after each iteration
    for (int iteration = 1; iteration <= options.start_iterations; ++iteration) {
        start.iterations = iteration;
        const StartChoice label{.iterate = StartIterate::kLocalGlobal,
                                .local_global_iteration = iteration,
                                .similarity = similarity,
                                .from_handle_rotations = rotations};
        A = linear_parts<D>(p.mesh, p.frames, x);
        if (keep_if_better(x, A, label)) last_improvement = iteration;
        if (done() || iteration - last_improvement > patience || budget.exhausted()) break;
        double energy = fit_rigid_parts<D>(p.frames, A, similarity, M);
        if (!(energy <= previous)) {  // the accelerated point raised Q: take the plain step
            ++start.rejected;
            anderson.reset();
            x = plain;
            A = linear_parts<D>(p.mesh, p.frames, x);
            if (keep_if_better(x, A, label)) last_improvement = iteration;
            if (done()) break;
            energy = fit_rigid_parts<D>(p.frames, A, similarity, M);
        }
        previous = energy;
        history.push_back(energy);
        // Converged: Q fell by less than kStallDecrease over the last kStallWindow iterations,
        // so further iterations would not change the map (the untangling below takes over). On
        // tlc/armadillo-598 (fixed boundary) Q's relative decrease per iteration was below 1e-4
        // from iteration 11 and exactly 0 from iteration 55, and no iterate had fewer bad
        // simplices than M^0; on deform/rabbit it stayed above 1.3e-3 per iteration until the
        // map was valid.
        if (history.size() > kStallWindow &&
            history[history.size() - 1 - kStallWindow] - energy <= kStallDecrease * energy) {
            break;
        }
        plain = p.recovery().recover(M, p.pinned);
        x = unflatten(anderson.next(flatten(x), flatten(plain)), rows);
    }
    if (start.bad.empty() || budget.exhausted()) return start;
    // The untangling moves every free vertex; a region solve only the rings around the bad
    // simplices, in r-SA's D^2 variables per simplex. When the regions have fewer variables than
    // the mesh's free vertex positions, the rounds go first, and the mesh driver untangles the
    // whole mesh if they fail (untangle_fallback.h); not where the handles force a simplex
    // beyond the exponent cap, as for the local defects above. deform/cat: ARAP left 3 bad
    // tetrahedra, whose regions (3,377 of 94,441 tetrahedra) round 0 solved, where the
    // untangling took 30 s and was not kept (its map wrapped edges). tlc/armadillo-598 and the
    // knight of bench/knight_pose.py: regions of 72% and 71% of the mesh, untangled.
    const Index regions_after =
        static_cast<Index>(grow_rings(p.mesh, p.topology, start.bad, options.rings).size());
    const Index free_vertices =
        static_cast<Index>(std::count(p.recovery_fixed.begin(), p.recovery_fixed.end(), 0));
    if (options.untangle_fallback && !forced_beyond_cap && regions_after * D < free_vertices) {
        start.choice.small_regions = true;
        return start;
    }
    untangle_start<D>(p, options, budget, logger, start);
    return start;
}

template std::vector<Index> bad_simplices<2>(const PreparedProblem<2>&, const std::vector<Mat<2>>&,
                                             bool);
template std::vector<Index> bad_simplices<3>(const PreparedProblem<3>&, const std::vector<Mat<3>>&,
                                             bool);
template SubmeshStart submesh_start<2>(PreparedProblem<2>&, const SimplexAssemblyOptions&,
                                       const TimeBudget&, const Logger&);
template SubmeshStart submesh_start<3>(PreparedProblem<3>&, const SimplexAssemblyOptions&,
                                       const TimeBudget&, const Logger&);

}  // namespace sa
