#pragma once
// An iteration callback that prints one fixed-width row per iteration to a stream the caller
// gives (never to stdout on its own):
//
//   iter        energy     change     |g|inf  decrement     step  max step  ls        tau   time
//      0  1.234567e+02          -          -          -        -         -   -          -  0.00s

#include <ostream>

#include "optim/iteration_callback.h"

namespace sa {

class ProgressPrinter {
  public:
    explicit ProgressPrinter(std::ostream& out) : out_(&out) {}
    CallbackResult operator()(const IterationContext& context) const;

  private:
    std::ostream* out_;
};

}  // namespace sa
