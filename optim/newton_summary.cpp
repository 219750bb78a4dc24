#include "optim/newton_summary.h"

#include <iomanip>
#include <sstream>

namespace sa {

std::string to_string(TerminationType type) {
    switch (type) {
        case TerminationType::kConverged:
            return "converged";
        case TerminationType::kUserSuccess:
            return "stopped by callback (success)";
        case TerminationType::kMaxIterations:
            return "iteration limit";
        case TerminationType::kMaxTime:
            return "time limit";
        case TerminationType::kUserAbort:
            return "aborted by callback";
        case TerminationType::kLineSearchFailed:
            return "line search failed";
        case TerminationType::kFactorizationFailed:
            return "factorization failed";
        case TerminationType::kInfeasibleStart:
            return "infeasible start";
        case TerminationType::kNonFinite:
            return "non-finite value";
    }
    return "unknown";
}

std::string NewtonSummary::brief_report() const {
    std::ostringstream out;
    out << std::setprecision(6) << "Newton: " << to_string(termination) << ", E " << initial_energy
        << " -> " << final_energy << " in " << num_steps() << " steps, " << std::setprecision(3)
        << times.total << " s";
    return out.str();
}

std::string NewtonSummary::phase_times() const {
    std::ostringstream out;
    out << std::fixed << std::setprecision(2) << "setup " << times.setup << ", evaluate "
        << times.evaluate << ", project " << times.project << ", assemble " << times.assemble
        << ", analyze " << times.analyze << ", factorize " << times.factorize << ", solve "
        << times.solve << ", line search " << times.line_search << ", callbacks "
        << times.callbacks;
    return out.str();
}

std::string NewtonSummary::full_report() const {
    std::ostringstream out;
    auto row = [&](const char* name, double seconds) {
        out << "  " << std::left << std::setw(14) << name << std::right << std::fixed
            << std::setprecision(4) << std::setw(10) << seconds << " s\n";
    };
    out << "Newton solver summary\n"
        << "  variables      " << num_variables << " (" << num_free_variables << " free)\n"
        << "  Hessian        " << hessian_nonzeros << " nonzeros in the lower triangle\n"
        << "  linear solver  " << to_string(linear_solver) << "\n"
        << "  threads        " << num_threads << "\n"
        << "  termination    " << to_string(termination) << ": " << message << "\n"
        << std::setprecision(12) << "  initial energy " << initial_energy << "\n"
        << "  final energy   " << final_energy << "\n"
        << std::setprecision(3) << "  final |g|_inf  " << final_gradient_norm << "\n"
        << "  steps          " << num_steps() << "\n"
        << "Time per phase\n";
    row("setup", times.setup);
    row("evaluate", times.evaluate);
    row("project", times.project);
    row("assemble", times.assemble);
    row("analyze", times.analyze);
    row("factorize", times.factorize);
    row("solve", times.solve);
    row("line search", times.line_search);
    row("callbacks", times.callbacks);
    row("total", times.total);
    return out.str();
}

}  // namespace sa
