#pragma once
// Simplex Assembly (Fu and Liu 2016): an inversion-free map of a simplicial mesh with handles.
// The mesh driver, under `sa map`, `sa param`, `sa deform` and `sa polycube`: a
// configuration of the engine (frontends/simplex_assembly/engine.h) by the mesh's simplices,
// its edges and its handles.
//
//   1. normalize: rest and map coordinates centred, scaled by the rest bounding-box diagonal;
//   2. disassemble: the initial map's linear parts A_i^0 are projected into the barrier's feasible
//      set (closest similarity or rotation, section 4.2); T_i^0 from the initial map;
//   3. assemble: the engine (engine.h) minimizes mu E_m + E_C + lambda E~_assembly (Eq. 10) with
//      projected Newton and section 4.4's schedule, until E~_assembly < 1e-12 and E changes by
//      less than 1e-8 (relative, within a step), or 200 iterations;
//   4. recover: translations by gluing (Appendix), vertex positions by Eq. 6 with handles fixed;
//      with options.vertex_stage (the default) the assembly stops as soon as E~_assembly < 1e-12
//      and Newton finishes on the vertex positions (vertex_stage.h);
//   5. verify the recovered positions: inverted and degenerate simplices (against each rest
//      orientation), handle error, distortion and the bound. Success means no inverted or
//      degenerate simplex, no branch point, every handle within tolerance and every bound held,
//      measured on the output;
//   6. fall back, when no valid map was found: untangling in vertex variables, then the vertex
//      stage (untangle_fallback.h).
// The mode (SolveMode) chooses how 2-4 run: the whole mesh at once, submeshes around the bad
// simplices (section 4.4), or, from a start without inverted simplices, the vertex stage alone
// with its bound continued in rounds (the descent: detail/vertex_descent.h). The run's path is
// SimplexAssemblyResult::stages (stage_trace.h).
//
// Triangles map to the plane (from a planar rest shape or from a surface in space), tetrahedra to
// space. Bad input throws InputError or InvalidArgumentError; numerical outcomes are reported in
// the result.

#include <functional>
#include <string>
#include <vector>

#include "frontends/simplex_assembly/assembly_plugin.h"
#include "frontends/simplex_assembly/engine_options.h"
#include "frontends/simplex_assembly/map_options.h"
#include "frontends/simplex_assembly/simplex_term.h"
#include "frontends/simplex_assembly/stage_trace.h"
#include "geometry/mesh/simplicial_mesh.h"
#include "geometry/quality/map_quality.h"
#include "optim/logger.h"
#include "optim/newton_summary.h"

namespace sa {

/// A user's linear assembly constraint on the image of a mesh edge (a, b):
///     normal . (f(b) - f(a)) = value,
/// e.g. "these boundary vertices stay on a plane" (one row per edge between them, value 0; a
/// handle among them fixes where the plane is). `normal` has d entries (the map's dimension)
/// and need not be a unit vector: the row is normal / |normal|, value / |normal|. Added to
/// E~_assembly as n^T A_s (u_b - u_a) = value on one simplex s containing the edge (the edge
/// assembly of Eq. 7 carries it to the others), as n . (x_b - x_a) = value in the vertex stage,
/// and verified on the output.
struct EdgeConstraint {
    Index a = -1, b = -1;
    Eigen::VectorXd normal;
    double value = 0.0;
};

struct MappingProblem {
    SimplicialMesh mesh;         ///< the rest shape
    Eigen::MatrixXd initial;     ///< #V x d initial map (d = simplex dimension)
    std::vector<Index> handles;  ///< vertices with prescribed positions
    Eigen::MatrixXd targets;     ///< #handles x d; empty: the handles' rows of `initial`
    /// #V x d map whose linear parts are the A0 of E_m = difference; empty: `initial`.
    Eigen::MatrixXd reference;
    std::string source = "input";  ///< names the input in error messages
    /// Triangles mapped to the plane only: add the boundary-angle barrier E_theta (section 5.1)
    /// so that the boundary stays locally injective (angle sums below 2 pi); full mode only.
    bool boundary_injective = false;
    /// The problem's own per-simplex energies of A (simplex_term.h; element s = simplex s of
    /// `mesh`, A in its rest frame): mapping energies and barriers, added to the options'
    /// mu E_m + E_C (or in its place, with SimplexAssemblyOptions::builtin_energy = false).
    /// A barrier on a distortion (DistortionBarrier) is verified on the output like the built-in
    /// one, and takes part in the optimal-bound rounds.
    std::vector<std::shared_ptr<const SimplexTermBase>> energies;
    /// The problem's own linear assembly constraints.
    std::vector<EdgeConstraint> constraints;
    /// A front-end's own assembly terms and multi-simplex barriers (assembly_plugin.h: each an
    /// AssemblyPlugin<d>), added in the assembly stage and the vertex stage. Full mode only.
    std::vector<std::shared_ptr<const AssemblyPluginBase>> plugins;
};

/// A problem's own barrier on a distortion, measured on the output.
struct BoundCheck {
    std::string name;
    double bound = kInfinity;
    double max_distortion = 0.0;  ///< +inf when a simplex is inverted
    bool within() const { return max_distortion <= bound; }
};

struct StageTimes {
    double setup = 0.0;         ///< normalization, frames, topology, Steiner tree, problem
    double disassembly = 0.0;   ///< initial linear parts and their projection
    double optimization = 0.0;  ///< the Newton iterations
    double recovery = 0.0;      ///< gluing and Eq. 6
    double vertex_stage = 0.0;  ///< the final stage in vertex variables
    double verification = 0.0;  ///< metrics of the output positions
    double total = 0.0;
};

/// What was checked on the output positions.
struct Verification {
    Index simplices = 0;
    Index inverted = 0;
    Index degenerate = 0;
    /// Interior vertices (triangles) or edges (tetrahedra) the map wraps around more than once,
    /// every simplex positive (geometry/quality/local_injectivity.h); counted when none is
    /// inverted.
    Index branched = 0;
    std::string first_branch;  ///< the first of them: "vertex V" or "edge A-B" (0-based)
    Index handles = 0;
    double handle_error = 0.0;      ///< largest |x_h - target_h|, in the map's units
    double handle_tolerance = 0.0;  ///< handle_tolerance times the initial map's diagonal
    double bound = kInfinity;       ///< K
    double max_distortion = 0.0;    ///< largest barrier distortion d of the output
    /// The problem's own barriers on a distortion (MappingProblem::energies).
    std::vector<BoundCheck> bounds;
    Index constraints = 0;              ///< MappingProblem::constraints
    double constraint_error = 0.0;      ///< largest |n . (x_b - x_a) - value|, n a unit vector
    double constraint_tolerance = 0.0;  ///< as handle_tolerance
    bool passed() const {
        return inverted == 0 && degenerate == 0 && branched == 0 &&
               handle_error <= handle_tolerance && constraint_error <= constraint_tolerance;
    }
    bool within_bound() const {
        if (!(max_distortion <= bound)) return false;
        for (const BoundCheck& b : bounds)
            if (!b.within()) return false;
        return true;
    }
    /// One sentence: what was measured and the outcome.
    std::string describe() const;
};

/// One round of the submesh mode.
struct SubmeshRound {
    int round = 0;
    Index bad_simplices = 0;  ///< at the start of the round
    Index regions = 0;        ///< submeshes built around them (merged where they touch)
    int colors = 0;       ///< colours of the conflict graph (1 unless regions grew into each other)
    Index solved = 0;     ///< solves kept (verified)
    Index failed = 0;     ///< regions given up at m_max rings
    Index remaining = 0;  ///< bad simplices after the round
    double time = 0.0;
};

/// Which iterate the submesh mode started from: the candidate with the fewest bad simplices
/// (submesh_start.h).
enum class StartIterate {
    kInitialMap,       ///< the initial map, its handles at their targets
    kHandleRotations,  ///< the handles' rotations carried through the mesh
                       ///< (handle_rotation_start.h)
    kM0,               ///< the paper's M^0: the disassembly's projection, then Eq. 6
    kLocalGlobal,      ///< an accelerated ARAP (ASAP for the conformal distortion) iterate from M^0
};

struct StartChoice {
    StartIterate iterate = StartIterate::kInitialMap;
    int local_global_iteration = 0;      ///< kLocalGlobal: which iteration
    bool similarity = false;             ///< kLocalGlobal: ASAP rather than ARAP
    bool from_handle_rotations = false;  ///< M^0 and the iterations ran from the handles' rotations
    /// The initial map composed with a conformal map that unwinds this many branch points.
    Index branch_points_removed = 0;
    bool small_regions = false;  ///< its regions were small enough to be solved as they are
    bool untangled = false;      ///< then untangled in vertex variables (Stage::kStartUntangle)
    /// "ARAP iteration 12 from the handles' rotations", "initial map (its regions are small)", ...
    std::string describe() const;
};

struct SubmeshStats {
    StartChoice start;         ///< which iterate of the start
    int start_iterations = 0;  ///< local/global iterations run after M^0
    int start_rejected = 0;    ///< accelerated points among them replaced by plain steps
    Index start_bad = 0;       ///< bad simplices of the start
    /// Simplices of the start within options.submesh_band of their bound (and not bad), whose
    /// regions the first round also solves.
    Index start_near_bound = 0;
    std::vector<SubmeshRound> rounds;
    Index solves = 0;           ///< submesh solves, retries included
    Index iterations = 0;       ///< Newton steps summed over them
    Index largest_submesh = 0;  ///< simplices
    int max_rings = 0;
    double start_time = 0.0, region_time = 0.0, solve_time = 0.0;
    bool out_of_time = false;  ///< max_time_seconds ran out before the regions were done
    /// One sentence.
    std::string describe() const;
};

struct SimplexAssemblyResult {
    Eigen::MatrixXd positions;  ///< #V x d output map
    bool success = false;       ///< valid, and every bound held
    /// Verification passed (no inverted, degenerate or branched simplex, handles and constraints
    /// in place, boundary angle sums under 2 pi with E_theta): a valid map, bounds aside.
    bool valid = false;
    std::string message;     ///< the outcome in a sentence or two
    bool assembled = false;  ///< E~_assembly reached the tolerance
    double final_assembly = 0.0;
    double final_lambda = 0.0;
    SolveMode mode = SolveMode::kFull;  ///< the mode that ran
    SubmeshStats submesh;               ///< when mode is kSubmesh
    /// When mode is kDescent: the vertex stage's rounds, at each bound (ContinuationRound::bound)
    /// and exponent; empty when the start was not valid.
    std::vector<ContinuationRound> descent_rounds;
    Verification verification;
    MapQuality initial_quality;  ///< of the initial map
    MapQuality final_quality;    ///< of the output positions
    NewtonSummary newton;        ///< the assembly stage
    std::vector<AssemblyRecord> iterations;
    NewtonSummary vertex_stage;  ///< the vertex stage (empty when it did not run)
    /// The stages the run passed, in order, each with its typed outcome (stage_trace.h).
    StageTrace stages;
    StageTimes times;
    Index num_variables = 0;
    Index num_translation_simplices = 0;  ///< |Omega_s| for r-SA, N for f-SA
    Index num_tree_edges = 0;             ///< r-SA: edges of the Steiner tree and of the loops
    Index num_loops = 0;                  ///< r-SA: loops closed around holes and handles
    Index num_anchored_simplices = 0;
    /// With boundary_injective: boundary vertices whose angle sum is >= 2 pi, before and after
    /// (-1 when not measured).
    Index boundary_violations_before = -1;
    Index boundary_violations_after = -1;
};

struct SimplexAssemblyObserver {
    /// Receives a header and one progress row per iteration.
    Logger logger;
    /// Called before the first step and after each one with the disassembled simplices: row
    /// (d + 1) s + k is the image of corner k of simplex s, in the map's units.
    std::function<void(int iteration, const Eigen::MatrixXd& corners)> snapshot;
};

SimplexAssemblyResult run_simplex_assembly(const MappingProblem& problem,
                                           const SimplexAssemblyOptions& options,
                                           const SimplexAssemblyObserver& observer = {});

/// Mode kDescent: whether the start was valid and the descent ran from it (otherwise the trace's
/// first vertex stage is VertexStageOutcome::kSkippedInfeasibleStart and the positions are the
/// start's).
bool descent_started(const SimplexAssemblyResult& result);

}  // namespace sa
