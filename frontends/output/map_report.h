#pragma once
// The JSON report of a Simplex Assembly run: input sizes, options, the initial and final quality
// metrics, what was verified, per-iteration records, Newton's termination and the time of each
// stage and phase.

#include <nlohmann/json.hpp>

#include "frontends/simplex_assembly/simplex_assembly.h"

namespace sa {

nlohmann::json map_report(const MappingProblem& problem, const SimplexAssemblyOptions& options,
                          const SimplexAssemblyResult& result);

nlohmann::json quality_json(const MapQuality& quality);

/// Writes `report` (indented) through AtomicFile.
void write_json(const std::string& path, const nlohmann::json& report);

}  // namespace sa
