#include "energies/distortion.h"

#include "optim/errors.h"

namespace sa {

std::string to_string(DistortionType type) {
    switch (type) {
        case DistortionType::kConformal: return "conformal";
        case DistortionType::kVolumetric: return "volumetric";
        case DistortionType::kIsometric: return "isometric";
        case DistortionType::kDirichlet: return "dirichlet";
        case DistortionType::kSymmetricDirichlet: return "symmetric-dirichlet";
        case DistortionType::kGreenLagrange: return "green-lagrange";
        case DistortionType::kAsap: return "asap";
        case DistortionType::kArap: return "arap";
        case DistortionType::kLscm: return "lscm";
        case DistortionType::kDifference: return "difference";
    }
    return "unknown";
}

const std::vector<DistortionType>& all_distortions() {
    static const std::vector<DistortionType> all = {
        DistortionType::kConformal,     DistortionType::kVolumetric, DistortionType::kIsometric,
        DistortionType::kDirichlet,     DistortionType::kSymmetricDirichlet,
        DistortionType::kGreenLagrange, DistortionType::kAsap,       DistortionType::kArap,
        DistortionType::kLscm,          DistortionType::kDifference};
    return all;
}

DistortionType parse_distortion(const std::string& name) {
    std::string names;
    for (DistortionType type : all_distortions()) {
        if (to_string(type) == name) return type;
        names += (names.empty() ? "" : ", ") + to_string(type);
    }
    throw InvalidArgumentError("unknown distortion '" + name + "' (expected one of: " + names + ")");
}

}  // namespace sa
