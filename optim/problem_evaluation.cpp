#include "optim/problem_evaluation.h"

#include <string>

#include "optim/detail/hessian_assembler.h"
#include "optim/errors.h"

namespace sa {

ProblemEvaluator::ProblemEvaluator(const Problem& problem, ProjectionMode projection,
                                   double epsilon)
    : problem_(&problem), projection_(projection), epsilon_(epsilon) {
    if (!(epsilon >= 0.0)) {
        throw InvalidArgumentError("ProblemEvaluator: epsilon must be >= 0, got " +
                                   std::to_string(epsilon));
    }
}

ProblemEvaluator::~ProblemEvaluator() = default;

HessianAssembler& ProblemEvaluator::assembler() {
    if (!assembler_ || !assembler_->matches(*problem_))
        assembler_ = std::make_unique<HessianAssembler>(*problem_);
    return *assembler_;
}

double ProblemEvaluator::value(const Eigen::VectorXd& x) const {
    if (x.size() != problem_->num_variables()) {
        throw InvalidArgumentError("ProblemEvaluator::value: expected " +
                                   std::to_string(problem_->num_variables()) + " values, got " +
                                   std::to_string(x.size()));
    }
    return problem_->value(x);
}

ProblemEvaluation ProblemEvaluator::evaluate(const Eigen::VectorXd& x) {
    if (x.size() != problem_->num_variables()) {
        throw InvalidArgumentError("ProblemEvaluator::evaluate: expected " +
                                   std::to_string(problem_->num_variables()) + " values, got " +
                                   std::to_string(x.size()));
    }
    HessianAssembler& a = assembler();
    PhaseTimes times;
    ProblemEvaluation result;
    result.value = a.evaluate(*problem_, x, projection_, epsilon_, times).energy;
    if (std::isfinite(result.value)) {
        result.gradient = a.gradient();
        result.hessian = a.hessian().selfadjointView<Eigen::Lower>();
    }
    return result;
}

const std::vector<Index>& ProblemEvaluator::free_variables() {
    return assembler().variable_of_free();
}

Eigen::VectorXd ProblemEvaluator::expand(const Eigen::VectorXd& free_values) {
    const std::vector<Index>& variables = free_variables();
    if (free_values.size() != Eigen::Index(variables.size())) {
        throw InvalidArgumentError("ProblemEvaluator::expand: expected " +
                                   std::to_string(variables.size()) + " values, got " +
                                   std::to_string(free_values.size()));
    }
    Eigen::VectorXd all = Eigen::VectorXd::Zero(problem_->num_variables());
    for (std::size_t i = 0; i < variables.size(); ++i) all[variables[i]] = free_values[i];
    return all;
}

ProblemEvaluation evaluate(const Problem& problem, const Eigen::VectorXd& x,
                           ProjectionMode projection, double epsilon) {
    return ProblemEvaluator(problem, projection, epsilon).evaluate(x);
}

}  // namespace sa
