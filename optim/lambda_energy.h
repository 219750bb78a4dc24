#pragma once
// An element energy from a lambda (or any callable) written once over the scalar type, as in
// TinyAD: Problem::add_elements<N>() wraps it in a LambdaEnergy, which evaluates it with double
// for values and with Dual<N> for gradients and Hessians.
//
//   problem.add_elements<4>("springs", springs, [&](auto const& x, sa::Index e) {
//       using T = sa::ScalarOf<decltype(x)>;       // double or sa::Dual<4>
//       const T dx = x[2] - x[0], dy = x[3] - x[1];
//       const T stretch = sqrt(dx * dx + dy * dy) - rest_length[e];
//       return stretch * stretch;
//   });
//
// The callable takes the element's N variables (an Eigen::Matrix<T, N, 1>) and the element's
// index, and returns a T; return T(sa::kInfinity) where the element is infeasible (every return
// statement must then give a T: `return T(...)`). Call sqrt, exp, log, ... unqualified, so that
// they find sa::sqrt for Dual and std::sqrt for double (`using std::sqrt;` may be needed). It is
// called concurrently from several threads: it must not change shared state.
//
// An energy that needs max_step(), is_quadratic or its own projection is a struct
// (element_energy.h, autodiff_energy.h).

#include <type_traits>
#include <utility>

#include "optim/dual.h"
#include "optim/element_energy.h"

namespace sa {

/// The scalar type of an Eigen vector given to an element function: double or Dual<N>.
template <class Vector>
using ScalarOf = typename std::decay_t<Vector>::Scalar;

/// The ElementEnergy of arity N that evaluates `function(x, element)`.
template <int N, class Function>
struct LambdaEnergy {
    static constexpr int arity = N;
    Function function;

    double value(Index element, const Vec<N>& x) const {
        return static_cast<double>(function(x, element));
    }

    double value_gradient_hessian(Index element, const Vec<N>& x, Vec<N>& gradient,
                                  Mat<N>& hessian) const {
        const Dual<N> r = function(Dual<N>::variables(x), element);
        gradient = r.gradient;
        hessian = r.hessian;
        return r.value;
    }
};

/// LambdaEnergy<N, F>{function}, checking that the function takes an element's variables and
/// index and returns its scalar for both double and Dual<N>.
template <int N, class Function>
LambdaEnergy<N, std::decay_t<Function>> lambda_energy(Function&& function) {
    static_assert(
        std::is_convertible_v<
            std::invoke_result_t<const std::decay_t<Function>&, const Vec<N>&, Index>, double>,
        "an element function f(x, e) must return a double for x of doubles");
    static_assert(
        std::is_convertible_v<std::invoke_result_t<const std::decay_t<Function>&,
                                                   const Eigen::Matrix<Dual<N>, N, 1>&, Index>,
                              Dual<N>>,
        "an element function f(x, e) must return its scalar type T for x of T = Dual<N> (write "
        "it over the scalar type: `auto const& x`, and `return T(...)` in every branch)");
    return LambdaEnergy<N, std::decay_t<Function>>{std::forward<Function>(function)};
}

}  // namespace sa
