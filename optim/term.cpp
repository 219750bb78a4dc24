#include "optim/term.h"

#include <cmath>
#include <sstream>

#include "optim/errors.h"

namespace sa {

void Term::set_weight(double weight) {
    if (!std::isfinite(weight) || weight < 0.0) {
        std::ostringstream msg;
        msg << "term '" << name_ << "': weight must be finite and >= 0, got " << weight;
        throw InvalidArgumentError(msg.str());
    }
    weight_ = weight;
}

}  // namespace sa
