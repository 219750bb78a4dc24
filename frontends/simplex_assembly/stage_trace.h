#pragma once
// A run's path through the stages of Simplex Assembly, typed: which stages ran, in order, how
// each ended (an enum, never text), its Newton steps, its time and its figures. The mesh driver
// (frontends/simplex_assembly/map_solve.h) records it in SimplexAssemblyResult::stages, the report
// serializes it ("stages", frontends/output/map_report.h) and the tests assert on it.
//
// The stages a run of the mesh driver can pass, in order (docs/algorithm.md):
//   kStartUntangle  the submesh mode's start, untangled in vertex variables when the initial map
//                   and the local/global iterations leave bad simplices (submesh_start.h);
//                   outcome: UntangleOutcome
//   kAssembly       the engine's lambda schedule on the disassembled simplices (engine.h), ended
//                   by its own tests or by the hand-over of the mesh recovered by Eq. 6 (the
//                   driver's hook: AssemblyStop::kHook); outcome: AssemblyStop
//   kVertexStage    Newton in vertex variables from the recovered mesh (in the descent mode,
//                   from the start: once per bound round), with E_C's exponent continuation
//                   (vertex_stage.h); outcome: VertexStageOutcome
//   kFallback       the last resort when no valid map was found: untangling in vertex variables,
//                   then the vertex stage (untangle_fallback.h); outcome: FallbackOutcome
// The submesh mode's rounds are typed records of their own (SubmeshStats::rounds) and the
// verification's figures are SimplexAssemblyResult::verification.

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "frontends/simplex_assembly/engine_options.h"
#include "optim/newton_summary.h"

namespace sa {

enum class Stage { kStartUntangle, kAssembly, kVertexStage, kFallback };

/// How the untangling in vertex variables ended (untangle.h).
enum class UntangleOutcome {
    kNothingFree,         ///< no simplex has a free vertex: nothing ran
    kStartUntangled,      ///< the start was untangled (and accepted): nothing ran
    kUntangled,           ///< stopped at the first untangled iterate it accepted
    kUntangledConverged,  ///< untangled, and the energy converged at the final eps
    kNotUntangled,        ///< a simplex with a free vertex is still inverted
};

/// How the vertex stage ended (vertex_stage.h). In the outcomes that say "ran", Newton ran and
/// NewtonSummary::termination says how it stopped.
enum class VertexStageOutcome {
    kRan,                     ///< ran from the recovered mesh (or the stage's given start)
    kRanStartKept,            ///< ran, but found no lower energy at the exponent asked for
    kRanUndone,               ///< ran, but its result had degenerate simplices and its start
                              ///< none: the start is kept
    kRanFromInitialMap,       ///< the recovered mesh was no valid start: ran from the initial map
    kInitialMapKept,          ///< neither was a valid start; the initial map, inversion-free but
                              ///< beyond what the barrier represents, is kept
    kSkippedTimeLimit,        ///< the time limit was reached before it
    kSkippedNothingMoved,     ///< the submesh mode's start was the valid initial map, unchanged
    kSkippedInfeasibleStart,  ///< the start has an inverted simplex, one over the bound or
                              ///< (projected by the plugins) a plugin barrier at +inf
    kSkippedPluginCannotProject,  ///< a plugin cannot project the start onto its constraints
    kSkippedBeyondExponentCap,    ///< simplices so distorted that the barrier cannot rank the
                                  ///< others (barrier.h's exponent cap; forced by handles)
    kSkippedWrappedStart,  ///< every simplex positive, but the start wraps around an interior
                           ///< edge or vertex: the barrier would keep the wrap
};

/// Whether Newton ran in the vertex stage.
bool newton_ran(VertexStageOutcome outcome);

/// One run of Newton in the vertex stage (vertex_stage.h): the single run, or a round of its
/// exponent continuation.
struct ContinuationRound {
    double s = 1.0;                      ///< E_C's exponent
    double bound = kInfinity;            ///< E_C's bound K
    double max_distortion_before = 0.0;  ///< the largest barrier distortion at its start
    double max_distortion_after = 0.0;   ///< and of what it kept
    int iterations = 0;                  ///< Newton steps
    VertexStageOutcome outcome = VertexStageOutcome::kRan;
    TerminationType termination = TerminationType::kConverged;  ///< when Newton ran
    Index undone_degenerate = 0;  ///< kRanUndone: the degenerate simplices it left
};

/// How the last resort ended (untangle_fallback.h).
enum class FallbackOutcome {
    kReplaced,  ///< fewer bad simplices than the result, which it replaced
    kNoBetter,  ///< no fewer bad simplices: the result is kept
};

using StageOutcome =
    std::variant<AssemblyStop, UntangleOutcome, VertexStageOutcome, FallbackOutcome>;

struct StageRecord {
    Stage stage = Stage::kAssembly;
    StageOutcome outcome = {};
    int newton_steps = 0;
    std::optional<TerminationType> termination = {};  ///< how Newton stopped, when it ran
    double seconds = 0.0;
    /// The stage's figures in words, for the report and the summary (the exponent
    /// continuation's rounds, the hand-over, the simplices beyond the exponent cap, ...); empty
    /// when there are none.
    std::string figures = {};
};

/// The records of one run, in the order the stages ran (a stage can run more than once: the
/// vertex stage inside the fallback).
struct StageTrace {
    std::vector<StageRecord> records;

    StageRecord& add(Stage stage, StageOutcome outcome);
    /// The last record of `stage`, or nullptr when it did not run.
    const StageRecord* last(Stage stage) const;
    /// The last outcome of `stage` when it is an `Outcome`.
    template <class Outcome>
    std::optional<Outcome> outcome(Stage stage) const {
        const StageRecord* r = last(stage);
        if (r == nullptr || !std::holds_alternative<Outcome>(r->outcome)) return std::nullopt;
        return std::get<Outcome>(r->outcome);
    }
    /// Whether Newton ran in any vertex stage (the driver's or the fallback's).
    bool vertex_stage_ran() const;
};

std::string to_string(Stage stage);
std::string to_string(UntangleOutcome outcome);
std::string to_string(VertexStageOutcome outcome);
std::string to_string(FallbackOutcome outcome);
std::string to_string(const StageOutcome& outcome);

}  // namespace sa
