#include "frontends/simplex_assembly/map_options.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "optim/enum_names.h"
#include "optim/errors.h"

namespace sa {

constexpr EnumName<Variant> kVariantNames[] = {
    {Variant::kReduced, "r-SA"}, {Variant::kFull, "f-SA"}, {Variant::kVertex, "v-SA"}};
constexpr EnumName<SolveMode> kSolveModeNames[] = {{SolveMode::kAuto, "auto"},
                                                   {SolveMode::kFull, "full"},
                                                   {SolveMode::kSubmesh, "submesh"},
                                                   {SolveMode::kDescent, "descent"}};

std::string to_string(Variant variant) {
    return enum_name(kVariantNames, variant);
}

std::string to_string(SolveMode mode) {
    return enum_name(kSolveModeNames, mode);
}

SolveMode parse_solve_mode(const std::string& name) {
    return parse_enum(kSolveModeNames, name, "mode");
}

Variant parse_variant(const std::string& name) {
    if (name == "r" || name == "reduced" || name == "r-SA") return Variant::kReduced;
    if (name == "f" || name == "full" || name == "f-SA") return Variant::kFull;
    if (name == "v" || name == "vertex" || name == "v-SA") return Variant::kVertex;
    throw InvalidArgumentError("unknown variant '" + name + "' (expected r, f or v)");
}

SimplexEnergyOptions simplex_energy_options(const SimplexAssemblyOptions& o) {
    SimplexEnergyOptions e;
    e.barrier_distortion = o.distortion;
    e.barrier.bound = o.bound;
    e.barrier.s = o.s;
    e.mapping_distortion = o.mapping_distortion;
    e.mu = o.mu;
    e.gamma = o.gamma;
    return e;
}

Initialization SimplexAssemblyOptions::effective_initialization() const {
    if (initialization) return *initialization;
    return distortion == DistortionType::kConformal ? Initialization::kClosestSimilarity
                                                    : Initialization::kClosestRotation;
}

void SimplexAssemblyOptions::validate() const {
    auto fail = [](const char* field, double value, const char* rule) {
        std::ostringstream msg;
        msg << field << " = " << value << ": " << rule;
        throw InvalidArgumentError(msg.str());
    };
    if (distortion != DistortionType::kConformal && distortion != DistortionType::kVolumetric &&
        distortion != DistortionType::kIsometric) {
        throw InvalidArgumentError("distortion = " + to_string(distortion) +
                                   ": the barrier needs conformal, volumetric or isometric");
    }
    if (!(bound > 1.0)) fail("bound", bound, "must be > 1 (every barrier distortion is >= 1)");
    if (!(s > 0.0) || !std::isfinite(s)) fail("s", s, "must be finite and > 0");
    if (!(gamma >= 0.0 && gamma <= 1.0)) fail("gamma", gamma, "must be in [0, 1]");
    if (!(mu >= 0.0) || !std::isfinite(mu)) fail("mu", mu, "must be finite and >= 0");
    AssemblyEngineOptions::validate();  // the schedule's, termination's and solver's fields
    if (!(handover_ratio >= 1.0)) fail("handover_ratio", handover_ratio, "must be >= 1");
    if (!(handle_tolerance > 0.0)) fail("handle_tolerance", handle_tolerance, "must be > 0");
    if (rings < 1) fail("rings", rings, "must be >= 1");
    if (max_rings < rings) fail("max_rings", max_rings, "must be >= rings");
    if (max_rounds < 0) fail("max_rounds", max_rounds, "must be >= 0");
    if (!(submesh_band >= 0.0 && submesh_band < 1.0))
        fail("submesh_band", submesh_band, "must be in [0, 1)");
    if (start_iterations < 0) fail("start_iterations", start_iterations, "must be >= 0");
    if (!(auto_bad_share >= 0.0 && auto_bad_share <= 1.0))
        fail("auto_bad_share", auto_bad_share, "must be in [0, 1]");
}

SimplexAssemblyOptions with_time_left(const SimplexAssemblyOptions& options,
                                      const TimeBudget& budget) {
    SimplexAssemblyOptions o = options;
    o.max_time_seconds = std::max(budget.remaining(), 1e-3);
    return o;
}

}  // namespace sa
