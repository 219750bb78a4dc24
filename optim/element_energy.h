#pragma once
// The element-energy interface: what a type must provide to be summed over many elements by a
// Problem. An element energy of arity N evaluates one element from the N variables it names.
// (Elements whose number of variables varies, such as fans of any size, have an energy of
// run-time arity instead: dynamic_element_energy.h.)
//
// Required members (E is the energy type, x the element's N variables):
//
//   static constexpr int arity = N;
//   double value(Index element, const Vec<N>& x) const;
//       The energy of one element; +inf when x is infeasible (an inverted simplex, a distortion
//       over its bound). This is the cheap path used by the line search.
//   double value_gradient_hessian(Index element, const Vec<N>& x, Vec<N>& gradient,
//                                 Mat<N>& hessian) const;
//       Value, gradient (N) and Hessian (N x N, symmetric). May leave gradient and Hessian
//       unspecified when the value is +inf.
//
// Optional members, detected at compile time:
//
//   double max_step(Index element, const Vec<N>& x, const Vec<N>& dx) const;
//       The largest t > 0 such that x + s dx is feasible for every s in [0, t), or +inf. The
//       line search never evaluates beyond the smallest max_step over all elements.
//   static constexpr bool is_quadratic = true;
//       The Hessian is constant: it is evaluated, projected and assembled once, then scaled by
//       the term's weight. value_gradient(...) below, when present, spares the Hessian later.
//   static constexpr bool is_convex = true;
//       The Hessian is positive semidefinite wherever the energy is finite (a sum of squares of
//       linear functions, say): it is never projected (projecting the 18 x 18 blocks of 3D edge
//       assembly was a large part of a small solve's setup: docs/measurements.md).
//   double value_gradient(Index element, const Vec<N>& x, Vec<N>& gradient) const;
//   bool project_hessian(Index element, const Vec<N>& x, Mat<N>& hessian, ProjectionMode mode,
//                        double epsilon) const;
//       Replaces the element's Hessian at x in place by a positive (semi)definite one, with the
//       modes and epsilon of project_hessian_block() but faster, from what the energy knows about
//       its structure; returns true when it changed the Hessian. SimplexEnergy's gives
//       project_hessian_block()'s result; VertexSimplexEnergy's projects in A instead (see there).
//
//   static constexpr int hessian_block = B;   (B divides N)
//       Only the diagonal B x B blocks of the element Hessian are assembled: entries (i, j) with
//       i / B != j / B are dropped, and neither the Hessian's sparsity pattern nor its
//       factorization sees them. For an element that couples several groups of variables only
//       through a low-rank term (an angle-sum barrier over the tetrahedra around a vertex), whose
//       project_hessian() then majorizes that coupling by a block-diagonal matrix: a dense
//       element of many such groups makes the factorization several times denser.
//
//   Index num_elements() const;
//       How many elements the energy's per-element data covers: Problem::add_term() rejects a
//       term whose element count differs.
//
// Per-element rest data (areas, inverse rest matrices, ...) lives in the energy object and is
// indexed by the element number passed to every call. Calls are made concurrently from several
// threads: the member functions must be const and free of shared mutable state.

#include <concepts>
#include <type_traits>

#include "optim/hessian_projection.h"
#include "optim/types.h"

namespace sa {

template <class E>
concept ElementEnergy = requires(const E& e, Index i, const Vec<E::arity>& x, Vec<E::arity>& g,
                                 Mat<E::arity>& h) {
    requires(E::arity > 0);
    { e.value(i, x) } -> std::convertible_to<double>;
    { e.value_gradient_hessian(i, x, g, h) } -> std::convertible_to<double>;
};

template <class E>
concept HasMaxStep = requires(const E& e, Index i, const Vec<E::arity>& x) {
    { e.max_step(i, x, x) } -> std::convertible_to<double>;
};

template <class E>
concept HasValueGradient = requires(const E& e, Index i, const Vec<E::arity>& x, Vec<E::arity>& g) {
    { e.value_gradient(i, x, g) } -> std::convertible_to<double>;
};

template <class E>
concept HasElementCount = requires(const E& e) {
    { e.num_elements() } -> std::convertible_to<std::size_t>;
};

template <class E>
concept HasOwnProjection = requires(const E& e, Index i, const Vec<E::arity>& x, Mat<E::arity>& h,
                                    ProjectionMode mode) {
    { e.project_hessian(i, x, h, mode, 0.0) } -> std::convertible_to<bool>;
};

template <class E>
constexpr bool is_convex_energy() {
    if constexpr (requires { E::is_convex; }) {
        return E::is_convex;
    } else {
        return false;
    }
}

template <class E>
constexpr int hessian_block_of() {
    if constexpr (requires { E::hessian_block; }) {
        static_assert(E::hessian_block > 0 && E::arity % E::hessian_block == 0,
                      "hessian_block must divide the arity");
        return E::hessian_block;
    } else {
        return E::arity;
    }
}

template <class E>
constexpr bool is_quadratic_energy() {
    if constexpr (requires { E::is_quadratic; }) {
        return E::is_quadratic;
    } else {
        return false;
    }
}

}  // namespace sa
