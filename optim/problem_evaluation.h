#pragma once
// E, its gradient and its projected Hessian at a point, for callers who run their own loop (as
// TinyAD's eval_with_hessian_proj): the same assembly as the Newton solver's, per-element
// Hessian projection included, over the problem's free variables.
//
//   sa::ProblemEvaluator evaluator(problem);
//   for (int i = 0; i < 50; ++i) {
//       const sa::ProblemEvaluation e = evaluator.evaluate(x);
//       Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(e.hessian);
//       const Eigen::VectorXd step = evaluator.expand(ldlt.solve(-e.gradient));
//       ... a line search on evaluator.value(x + a * step) ...
//   }
//
// The free variables are those not fixed that some term uses; without fixed or unused variables
// they are all the variables, in order. Variable blocks' Hessian shifts are the Newton solver's
// and are not added here. Evaluations run on the calling thread's TBB arena (all cores by
// default; wrap the calls in a tbb::task_arena to use fewer) and give the same bits on any number
// of threads.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "optim/hessian_projection.h"
#include "optim/problem.h"

namespace sa {

class HessianAssembler;

struct ProblemEvaluation {
    /// E(x), weighted; +inf when an element is infeasible (the gradient and Hessian are then
    /// empty), NaN when an element's value is.
    double value = 0.0;
    /// dE/dx over the free variables (#free).
    Eigen::VectorXd gradient;
    /// The Hessian over the free variables (#free x #free, both triangles), each element's
    /// block projected as `projection` says before it is summed.
    Eigen::SparseMatrix<double> hessian;
};

class ProblemEvaluator {
  public:
    /// An evaluator of `problem`, which must outlive it. The sparsity pattern is built once and
    /// rebuilt when the problem's structure changes (terms added, variables fixed or freed).
    explicit ProblemEvaluator(const Problem& problem,
                              ProjectionMode projection = ProjectionMode::kClamp,
                              double epsilon = 1e-8);
    ~ProblemEvaluator();
    ProblemEvaluator(const ProblemEvaluator&) = delete;
    ProblemEvaluator& operator=(const ProblemEvaluator&) = delete;

    /// E(x) alone (+inf when infeasible): the cheap call for a line search.
    double value(const Eigen::VectorXd& x) const;
    /// E, gradient and projected Hessian at x (problem.num_variables() values; the free
    /// variables' are read, the others must hold their fixed values).
    ProblemEvaluation evaluate(const Eigen::VectorXd& x);

    /// The variable of each row of the gradient and Hessian.
    const std::vector<Index>& free_variables();
    /// A vector over the free variables spread over all variables, zero at the others.
    Eigen::VectorXd expand(const Eigen::VectorXd& free_values);

  private:
    HessianAssembler& assembler();

    const Problem* problem_;
    ProjectionMode projection_;
    double epsilon_;
    std::unique_ptr<HessianAssembler> assembler_;
};

/// ProblemEvaluator(problem, projection, epsilon).evaluate(x), building the pattern each call.
ProblemEvaluation evaluate(const Problem& problem, const Eigen::VectorXd& x,
                           ProjectionMode projection = ProjectionMode::kClamp,
                           double epsilon = 1e-8);

}  // namespace sa
