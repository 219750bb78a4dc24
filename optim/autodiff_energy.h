#pragma once
// Derive from AutodiffEnergy to get an ElementEnergy from a single template that computes the
// element's value for any scalar type; gradient and Hessian come from Dual<N>:
//
//   struct Spring : sa::AutodiffEnergy<Spring, 4> {           // 2 points in 2D: 4 variables
//       template <class T>
//       T energy(sa::Index e, const Eigen::Matrix<T, 4, 1>& x) const {
//           using std::sqrt;
//           const T dx = x[2] - x[0], dy = x[3] - x[1];
//           const T len = sqrt(dx * dx + dy * dy);
//           return (len - rest[e]) * (len - rest[e]);
//       }
//       std::vector<double> rest;
//   };
//
// Return +inf (T(sa::kInfinity)) for an infeasible element. Add max_step(), value_gradient() or
// project_hessian() to the derived type as for any ElementEnergy.

#include "optim/dual.h"
#include "optim/element_energy.h"

namespace sa {

template <class Derived, int N>
struct AutodiffEnergy {
    static constexpr int arity = N;

    double value(Index element, const Vec<N>& x) const {
        return static_cast<const Derived&>(*this).energy(element, x);
    }

    double value_gradient_hessian(Index element, const Vec<N>& x, Vec<N>& gradient,
                                  Mat<N>& hessian) const {
        const Dual<N> r = static_cast<const Derived&>(*this).energy(element, Dual<N>::variables(x));
        gradient = r.gradient;
        hessian = r.hessian;
        return r.value;
    }
};

}  // namespace sa
