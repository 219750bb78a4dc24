#include "optim/progress_printer.h"

#include <cstdio>

namespace sa {

namespace {
/// "-" for fields that hold -1 ("not computed").
void field(char* buffer, std::size_t size, double value, const char* format) {
    if (value < 0.0) {
        std::snprintf(buffer, size, "%s", "-");
    } else {
        std::snprintf(buffer, size, format, value);
    }
}
}  // namespace

CallbackResult ProgressPrinter::operator()(const IterationContext& context) const {
    const IterationRecord& r = context.record;
    if (r.iteration == 0) {
        *out_ << "iter        energy      change      |g|inf   decrement      step  max step"
                 "  ls       tau     time\n";
    }
    char change[32], grad[32], dec[32], step[32], max_step[32], tau[32], ls[16];
    field(change, sizeof change, r.energy_change, "%.3e");
    field(grad, sizeof grad, r.gradient_norm, "%.3e");
    field(dec, sizeof dec, r.decrement, "%.3e");
    field(step, sizeof step, r.step_length, "%.3e");
    field(max_step, sizeof max_step, r.max_feasible_step, "%.2e");
    field(tau, sizeof tau, r.regularization, "%.1e");
    if (r.line_search_trials < 0) {
        std::snprintf(ls, sizeof ls, "-");
    } else {
        std::snprintf(ls, sizeof ls, "%d", r.line_search_trials);
    }
    char line[256];
    std::snprintf(line, sizeof line, "%4d  %12.6e  %10s  %10s  %10s  %8s  %8s  %2s  %8s  %6.2fs\n",
                  r.iteration, r.energy, change, grad, dec, step, max_step, ls, tau,
                  r.cumulative_time);
    *out_ << line;
    out_->flush();
    return CallbackResult::kContinue;
}

}  // namespace sa
