#include "optim/newton_solver.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "optim/detail/hessian_assembler.h"
#include "optim/parallel.h"
#include "optim/stopwatch.h"

namespace sa {

namespace {

std::string format(const char* what, double value) {
    std::ostringstream out;
    out << what << value;
    return out.str();
}

/// Whether the n values are all finite, on the arena's threads (a serial pass over a mid-size
/// Hessian was a visible part of an iteration's time outside the timed phases).
bool all_finite(const double* values, Index n) {
    return tbb::parallel_reduce(
        tbb::blocked_range<Index>(0, n, 1 << 15), true,
        [&](const tbb::blocked_range<Index>& range, bool finite) {
            return finite && Eigen::Map<const Eigen::VectorXd>(values + range.begin(), range.size())
                                 .allFinite();
        },
        [](bool a, bool b) { return a && b; });
}

}  // namespace

NewtonSolver::NewtonSolver(NewtonOptions options) : options_(std::move(options)) {}
NewtonSolver::~NewtonSolver() = default;

NewtonSummary NewtonSolver::solve(Problem& problem) {
    std::string error;
    if (!options_.is_valid(&error)) throw InvalidArgumentError(error);
    const int threads = options_.num_threads > 0 ? options_.num_threads : default_thread_count();
    tbb::task_arena arena(threads);
    NewtonSummary summary;
    arena.execute([&] { summary = run(problem); });
    summary.num_threads = threads;
    return summary;
}

NewtonSummary NewtonSolver::run(Problem& problem) {
    const NewtonOptions& opt = options_;
    Stopwatch total;
    NewtonSummary summary;
    PhaseTimes& times = summary.times;

    const Index n = problem.num_variables();
    summary.num_variables = n;
    Eigen::VectorXd x = problem.variables();
    std::vector<double> term_values;
    double energy = problem.value(x, &term_values);
    summary.initial_energy = summary.final_energy = energy;

    auto finish = [&](TerminationType type, std::string message) {
        summary.termination = type;
        summary.message = std::move(message);
        summary.final_energy = energy;
        if (linear_solver_) summary.linear_solver = linear_solver_->active_type();
        times.total = total.seconds();
        return summary;
    };
    // Runs the callbacks on the last record; returns true when one of them stops the solve.
    auto run_callbacks = [&]() -> bool {
        Stopwatch cb;
        const IterationContext context{summary.iterations.back(), problem, term_values};
        for (const IterationCallback& callback : opt.callbacks) {
            const CallbackResult result = callback(context);
            if (result == CallbackResult::kContinue) continue;
            times.callbacks += cb.seconds();
            finish(result == CallbackResult::kStopSuccess ? TerminationType::kUserSuccess
                                                          : TerminationType::kUserAbort,
                   result == CallbackResult::kStopSuccess ? "a callback reported convergence"
                                                          : "a callback aborted the solve");
            return true;
        }
        times.callbacks += cb.seconds();
        return false;
    };

    IterationRecord start;
    start.iteration = 0;
    start.energy = energy;
    start.cumulative_time = total.seconds();
    summary.iterations.push_back(start);
    if (!(std::abs(energy) < kInfinity)) {
        return energy == kInfinity
                   ? finish(
                         TerminationType::kInfeasibleStart,
                         "the energy is +inf at the initial variables (an element is infeasible)")
                   : finish(TerminationType::kNonFinite,
                            "the energy is NaN at the initial variables");
    }
    if (run_callbacks()) return summary;

    auto out_of_time = [&] { return total.seconds() > opt.max_time_seconds; };
    auto stop_for_time = [&](const char* where) {
        return finish(TerminationType::kMaxTime,
                      format("reached max_time_seconds = ", opt.max_time_seconds) + where);
    };
    // The Hessian's pattern and its symbolic factorization only now: a callback that takes the
    // start (a hand-over at iteration 0) needs neither, nor a solve whose time is up already
    // (on a large system each costs about as much as an iteration, so the limit is checked
    // before each).
    if (out_of_time()) return stop_for_time(" before the Hessian's setup");
    Stopwatch watch;
    if (!assembler_ || !assembler_->matches(problem)) {
        assembler_.reset();
        linear_solver_.reset();
        assembler_ = std::make_unique<HessianAssembler>(problem);
        times.setup += watch.lap();
    }
    HessianAssembler& assembler = *assembler_;
    if (!linear_solver_ || requested_solver_ != opt.linear_solver) {
        if (out_of_time()) return stop_for_time(" before the symbolic analysis");
        requested_solver_ = opt.linear_solver;
        linear_solver_ = std::make_unique<LinearSolver>(opt.linear_solver);
        if (assembler.num_free() > 0) linear_solver_->analyze(assembler.hessian());
        times.analyze += watch.lap();
    }
    const Index nf = assembler.num_free();
    summary.num_free_variables = nf;
    summary.hessian_nonzeros = assembler.hessian().nonZeros();
    summary.linear_solver = linear_solver_->active_type();
    if (nf == 0) return finish(TerminationType::kConverged, "no free variables");

    const LineSearchOptions& ls = opt.line_search;
    double next_step = ls.initial_step;
    std::vector<double> shift(nf), regularizable(nf), diagonal(nf);
    Eigen::VectorXd dx = Eigen::VectorXd::Zero(n);
    Eigen::VectorXd trial(n);
    std::vector<double> trial_term_values;
    Eigen::VectorXd longer;  // the expanding line search's trials beyond the full step
    std::vector<double> longer_term_values;

    for (int k = 1;; ++k) {
        // Also before the first iteration: the setup and analysis above may have used the time
        // already, and one iteration of a large system costs as much again.
        if (out_of_time()) return stop_for_time(k == 1 ? " before the first iteration" : "");
        if (k > opt.max_iterations) {
            return finish(TerminationType::kMaxIterations,
                          "reached max_iterations = " + std::to_string(opt.max_iterations));
        }
        Stopwatch iteration_watch;
        IterationRecord record;
        record.iteration = k;

        // Energy, gradient and projected Hessian at x (weights may have changed since the step).
        HessianAssembler::Evaluation eval =
            assembler.evaluate(problem, x, opt.projection, opt.projection_epsilon, times);
        energy = eval.energy;
        if (!std::isfinite(energy)) {
            return finish(TerminationType::kNonFinite,
                          format("the energy became non-finite at the current point: ", energy));
        }
        const Eigen::VectorXd& g = assembler.gradient();
        Eigen::SparseMatrix<double>& H = assembler.hessian();
        const double gradient_norm = g.size() ? g.lpNorm<Eigen::Infinity>() : 0.0;
        summary.final_gradient_norm = gradient_norm;
        if (!std::isfinite(gradient_norm) || !all_finite(H.valuePtr(), H.nonZeros())) {
            return finish(TerminationType::kNonFinite, "the gradient or Hessian is not finite");
        }
        if (opt.gradient_tolerance > 0.0 && gradient_norm <= opt.gradient_tolerance) {
            return finish(TerminationType::kConverged,
                          format("gradient max-norm ", gradient_norm) +
                              format(" <= gradient_tolerance ", opt.gradient_tolerance));
        }

        // Block shifts (Hessian only) and which variables take tau.
        std::fill(shift.begin(), shift.end(), 0.0);
        std::fill(regularizable.begin(), regularizable.end(), 1.0);
        for (BlockId b = 0; b < problem.num_variable_blocks(); ++b) {
            const VariableBlock& block = problem.variable_block(b);
            for (Index v = block.begin; v < block.end; ++v) {
                const Index j = assembler.free_of_variable()[v];
                if (j < 0) continue;
                shift[j] = block.hessian_shift;
                regularizable[j] = block.regularize_on_failure ? 1.0 : 0.0;
            }
        }
        double* values = H.valuePtr();
        const auto& diag_pos = assembler.diagonal_positions();
        for (Index j = 0; j < nf; ++j) {
            values[diag_pos[j]] += shift[j];
            diagonal[j] = values[diag_pos[j]];
        }

        // Factorize, escalating tau on failure.
        Stopwatch factor_watch;
        double tau = 0.0;
        int factorizations = 1;
        FactorizationStatus status = linear_solver_->factorize(H);
        if (status == FactorizationStatus::kNotPositiveDefinite) {
            tau = last_regularization_ > 0.0
                      ? std::max(opt.regularization.initial,
                                 last_regularization_ / opt.regularization.factor)
                      : opt.regularization.initial;
            while (true) {
                for (Index j = 0; j < nf; ++j)
                    values[diag_pos[j]] = diagonal[j] + tau * regularizable[j];
                status = linear_solver_->factorize(H);
                ++factorizations;
                if (status != FactorizationStatus::kNotPositiveDefinite) break;
                if (tau >= opt.regularization.max) break;
                // Each retry is a full factorization: overrun the limit by at most one.
                if (out_of_time()) {
                    times.factorize += factor_watch.seconds();
                    return stop_for_time(" while regularizing the Hessian (tau escalation)");
                }
                tau = std::min(tau * opt.regularization.factor, opt.regularization.max);
            }
        }
        const double factorization_time = factor_watch.seconds();
        times.factorize += factorization_time;
        if (status != FactorizationStatus::kSuccess) {
            return finish(TerminationType::kFactorizationFailed,
                          status == FactorizationStatus::kFailed
                              ? "the linear solver failed: " + linear_solver_->fallback_reason()
                              : format("not positive definite even with tau = ", tau));
        }
        last_regularization_ = tau;

        Stopwatch solve_watch;
        const Eigen::VectorXd d = linear_solver_->solve(-g);
        times.solve += solve_watch.seconds();
        if (!d.allFinite())
            return finish(TerminationType::kNonFinite, "the Newton step is not finite");
        const double slope = g.dot(d);
        const double decrement = -0.5 * slope;
        if (opt.decrement_tolerance > 0.0 &&
            decrement <= opt.decrement_tolerance * std::max(1.0, std::abs(energy))) {
            return finish(TerminationType::kConverged,
                          format("Newton decrement ", decrement) +
                              format(" <= decrement_tolerance * max(1, |E|) = ",
                                     opt.decrement_tolerance * std::max(1.0, std::abs(energy))));
        }
        if (!(slope < 0.0)) {
            return finish(
                TerminationType::kLineSearchFailed,
                format("the Newton step is not a descent direction (g.d = ", slope) + ")");
        }

        // Line search.
        Stopwatch search_watch;
        const std::vector<Index>& var_of_free = assembler.variable_of_free();
        for (Index j = 0; j < nf; ++j) dx[var_of_free[j]] = d[j];
        const double max_feasible = problem.max_step(x, dx);
        double alpha = ls.reuse_previous_step ? next_step : ls.initial_step;
        if (max_feasible < kInfinity) alpha = std::min(alpha, ls.max_step_fraction * max_feasible);
        int trials = 0;
        bool accepted = false;
        double trial_energy = kInfinity;
        while (trials < ls.max_trials && alpha > 0.0) {
            trial = x + alpha * dx;
            trial_energy = problem.value(trial, &trial_term_values);
            ++trials;
            if (trial_energy < energy && trial_energy <= energy + ls.armijo * alpha * slope) {
                accepted = true;
                break;
            }
            alpha *= ls.backtracking_factor;
        }
        times.line_search += search_watch.seconds();
        if (!accepted) {
            return finish(TerminationType::kLineSearchFailed,
                          "no decrease along the Newton step after " + std::to_string(trials) +
                              format(" trials (largest feasible step ", max_feasible) + ")");
        }
        // The quadratic model's decrease at alpha: -(alpha g.d + alpha^2 d.Hd / 2), with
        // d.Hd = -g.d for the factorized H.
        const double predicted = -slope * alpha * (1.0 - 0.5 * alpha);
        if (ls.expand && trials == 1 && alpha == ls.initial_step &&
            energy - trial_energy > predicted) {
            while (trials < ls.max_trials && (max_feasible == kInfinity ||
                                              2.0 * alpha <= ls.max_step_fraction * max_feasible)) {
                longer = x + (2.0 * alpha) * dx;
                const double longer_energy = problem.value(longer, &longer_term_values);
                ++trials;
                if (!(longer_energy < trial_energy)) break;
                alpha *= 2.0;
                trial_energy = longer_energy;
                trial.swap(longer);
                trial_term_values.swap(longer_term_values);
            }
            next_step = ls.initial_step;
        } else {
            next_step = trials == 1 ? std::min(2.0 * alpha, ls.initial_step) : alpha;
        }

        record.energy = trial_energy;
        record.energy_change = energy - trial_energy;
        record.gradient_norm = gradient_norm;
        record.decrement = decrement;
        record.step_length = alpha;
        record.max_feasible_step = max_feasible;
        record.line_search_trials = trials;
        record.regularization = tau;
        record.factorizations = factorizations;
        record.factorization_time = factorization_time;
        record.projected_blocks = eval.projected_blocks;

        const double previous_energy = energy;
        x.swap(trial);
        problem.set_variables(x);
        energy = trial_energy;
        term_values.swap(trial_term_values);
        record.iteration_time = iteration_watch.seconds();
        record.cumulative_time = total.seconds();
        summary.iterations.push_back(record);

        if (run_callbacks()) return summary;
        if (opt.function_tolerance > 0.0 &&
            previous_energy - energy <=
                opt.function_tolerance * std::max(1.0, std::abs(previous_energy))) {
            return finish(
                TerminationType::kConverged,
                format("energy change ", previous_energy - energy) +
                    format(" <= function_tolerance * max(1, |E|) = ",
                           opt.function_tolerance * std::max(1.0, std::abs(previous_energy))));
        }
    }
}

NewtonSummary solve(Problem& problem, const NewtonOptions& options) {
    return NewtonSolver(options).solve(problem);
}

}  // namespace sa
