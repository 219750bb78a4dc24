#pragma once
// Element energies of run-time arity: one type (one compiled class) for elements of any size,
// such as a barrier on the angle sum of a boundary vertex's fan, whose number of triangles
// varies from vertex to vertex. Each element of such a term names its own number of variables
// (RaggedElements), and the energy sees them as dynamic-size Eigen vectors and matrices. The
// fixed-arity interface (element_energy.h) remains the one for simplices, whose size the
// compiler knows: it keeps their blocks in registers.
//
// Required members (x: the element's n variables, n its arity):
//
//   static constexpr int arity = sa::kDynamicArity;
//   double value(Index element, ConstVectorRef x) const;
//   double value_gradient_hessian(Index element, ConstVectorRef x, VectorRef gradient,
//                                 MatrixRef hessian) const;
//       Value, gradient (n) and Hessian: B x n, the element Hessian's diagonal B x B blocks side by
//       side (block k is hessian.middleCols(B k, B)), B = hessian_block below, or n x n (the whole
//       Hessian, symmetric) when the energy declares none. Must write every entry of `gradient`
//       and `hessian`: they come uninitialized. May leave them unspecified when the value is +inf.
//
// Optional members, detected at compile time, as in element_energy.h:
//
//   static constexpr int hessian_block = B;     only the diagonal B x B blocks are assembled,
//                                               and every element's arity is a multiple of B
//   Index num_elements() const;                 checked against the number of elements
//   int element_arity(Index element) const;     the arity element `element`'s own data expect
//                                               (called after the count is checked):
//                                               Problem::add_term() checks each element's
//   double max_step(Index element, ConstVectorRef x, ConstVectorRef dx) const;
//   double value_gradient(Index element, ConstVectorRef x, VectorRef gradient) const;
//   bool project_hessian(Index element, ConstVectorRef x, MatrixRef hessian, ProjectionMode mode,
//                        double epsilon) const;   on the B x n (or n x n) form above
//   static constexpr bool is_quadratic = true;
//   static constexpr bool is_convex = true;
//
// Without project_hessian(), each block (B x B, or the whole n x n) is projected by
// project_hessian_block(), whose eigen-solvers are compiled once (hessian_projection.h).

#include <Eigen/Core>
#include <concepts>

#include "optim/element_energy.h"  // is_quadratic_energy, is_convex_energy
#include "optim/hessian_projection.h"
#include "optim/types.h"

namespace sa {

/// The `arity` of an element energy whose elements each have their own number of variables.
inline constexpr int kDynamicArity = Eigen::Dynamic;

template <class E>
concept DynamicElementEnergy = requires(const E& e, Index i, ConstVectorRef x, VectorRef g,
                                        MatrixRef h) {
    requires(E::arity == kDynamicArity);
    { e.value(i, x) } -> std::convertible_to<double>;
    { e.value_gradient_hessian(i, x, g, h) } -> std::convertible_to<double>;
};

template <class E>
concept DynamicHasMaxStep = requires(const E& e, Index i, ConstVectorRef x) {
    { e.max_step(i, x, x) } -> std::convertible_to<double>;
};

template <class E>
concept DynamicHasValueGradient = requires(const E& e, Index i, ConstVectorRef x, VectorRef g) {
    { e.value_gradient(i, x, g) } -> std::convertible_to<double>;
};

template <class E>
concept DynamicHasOwnProjection = requires(const E& e, Index i, ConstVectorRef x, MatrixRef h,
                                           ProjectionMode mode) {
    { e.project_hessian(i, x, h, mode, 0.0) } -> std::convertible_to<bool>;
};

template <class E>
concept HasElementArity = requires(const E& e, Index i) {
    { e.element_arity(i) } -> std::convertible_to<int>;
};

/// B of a run-time-arity energy's hessian_block, or 0 when each element's Hessian is dense.
template <class E>
constexpr int dynamic_hessian_block_of() {
    if constexpr (requires { E::hessian_block; }) {
        static_assert(E::hessian_block > 0, "hessian_block must be positive");
        return E::hessian_block;
    } else {
        return 0;
    }
}

}  // namespace sa
