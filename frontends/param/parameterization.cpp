#include "frontends/param/parameterization.h"

#include "frontends/param/start_disk.h"

#include <sstream>

#include "frontends/simplex_assembly/map_rank.h"
#include "geometry/maps/initial_maps.h"
#include "geometry/mesh/boundary_fans.h"
#include "geometry/mesh/boundary_loops.h"
#include "geometry/mesh/rest_frames.h"
#include "geometry/quality/map_quality.h"
#include "optim/enum_names.h"
#include "optim/errors.h"
#include "optim/stopwatch.h"
#include "optim/time_budget.h"

namespace sa {

constexpr EnumName<InitialMap> kInitialMapNames[] = {{InitialMap::kLscm, "lscm"},
                                                     {InitialMap::kTutte, "tutte"},
                                                     {InitialMap::kTutteUniform, "tutte-uniform"},
                                                     {InitialMap::kHarmonic, "harmonic"}};

std::string to_string(InitialMap map) {
    return enum_name(kInitialMapNames, map);
}

InitialMap parse_initial_map(const std::string& name) {
    return parse_enum(kInitialMapNames, name, "initial map");
}

ParameterizationResult parameterize(const SimplicialMesh& mesh, const std::string& source,
                                    const Eigen::MatrixXd* initial_uv, InitialMap initial,
                                    const ParameterizationOptions& options,
                                    const SimplexAssemblyObserver& observer) {
    Stopwatch total, stage;
    const TimeBudget budget(options.solver.max_time_seconds);
    ParameterizationResult result;
    validate_mesh(mesh, source);
    const MeshTopology topology = mesh_topology(mesh, source);
    require_planar_surface(mesh, topology, source);
    const StartDisk disk = start_disk(mesh, topology, source);
    result.filled_holes = disk.filled_holes;
    result.unused_vertices = disk.unused_vertices;
    if (initial_uv != nullptr) {
        if (initial_uv->rows() != mesh.num_vertices() || initial_uv->cols() < 2) {
            throw InputError(source + ": the initial map has " +
                             std::to_string(initial_uv->rows()) + " rows for " +
                             std::to_string(mesh.num_vertices()) + " vertices");
        }
        result.initial_uv = initial_uv->leftCols(2);
    } else {
        Eigen::MatrixXd uv;
        switch (initial) {
            case InitialMap::kLscm:
                uv = lscm(disk.mesh, disk.topology);
                break;
            case InitialMap::kTutte:
                uv = tutte_embedding(disk.mesh, disk.topology, TutteWeights::kMeanValue);
                break;
            case InitialMap::kTutteUniform:
                uv = tutte_embedding(disk.mesh, disk.topology, TutteWeights::kUniform);
                break;
            case InitialMap::kHarmonic:
                uv = harmonic_circle(disk.mesh, disk.topology);
                break;
        }
        result.initial_uv = disk.to_surface(uv);
    }
    result.initial_map_time = stage.lap();
    const std::vector<BoundaryFan> fans = boundary_fans(mesh, topology);
    result.boundary_violations_before = count_boundary_violations(fans, result.initial_uv);

    MappingProblem problem;
    problem.mesh = mesh;
    problem.source = source;
    problem.initial = result.initial_uv;
    problem.reference =
        result.initial_uv;  // E_m measures the change from the initial map in every round
    problem.boundary_injective = options.free_boundary_injective;
    SimplexAssemblyOptions solver = options.solver;
    // The parameterization's own last resort is the Tutte start below (start_fallback.h).
    solver.untangle_fallback = false;
    // After the first, the rounds of the optimal bound run in the submesh mode unless the caller
    // asks for the full mode (or E_theta needs it): each solves regions around the simplices
    // within optimal_bound_band of the bound, the rest fixed (camelhead.off: delta_con 1.827 in
    // 0.9 s, against 1.828 in 26-36 s for the full mode's rounds; docs/measurements.md).
    OptimalBoundOptions rounds;
    rounds.rounds = std::max(1, options.optimal_bound_rounds);
    rounds.tolerance = options.optimal_bound_tolerance;
    if (options.optimal_bound_rounds > 0 && solver.mode != SolveMode::kFull &&
        !options.free_boundary_injective) {
        rounds.submesh_band = options.optimal_bound_band;
        // The previous result stays a feasible start: its largest distortion is under the bound.
        rounds.margin = 1e-6;
        // A start without foldovers needs no full first round either: the submesh rounds lower
        // its largest distortions (hand-uv.obj: K 1.040 in 2.4 s, with a full first round 1.038
        // in 29 s). A folded start is repaired by the mode kAuto chooses.
        if (solver.mode == SolveMode::kAuto) {
            const RestFrames<2> frames = rest_frames<2>(mesh);
            const MapQuality start =
                map_quality<2>(linear_parts<2>(mesh, frames, result.initial_uv), frames.volume);
            if (start.inverted == 0 && start.degenerate == 0) solver.mode = SolveMode::kSubmesh;
        }
    }
    OptimalBound solved = optimal_bound(problem, with_time_left(solver, budget), rounds, observer);
    result.initial_quality = solved.initial_quality;
    result.rounds = std::move(solved.rounds);
    const bool have_result = solved.verified;
    result.solve = std::move(solved.solve);
    if (have_result) {
        result.uv = result.solve.positions;
        result.reached_bound = result.solve.verification.max_distortion;
    }
    result.success = have_result;
    if (!have_result) result.uv = result.solve.positions;
    if (!have_result && options.fallback) {
        // The requested start folded beyond repair, or its result is over the bound: a start that
        // cannot fold, kept valid by a barrier on the vertex positions (start_fallback.h).
        const Verification& v = result.solve.verification;
        MappingProblem fallback_problem = problem;
        result.fallback = fall_back_to_tutte(
            fallback_problem, disk, with_time_left(options.solver, budget), observer,
            initial_uv != nullptr ? std::string("given") : to_string(initial), v);
        const StartFallback& f = result.fallback;
        const bool keep = MapRank::of_verdict(f.verified(), f.solve.verification.max_distortion)
                              .better_than(MapRank::of_verdict(v.passed(), v.max_distortion));
        if (keep) {
            result.uv = f.solve.positions;
            result.solve = f.solve;
            result.reached_bound = f.solve.verification.max_distortion;
            result.success = f.solve.verification.within_bound();
        }
        if (keep && options.optimal_bound_rounds > 0 && !budget.exhausted()) {
            // The optimal bound from the fallback's map: the descent's bound rounds
            // (bound_rounds.h) towards a target at the identity's distortion, lowered until they
            // stop improving.
            Stopwatch round_watch;
            MappingProblem lowered = problem;
            lowered.initial = result.uv;
            lowered.reference = f.initial_uv;
            SimplexAssemblyOptions o = descent_options(with_time_left(options.solver, budget));
            o.bound = 1.0 + 1e-9;
            SimplexAssemblyResult d = run_simplex_assembly(lowered, o, observer);
            BoundRound record;
            record.bound = d.descent_rounds.empty() ? kInfinity : d.descent_rounds.back().bound;
            record.max_distortion = d.verification.max_distortion;
            record.success = d.valid;
            for (const ContinuationRound& r : d.descent_rounds) record.iterations += r.iterations;
            record.time = round_watch.seconds();
            result.rounds.push_back(record);
            if (MapRank::of_verdict(d.valid, record.max_distortion)
                    .better_than(MapRank::of_verdict(true, result.reached_bound))) {
                result.uv = d.positions;
                result.solve = std::move(d);
                // Measured against the bound asked for, not the rounds' target.
                result.solve.verification.bound = options.solver.bound;
                result.solve.success =
                    result.solve.valid && result.solve.verification.within_bound();
                result.reached_bound = record.max_distortion;
            }
        }
    }
    result.boundary_violations_after = count_boundary_violations(fans, result.uv);
    if (options.free_boundary_injective && result.boundary_violations_after > 0)
        result.success = false;
    std::ostringstream message;
    message << (result.success ? "success: " : "FAILED: ");
    // A start read from a file was not computed here: the holes count only if the fallback ran.
    if (result.filled_holes > 0 && (initial_uv == nullptr || result.fallback.used)) {
        message << "the start computed with " << result.filled_holes << " inner hole"
                << (result.filled_holes == 1 ? "" : "s") << " filled; ";
    }
    if (result.unused_vertices > 0) {
        message << result.unused_vertices << " vertices belong to no triangle (left out, written "
                << "at the centroid of the others); ";
    }
    if (result.fallback.used) {
        message << "fallback (" << result.fallback.describe_reason() << "): ";
        message << (result.fallback.verified() ? "from " + start_name(*result.fallback.start) +
                                                     ", Newton on the vertex positions; "
                                               : "no start verified; ");
    }
    message << result.solve.verification.describe() << "; " << result.boundary_violations_after
            << " boundary vertices with an angle sum >= 2 pi (" << result.boundary_violations_before
            << " in the initial map)";
    if (options.optimal_bound_rounds > 0) {
        message << "; optimal bound: " << result.rounds.size() << " rounds, reached "
                << result.reached_bound;
    }
    const Verification& final_check = result.solve.verification;
    if (final_check.passed() && !final_check.within_bound()) {
        message << "; the bound " << final_check.bound
                << " was not reached, the map written has no foldovers";
    }
    message << ".";
    result.message = message.str();
    result.total_time = total.seconds();
    return result;
}

}  // namespace sa
