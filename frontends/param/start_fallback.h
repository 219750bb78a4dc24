#pragma once
// The parameterization's fallback when the requested start folds beyond repair or its result does
// not verify: a start that cannot fold, kept valid. Tutte's embedding with mean-value weights,
// then with uniform weights (both onto a circle, convex: no foldover in exact arithmetic), each
// checked as a map before it is used:
//  - a start with an inverted triangle (round-off) is rejected and the next one tried;
//  - a start whose triangles are positively oriented but numerically degenerate (Tutte maps of
//    nearly closed surfaces shrink triangles by 1e10 and more: the far end of a tube closed at
//    one end shrinks exponentially with its depth) is repaired first: Newton on the vertex
//    positions with the isometric barrier alone, which grows shrunken triangles back (the
//    conformal barrier is scale-invariant and would leave them); a start it cannot repair goes
//    on as it is.
// An accepted start goes to Newton on the vertex positions (the driver's descent mode,
// SolveMode::kDescent) with the solver's options, whose barrier keeps every iterate valid; E_m's
// reference is that start (E_m = difference measures the change from the initial map, and the
// initial map is now it).

#include <optional>
#include <string>
#include <vector>

#include "frontends/param/start_disk.h"
#include "frontends/simplex_assembly/map_solve.h"
#include "geometry/maps/initial_maps.h"
#include "geometry/mesh/mesh_topology.h"

namespace sa {

/// Why the requested start's result was not kept.
enum class FallbackReason {
    kNotVerified,   ///< it has an inverted or degenerate triangle
    kOverTheBound,  ///< it verifies, over the bound
};

/// How one Tutte start ended.
enum class TriedStartOutcome {
    kRejected,     ///< the start itself has inverted or degenerate triangles: no descent ran
    kVerified,     ///< the descent from it verifies
    kNotVerified,  ///< the descent from it does not verify
    kRepairKept,   ///< the descent left degenerate triangles; the repaired start is the result
};

/// "tutte" (mean-value weights) or "tutte-uniform".
std::string start_name(TutteWeights weights);
std::string to_string(FallbackReason reason);
std::string to_string(TriedStartOutcome outcome);

struct TriedStart {
    TutteWeights weights = TutteWeights::kMeanValue;
    TriedStartOutcome outcome = TriedStartOutcome::kRejected;
    /// Degenerate triangles of the start that the isometric repair ran on (0: it did not run),
    /// whether it removed them (in repair_rounds rounds), and what it left.
    Index repair_degenerate = 0;
    bool repaired = false;
    int repair_rounds = 0;
    Verification repair;
    bool valid = false;                 ///< the start itself had no inverted or degenerate triangle
    bool verified = false;              ///< its result (kRepairKept: the repaired start) verifies
    double max_distortion = kInfinity;  ///< of its result, in the barrier's measure
    Index start_inverted = 0, start_degenerate = 0;  ///< of the start the descent ran from
    Verification descent_verification;  ///< of the descent's result (kRepairKept: the one dropped)
    std::string descent;                ///< the descent's summary (SimplexAssemblyResult::message)
    /// One sentence for the log and the report.
    std::string describe() const;
};

struct StartFallback {
    bool used = false;  ///< the fallback ran
    FallbackReason reason = FallbackReason::kNotVerified;
    std::string requested_start;  ///< its name: "lscm", "given", ...
    Verification requested;       ///< the requested start's result's verification
    std::vector<TriedStart> starts;
    std::optional<TutteWeights> start;  ///< the start whose result is `solve`, if one verified
    Eigen::MatrixXd initial_uv;         ///< that start, #V x 2
    std::vector<ContinuationRound>
        rounds;                   ///< the descent's (SimplexAssemblyResult::descent_rounds)
    SimplexAssemblyResult solve;  ///< its result (verified: no inverted or degenerate triangle)
    double time = 0.0;
    bool verified() const { return start.has_value(); }
    /// Why it ran, in a sentence with the figures.
    std::string describe_reason() const;
};

/// `solver` for a descent from a valid start (SolveMode::kDescent), without the driver's
/// untangling fallback: the start is the only candidate.
SimplexAssemblyOptions descent_options(SimplexAssemblyOptions solver);

/// Runs the fallback on `problem.mesh` with the solver's options; `problem` supplies the boundary
/// barrier flag and the source name. The Tutte starts are computed on `disk` (start_disk.h).
/// Keeps the first start whose result verifies within the bound, else the verified one of least
/// distortion.
/// `requested_start` names the start whose result `requested` did not verify or was over the bound.
StartFallback fall_back_to_tutte(const MappingProblem& problem, const StartDisk& disk,
                                 const SimplexAssemblyOptions& solver,
                                 const SimplexAssemblyObserver& observer,
                                 std::string requested_start, const Verification& requested);

}  // namespace sa
