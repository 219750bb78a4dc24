#pragma once
// The last stage of Simplex Assembly in vertex variables. Once E~_assembly is below its tolerance
// the simplices form a mesh, and what the paper's schedule does next (lambda at 1e16) is to
// minimize mu E_m + E_C over assembled configurations: the same problem as minimizing it over
// the vertex positions with the handles fixed. In vertex variables it has no penalty term, so
// Newton keeps its quadratic convergence instead of fighting a condition number of 1e16
// (measured in docs/measurements.md). Starting from the recovered, inversion-free mesh, the barrier
// and the largest feasible step keep every iterate inversion-free and within the bound.
//
// It is the engine (engine.h) in its vertex layout: the per-simplex energies through the
// adapter that evaluates them at A = X E^-1, E_theta in its vertex form, and the problem's own
// linear constraints as its only assembly terms: with constraints the engine's schedule keeps
// them (as in the assembly), without them it is plain projected Newton.
//
// E_C's exponent continuation (its rule: energies/exponent_continuation.h). A valid start can still
// be far from optimal: an untangled map (untangle.h) of a fixed-boundary problem with a large
// tangled region has simplices with s d ~ 150 next to perfect ones, so the per-simplex Hessians
// span e^150 and no regularization makes their sum factorizable ("factorization failed" at the
// first step: the untangled map was returned as it was). With an ExponentContinuation (the built-in
// E_C) the stage runs rounds at s_r = min(s, kExponentRange / (d_max - d_min)), d_max and d_min the
// largest and smallest barrier distortion of a simplex with a free vertex at the round's start (the
// Hessians span about e^{s_r (d_max - d_min)}), each to convergence, raising s_r as the spread
// falls until s_r = s; a round that lowers the spread by less than 1% ends the continuation, and a
// last round at s follows from the best iterate so far. Each round has the stage's iteration limit;
// they share its time limit. The result is the iterate with the lowest energy at the requested s
// (never worse than the start). This is the one exponent continuation: the mesh driver's vertex
// stage and the descent from a Tutte start (the descent mode, detail/vertex_descent.h, whose bound
// rounds each run it) both go through it.
//
// A run (a round, or the single run without a continuation) whose result has degenerate
// simplices (the verification's relative rule) while its start had none is undone and ends the
// stage: an energy whose minimizers are not representable in doubles (the conformal map of a
// nearly closed or strongly stretched surface shrinks parts of it exponentially) cannot turn a
// valid start into a map the verification rejects.

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "energies/exponent_continuation.h"
#include "frontends/simplex_assembly/detail/assembly_problem.h"
#include "frontends/simplex_assembly/detail/prepared_problem.h"
#include "frontends/simplex_assembly/map_options.h"
#include "frontends/simplex_assembly/simplex_term.h"
#include "frontends/simplex_assembly/stage_trace.h"
#include "geometry/mesh/boundary_fans.h"
#include "geometry/mesh/rest_frames.h"
#include "optim/logger.h"
#include "optim/newton_summary.h"

namespace sa {

struct VertexStage {
    VertexStageOutcome outcome = VertexStageOutcome::kSkippedInfeasibleStart;
    bool ran() const { return newton_ran(outcome); }
    Eigen::MatrixXd positions;  ///< #V x D (the start when it did not run)
    NewtonSummary newton;
    AssemblyStop stop = AssemblyStop::kConverged;  ///< the engine's reason, when it ran
    int continuation_rounds = 0;  ///< rounds of the exponent continuation (0: a single run)
    std::vector<ContinuationRound> rounds;  ///< every run, in order
    /// The continuation's rounds, the plugin that could not project the start or the simplices
    /// beyond the exponent cap, in words (empty when there is nothing to say).
    std::string figures;
};

/// The per-simplex energies at another exponent s of E_C, for the continuation. The problem's
/// own exponential barriers (SimplexTerm::exponent() > 0, a DistortionBarrier: the volumetric
/// bound of `sa deform`) go along: at s_r their exponent is theirs times s_r / s.
template <int D>
struct ExponentContinuation {
    double s = 1.0;  ///< the exponent asked for
    /// E_C's distortion d of A (+inf when det A <= 0); with barriers of the problem's own, the
    /// largest of d and their s_t d_t / s (their exponent in E_C's units).
    std::function<double(const Mat<D>&)> distortion;
    /// The stage's energies (the same terms on the same simplices) with E_C at exponent s_r;
    /// empty: no continuation.
    std::function<std::vector<std::shared_ptr<const SimplexTerm<D>>>(double)> energies;
};

/// The continuation of `prepared`'s built-in E_C, its energies restricted to `simplices` (every
/// simplex when empty; as SimplexTerm::restricted), with E_C's bound at `bound` (the options'
/// when absent: the descent's rounds lower it). Empty without the built-in energy.
template <int D>
ExponentContinuation<D> exponent_continuation(const PreparedProblem<D>& prepared,
                                              const std::vector<Index>& simplices = {},
                                              std::optional<double> bound = std::nullopt);

/// What the vertex stage minimizes besides the per-simplex energies.
template <int D>
struct VertexStageTerms {
    /// Triangles only: the boundary-angle barrier E_theta on these fans.
    std::vector<BoundaryFan> fans;
    /// The problem's linear constraints (normalized units).
    std::vector<EdgeRow<D>> constraints;
    /// The problem's plugins: each projects the start (a start one refuses is not run from) and
    /// adds its vertex-stage terms; `plugin_stage` is what they are told (kind, fixed: set by
    /// run_vertex_stage).
    std::vector<std::shared_ptr<const AssemblyPlugin<D>>> plugins = {};
    PluginStage<D> plugin_stage = {};
    /// E_C's exponent continuation (empty: one run at the energies' own exponent).
    ExponentContinuation<D> exponent = {};
};

/// `start` #V x D in the driver's normalized coordinates; `fixed` flags handles and anchors;
/// `energies` are the per-simplex energies of A, each evaluated at A = X E^-1 of the vertex
/// positions X (VertexSimplexEnergy: the adapter of v-SA). Simplices whose vertices are all
/// fixed are left out. A start with a wrap (every simplex positive, not locally injective:
/// wrapped_simplices() of local_injectivity.h) is not run from (kSkippedWrappedStart). Newton runs
/// as the engine's run() says; with terms.exponent, in the continuation's rounds when the start's
/// spread of distortions calls for them (above).
template <int D>
VertexStage run_vertex_stage(const SimplicialMesh& mesh, const RestFrames<D>& frames,
                             const MeshTopology& topology,
                             const std::vector<std::shared_ptr<const SimplexTerm<D>>>& energies,
                             const Eigen::MatrixXd& start, const std::vector<unsigned char>& fixed,
                             const SimplexAssemblyOptions& options, const Logger& logger,
                             const VertexStageTerms<D>& terms = {});

/// Records `stage` in `trace`: its outcome, Newton steps and figures, and `seconds`.
void record_vertex_stage(StageTrace& trace, const VertexStage& stage, double seconds);

}  // namespace sa
