#pragma once
// The boundary-angle barriers of a tetrahedral map (issue 21; the 3D form of E_theta in the
// paper's 5.1, "Locally injective mapping"): with every tetrahedron positively oriented, a map is
// locally injective at the boundary when
//   - at every boundary edge e, theta_e = the sum of the dihedral angles at e of the tetrahedra
//     around it is below 2 pi, and
//   - at every boundary vertex v, theta_v = the sum of the solid angles at v of the tetrahedra
//     around it is below 4 pi.
// The barriers are
//     E_e = 1 / (2 pi - theta_e),      E_v = 1 / (4 pi - theta_v),
// +inf from 2 pi (4 pi) on, and when an angle is undefined (a vanishing edge or face).
//
// Angles are signed against each rest tetrahedron's orientation, so that an inverted tetrahedron
// counts negatively: the caller lists each tetrahedron's vertices in the order whose rest
// determinant is positive (geometry/tet_angle_sums.h does). For edge vectors from the apex,
//     dihedral at edge e between the faces (e, u) and (e, w):
//         atan2(|e| det[e, u, w], (e x u) . (e x w))                  in (0, pi) when det > 0
//     solid angle of (a, b, c) (Van Oosterom and Strackee 1983):
//         2 atan2(det[a, b, c], |a||b||c| + (a.b)|c| + (a.c)|b| + (b.c)|a|)   in (0, 2 pi)
//
// Two variable layouts, as for the 2D barrier (energies/boundary_angle_energy.h):
//   DihedralSumEnergy<K>, SolidAngleSumEnergy<K>   A-form: vec(A_k) of the K tetrahedra around
//       the edge or vertex (9 K variables, column-major), each tetrahedron's rest edge vectors in
//       its rest frame: the assembly stage of Simplex Assembly. K <= kMaxAngleFan.
//   DihedralSumVertexEnergy<M>, SolidAngleSumVertexEnergy<M>   vertex form: the positions of the
//       edge's two vertices (or the vertex) and of its M ring vertices; each tetrahedron names
//       its other vertices by their place in the ring: the vertex stage.
// Derivatives: each angle by forward-mode autodiff over its own 9 (A-form) or 12 (vertex form)
// variables (optim/dual.h), then the chain rule: with E = f(theta), f' = E^2, f'' = 2 E^3,
//     grad E = f' sum_k grad phi_k,   Hess E = f' sum_k Hess phi_k + f'' grad theta grad theta^T.
// project_hessian() projects each angle's block (epsilon / f') and keeps the rank-one term: a
// positive semidefinite Hessian for 9 x 9 or 12 x 12 eigen-decompositions instead of one of the
// whole element. In A-form the rank-one term is the only coupling between the K tetrahedra, and
// a dense 9K x 9K element makes the Newton system's factorization several times denser (cup:
// BENCHMARKS.md, PolyCube); so the A-forms declare hessian_block = 9 (optim/element_energy.h)
// and their project_hessian() replaces the rank-one term by its block-diagonal majorizer
//     f'' grad theta grad theta^T  <=  K f'' sum_k grad phi_k grad phi_k^T
// (Cauchy-Schwarz: (sum_k g_k . z_k)^2 <= K sum_k (g_k . z_k)^2), which keeps the Newton step a
// descent direction. value_gradient_hessian() still returns the exact Hessian.
//
// Sizes: the element's Hessian is a fixed-size matrix, and Eigen refuses fixed-size objects over
// 128 KB, so an element has at most 126 variables: kMaxAngleFan = 14 tetrahedra in A-form and
// kMaxAngleRing = 40 ring vertices in vertex form. On ../shared/data/polycube (after the splits)
// boundary edges have at most 7 tetrahedra and 8 ring vertices, boundary vertices up to 31
// tetrahedra and 20 ring vertices: the vertex form covers every boundary vertex, the vertex
// barrier's A-form only those with at most 14 tetrahedra (85-95% of them; BENCHMARKS.md,
// PolyCube).

#include <array>
#include <cmath>
#include <type_traits>
#include <vector>

#include "optim/dual.h"
#include "optim/hessian_projection.h"
#include "optim/types.h"

namespace sa {

inline constexpr int kMaxAngleFan = 14;
inline constexpr int kMaxAngleRing = 40;

template <class T>
using Vec3T = Eigen::Matrix<T, 3, 1>;

namespace detail {

template <class T>
Vec3T<T> cross(const Vec3T<T>& a, const Vec3T<T>& b) {
    return Vec3T<T>(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                    a[0] * b[1] - a[1] * b[0]);
}
template <class T>
T dot(const Vec3T<T>& a, const Vec3T<T>& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

}  // namespace detail

/// The signed dihedral angle at edge `e` between the faces spanned with `u` and `w` (vectors from
/// the edge's first vertex). `defined` is set to false when a face or the edge vanishes.
template <class T>
T dihedral_angle(const Vec3T<T>& e, const Vec3T<T>& u, const Vec3T<T>& w, bool* defined) {
    using std::atan2;
    using std::sqrt;
    const Vec3T<T> n1 = detail::cross(e, u), n2 = detail::cross(e, w);
    const T y = sqrt(detail::dot(e, e)) * detail::dot(n1, w);  // |e| det[e, u, w]
    const T x = detail::dot(n1, n2);
    *defined = value_of(detail::dot(n1, n1)) > 0.0 && value_of(detail::dot(n2, n2)) > 0.0;
    if (!*defined) return T(0.0);
    return atan2(y, x);
}

/// The signed solid angle of the cone spanned by `a`, `b`, `c` at their common origin. `defined`
/// is set to false when an edge vanishes.
template <class T>
T solid_angle(const Vec3T<T>& a, const Vec3T<T>& b, const Vec3T<T>& c, bool* defined) {
    using std::atan2;
    using std::sqrt;
    const T la = sqrt(detail::dot(a, a)), lb = sqrt(detail::dot(b, b)),
            lc = sqrt(detail::dot(c, c));
    *defined = value_of(la) > 0.0 && value_of(lb) > 0.0 && value_of(lc) > 0.0;
    if (!*defined) return T(0.0);
    const T y = detail::dot(a, detail::cross(b, c));
    const T x =
        la * lb * lc + detail::dot(a, b) * lc + detail::dot(a, c) * lb + detail::dot(b, c) * la;
    if (value_of(x) == 0.0 && value_of(y) == 0.0) {
        *defined = false;
        return T(0.0);
    }
    return 2.0 * atan2(y, x);
}

/// 1 / (limit - theta), +inf from limit on (limit = 2 pi for edges, 4 pi for vertices).
inline double angle_sum_barrier(double theta, double limit) {
    return theta < limit ? 1.0 / (limit - theta) : kInfinity;
}

namespace detail {

/// theta = sum_k phi_k(x[index_k]) over `parts` angles of B variables each, and
/// E = 1 / (limit - theta). `angle(k, y, defined)` evaluates angle k on its variables y (double or
/// Dual<B>). With `dtheta`: the gradient of theta. With g and h: E's gradient and Hessian; with
/// `projection` set, the Hessian is projected block by block (see the header), `changed` telling
/// whether a block changed. Returns E, +inf when an angle is undefined or theta reaches the limit
/// (theta is still returned in `theta_out` then, +inf for an undefined angle).
template <int N, int B, class Index_, class Angle>
double angle_sum_energy(double limit, const Vec<N>& x, int parts, const Index_& index,
                        const Angle& angle, double* theta_out, Vec<N>* dtheta_out, Vec<N>* g,
                        Mat<N>* h, const ProjectionMode* projection = nullptr, double epsilon = 0.0,
                        bool* changed = nullptr, bool majorize_coupling = false) {
    double theta = 0.0;
    const bool derivatives = g != nullptr || dtheta_out != nullptr;
    std::vector<Dual<B>> phi(derivatives ? parts : 0);
    for (int k = 0; k < parts; ++k) {
        const std::array<int, B> at = index(k);
        Vec<B> y;
        for (int i = 0; i < B; ++i) y[i] = x[at[i]];
        bool defined = true;
        if (derivatives) {
            phi[k] = angle(k, Dual<B>::variables(y), &defined);
            theta += phi[k].value;
        } else {
            theta += angle(k, y, &defined);
        }
        if (!defined) {
            if (theta_out != nullptr) *theta_out = kInfinity;
            return kInfinity;
        }
    }
    if (theta_out != nullptr) *theta_out = theta;
    Vec<N> dtheta = Vec<N>::Zero();
    for (int k = 0; k < int(phi.size()); ++k) {
        const std::array<int, B> at = index(k);
        for (int i = 0; i < B; ++i) dtheta[at[i]] += phi[k].gradient[i];
    }
    if (dtheta_out != nullptr) *dtheta_out = dtheta;
    const double e = sa::angle_sum_barrier(theta, limit);  // detail:: has another
    if (!std::isfinite(e)) return kInfinity;
    if (g == nullptr) return e;
    // E' = E^2 and E'' = 2 E^3 with respect to theta.
    const double d1 = e * e, d2 = 2.0 * d1 * e;
    h->setZero();
    for (int k = 0; k < parts; ++k) {
        const std::array<int, B> at = index(k);
        Mat<B> block = phi[k].hessian;
        if (projection != nullptr) {
            const bool c = project_hessian_block<B>(block, *projection, epsilon / d1);
            if (changed != nullptr) *changed = *changed || c;
        }
        for (int i = 0; i < B; ++i) {
            for (int j = 0; j < B; ++j) (*h)(at[i], at[j]) += d1 * block(i, j);
        }
    }
    *g = d1 * dtheta;
    if (majorize_coupling) {  // the angles' blocks are disjoint (A-form)
        for (int k = 0; k < parts; ++k) {
            const std::array<int, B> at = index(k);
            for (int i = 0; i < B; ++i) {
                for (int j = 0; j < B; ++j) {
                    (*h)(at[i], at[j]) +=
                        double(parts) * d2 * phi[k].gradient[i] * phi[k].gradient[j];
                }
            }
        }
    } else {
        h->noalias() += d2 * dtheta * dtheta.transpose();
    }
    return e;
}

/// vec(A) (9 values, column-major) times a rest vector.
template <class T, class Y>
Vec3T<T> apply(const Y& a, const Eigen::Vector3d& r) {
    return Vec3T<T>(a[0] * r[0] + a[3] * r[1] + a[6] * r[2],
                    a[1] * r[0] + a[4] * r[1] + a[7] * r[2],
                    a[2] * r[0] + a[5] * r[1] + a[8] * r[2]);
}

/// Point i (3 values from 3 i) of y.
template <class T, class Y>
Vec3T<T> point(const Y& y, int i) {
    return Vec3T<T>(y[3 * i], y[3 * i + 1], y[3 * i + 2]);
}

/// The four barriers share this: Derived gives kLimit (2 pi or 4 pi), kBlock (the variables of
/// one angle, B), parts(e), index(e, k) (an angle's B variables within the element) and
/// angle(e, k, y, defined).
template <class Derived, int N, int B>
struct AngleSumEnergyBase {
    static constexpr int arity = N;

    double value(Index e, const Vec<N>& x) const {
        return evaluate(e, x, nullptr, nullptr, nullptr, nullptr);
    }
    double value_gradient_hessian(Index e, const Vec<N>& x, Vec<N>& g, Mat<N>& h) const {
        return evaluate(e, x, nullptr, nullptr, &g, &h);
    }
    bool project_hessian(Index e, const Vec<N>& x, Mat<N>& h, ProjectionMode mode,
                         double epsilon) const {
        if (mode == ProjectionMode::kNone) return false;
        // Derived declares hessian_block when its angles' blocks are disjoint (the A-forms).
        constexpr bool block_diagonal = requires {
            Derived::hessian_block;
        };
        // The projection is computed from x, block by block; `h` holds the term's weight times
        // the exact Hessian (its diagonal blocks when block_diagonal), so that weight is
        // measured against the exact Hessian and carried over to the result.
        Vec<N> g;
        Mat<N> exact;
        if (!std::isfinite(evaluate(e, x, nullptr, nullptr, &g, &exact))) return false;
        double along = 0.0, norm = 0.0;
        for (int j = 0; j < N; ++j) {
            for (int i = 0; i < N; ++i) {
                if (block_diagonal && i / B != j / B) continue;
                along += h(i, j) * exact(i, j);
                norm += exact(i, j) * exact(i, j);
            }
        }
        const double weight = norm > 0.0 ? along / norm : 1.0;
        if (!(weight > 0.0) || !std::isfinite(weight)) return false;
        bool changed = false;
        Mat<N> projected;
        const double energy = detail::angle_sum_energy<N, B>(
            Derived::kLimit, x, self().parts(e), [&](int k) { return self().index(e, k); },
            [&](int k, const auto& y, bool* defined) { return self().angle(e, k, y, defined); },
            nullptr, nullptr, &g, &projected, &mode, epsilon / weight, &changed, block_diagonal);
        // The majorizer changes the Hessian whether or not a block was projected.
        if (!std::isfinite(energy) || !(changed || block_diagonal)) return false;
        h = weight * projected;
        return true;
    }
    /// theta of element e at x (+inf when an angle is undefined), and its gradient when
    /// `gradient` is given: defined beyond the limit too, for a descent that brings theta below
    /// it.
    double angle_sum(Index e, const Vec<N>& x, Vec<N>* gradient = nullptr) const {
        double theta = 0.0;
        evaluate(e, x, &theta, gradient, nullptr, nullptr);
        return theta;
    }

  private:
    const Derived& self() const { return static_cast<const Derived&>(*this); }
    double evaluate(Index e, const Vec<N>& x, double* theta, Vec<N>* dtheta, Vec<N>* g,
                    Mat<N>* h) const {
        return detail::angle_sum_energy<N, B>(
            Derived::kLimit, x, self().parts(e), [&](int k) { return self().index(e, k); },
            [&](int k, const auto& y, bool* defined) { return self().angle(e, k, y, defined); },
            theta, dtheta, g, h);
    }
};

/// The index array of block k in the A-form: vec(A_k) at 9 k.
template <int B>
std::array<int, B> contiguous_block(int k) {
    std::array<int, B> at;
    for (int i = 0; i < B; ++i) at[i] = B * k + i;
    return at;
}

}  // namespace detail

/// E_e in A-form over the K tetrahedra around a boundary edge.
template <int K>
struct DihedralSumEnergy : detail::AngleSumEnergyBase<DihedralSumEnergy<K>, 9 * K, 9> {
    static constexpr int hessian_block = 9;
    static_assert(K >= 1 && K <= kMaxAngleFan);
    static constexpr double kLimit = 2.0 * M_PI;
    /// Rest vectors of one tetrahedron in its rest frame, from the edge's first vertex: the edge
    /// and the two other vertices, ordered so that det[edge, u, w] > 0.
    struct Tet {
        Eigen::Vector3d edge, u, w;
    };
    std::vector<std::array<Tet, K>> fans;  ///< one per element

    int parts(Index) const { return K; }
    std::array<int, 9> index(Index, int k) const { return detail::contiguous_block<9>(k); }
    template <class Y>
    auto angle(Index e, int k, const Y& y, bool* defined) const {
        using T = std::decay_t<decltype(y[0])>;
        const Tet& t = fans[e][k];
        return dihedral_angle<T>(detail::apply<T>(y, t.edge), detail::apply<T>(y, t.u),
                                 detail::apply<T>(y, t.w), defined);
    }
};

/// E_e in vertex form: variables p (0..2), q (3..5), then ring vertex m at 6 + 3 m (M of them).
template <int M>
struct DihedralSumVertexEnergy
    : detail::AngleSumEnergyBase<DihedralSumVertexEnergy<M>, 3 * M + 6, 12> {
    static_assert(M >= 2 && M <= kMaxAngleRing);
    static constexpr double kLimit = 2.0 * M_PI;
    /// Per element: per tetrahedron (p, q, ring[i], ring[j]) its (i, j), ordered so that the rest
    /// det[q - p, r_i - p, r_j - p] > 0.
    std::vector<std::vector<std::array<int, 2>>> tets;

    int parts(Index e) const { return static_cast<int>(tets[e].size()); }
    std::array<int, 12> index(Index e, int k) const {
        std::array<int, 12> at;
        for (int c = 0; c < 3; ++c) {
            at[c] = c;
            at[3 + c] = 3 + c;
            at[6 + c] = 6 + 3 * tets[e][k][0] + c;
            at[9 + c] = 6 + 3 * tets[e][k][1] + c;
        }
        return at;
    }
    template <class Y>
    auto angle(Index, int, const Y& y, bool* defined) const {
        using T = std::decay_t<decltype(y[0])>;
        const Vec3T<T> p = detail::point<T>(y, 0);
        return dihedral_angle<T>(detail::point<T>(y, 1) - p, detail::point<T>(y, 2) - p,
                                 detail::point<T>(y, 3) - p, defined);
    }
};

/// E_v in A-form over the K tetrahedra around a boundary vertex.
template <int K>
struct SolidAngleSumEnergy : detail::AngleSumEnergyBase<SolidAngleSumEnergy<K>, 9 * K, 9> {
    static constexpr int hessian_block = 9;
    static_assert(K >= 1 && K <= kMaxAngleFan);
    static constexpr double kLimit = 4.0 * M_PI;
    /// Rest vectors of one tetrahedron in its rest frame from the vertex to its three others,
    /// ordered so that det[a, b, c] > 0.
    struct Tet {
        Eigen::Vector3d a, b, c;
    };
    std::vector<std::array<Tet, K>> stars;  ///< one per element

    int parts(Index) const { return K; }
    std::array<int, 9> index(Index, int k) const { return detail::contiguous_block<9>(k); }
    template <class Y>
    auto angle(Index e, int k, const Y& y, bool* defined) const {
        using T = std::decay_t<decltype(y[0])>;
        const Tet& t = stars[e][k];
        return solid_angle<T>(detail::apply<T>(y, t.a), detail::apply<T>(y, t.b),
                              detail::apply<T>(y, t.c), defined);
    }
};

/// E_v in vertex form: variables v (0..2), then ring vertex m at 3 + 3 m (M of them).
template <int M>
struct SolidAngleSumVertexEnergy
    : detail::AngleSumEnergyBase<SolidAngleSumVertexEnergy<M>, 3 * M + 3, 12> {
    static_assert(M >= 3 && M <= kMaxAngleRing);
    static constexpr double kLimit = 4.0 * M_PI;
    /// Per element: per tetrahedron (v, ring[i], ring[j], ring[k]) its (i, j, k), ordered so that
    /// the rest det[r_i - v, r_j - v, r_k - v] > 0.
    std::vector<std::vector<std::array<int, 3>>> tets;

    int parts(Index e) const { return static_cast<int>(tets[e].size()); }
    std::array<int, 12> index(Index e, int k) const {
        std::array<int, 12> at;
        for (int c = 0; c < 3; ++c) {
            at[c] = c;
            for (int m = 0; m < 3; ++m) at[3 + 3 * m + c] = 3 + 3 * tets[e][k][m] + c;
        }
        return at;
    }
    template <class Y>
    auto angle(Index, int, const Y& y, bool* defined) const {
        using T = std::decay_t<decltype(y[0])>;
        const Vec3T<T> v = detail::point<T>(y, 0);
        return solid_angle<T>(detail::point<T>(y, 1) - v, detail::point<T>(y, 2) - v,
                              detail::point<T>(y, 3) - v, defined);
    }
};

}  // namespace sa
