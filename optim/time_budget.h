#pragma once
// A wall-clock budget in seconds that starts when it is made: the stages of a long run each take
// what is left, so that a limit given once holds for the whole run. An infinite budget never runs
// out.

#include "optim/stopwatch.h"

namespace sa {

class TimeBudget {
  public:
    explicit TimeBudget(double seconds) : seconds_(seconds) {}
    /// Seconds left (negative once overrun; infinite for an infinite budget).
    double remaining() const { return seconds_ - watch_.seconds(); }
    bool exhausted() const { return !(remaining() > 0.0); }

  private:
    double seconds_;
    Stopwatch watch_;
};

}  // namespace sa
