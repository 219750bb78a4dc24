#pragma once
// Wall-clock seconds spent in each phase of a Newton solve, accumulated over its iterations.

namespace sa {

struct PhaseTimes {
    double setup = 0.0;        ///< Hessian pattern, gather lists, constant (quadratic) terms
    double evaluate = 0.0;     ///< element values, gradients and Hessians
    double project = 0.0;      ///< per-element Hessian projection
    double assemble = 0.0;     ///< summing element blocks into the sparse matrix and gradient
    double analyze = 0.0;      ///< symbolic factorization (ordering), once per pattern
    double factorize = 0.0;    ///< numeric factorization, retries with regularization included
    double solve = 0.0;        ///< triangular solves
    double line_search = 0.0;  ///< largest feasible step and trial evaluations
    double callbacks = 0.0;    ///< iteration callbacks (progress output, caller's tests)
    double total = 0.0;

    PhaseTimes& operator+=(const PhaseTimes& o) {
        setup += o.setup;
        evaluate += o.evaluate;
        project += o.project;
        assemble += o.assemble;
        analyze += o.analyze;
        factorize += o.factorize;
        solve += o.solve;
        line_search += o.line_search;
        callbacks += o.callbacks;
        total += o.total;
        return *this;
    }
};

}  // namespace sa
