#pragma once
// The JSON report of a Simplex Assembly run: input sizes, options, the initial and final quality
// metrics, what was verified, per-iteration records, Newton's termination and the time of each
// stage and phase.

#include <nlohmann/json.hpp>

#include "frontends/simplex_assembly/map_solve.h"
#include "geometry/quality/handle_feasibility.h"

namespace sa {

nlohmann::json map_report(const MappingProblem& problem, const SimplexAssemblyOptions& options,
                          const SimplexAssemblyResult& result);

nlohmann::json quality_json(const MapQuality& quality);

/// The stages a run passed, in order: [{stage, outcome, newton_steps, termination, seconds,
/// figures}], the enums by their names (stage_trace.h); termination and figures when present.
nlohmann::json stages_json(const StageTrace& stages);

/// One round of the vertex stage's continuation: {s, bound, max_distortion_before,
/// max_distortion_after, iterations, outcome, termination, undone_degenerate}; an infinite bound
/// and a termination when Newton did not run are null.
nlohmann::json continuation_round_json(const ContinuationRound& round);

/// One row per assembly iteration of `result`: energy, E~_assembly, lambda, time, and from the
/// first step on Newton's step length, line-search trials, gradient norm, decrement, the
/// regularization tau its factorization needed, and the iteration's and factorization's seconds.
nlohmann::json assembly_iterations_json(const SimplexAssemblyResult& result);

/// The seconds of each stage of `result` (StageTimes), with "newton_phases": the assembly's
/// Newton phases (optim/phase_times.h) summed over its iterations.
nlohmann::json solve_times_json(const SimplexAssemblyResult& result);

/// The report of a problem stopped before any optimization because its handles make it
/// infeasible: "input", "message" and "infeasible" (the counts and every simplex, handle and edge
/// found, handle_feasibility.h), "success": false.
nlohmann::json infeasible_report(const MappingProblem& problem,
                                 const InfeasibleProblemError& error);

/// Writes `report` (indented) through AtomicFile.
void write_json(const std::string& path, const nlohmann::json& report);

}  // namespace sa
