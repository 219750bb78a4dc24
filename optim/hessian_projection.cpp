#include "optim/hessian_projection.h"

namespace sa {

std::string to_string(ProjectionMode mode) {
    switch (mode) {
        case ProjectionMode::kClamp: return "clamp";
        case ProjectionMode::kAbs: return "abs";
        case ProjectionMode::kShift: return "shift";
        case ProjectionMode::kNone: return "none";
    }
    return "unknown";
}

}  // namespace sa
