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
// Two variable layouts, as for the 2D barrier (energies/boundary_angle_energy.h), each of
// run-time arity (optim/dynamic_element_energy.h: one term for fans and stars of any size):
//   DihedralSumEnergy, SolidAngleSumEnergy   A-form: vec(A_k) of the K tetrahedra around the edge
//       or vertex (9 K variables, column-major), each tetrahedron's rest edge vectors in its rest
//       frame: the assembly stage of Simplex Assembly.
//   DihedralSumVertexEnergy, SolidAngleSumVertexEnergy   vertex form: the positions of the edge's
//       two vertices (or the vertex) and of its M ring vertices; each tetrahedron names its other
//       vertices by their place in the ring: the vertex stage.
// Derivatives: each angle by forward-mode autodiff over its own 9 (A-form) or 12 (vertex form)
// variables (optim/dual.h), then the chain rule: with E = f(theta), f' = E^2, f'' = 2 E^3,
//     grad E = f' sum_k grad phi_k,   Hess E = f' sum_k Hess phi_k + f'' grad theta grad theta^T.
// project_hessian() projects each angle's block (epsilon / f') and keeps the rank-one term: a
// positive semidefinite Hessian for 9 x 9 or 12 x 12 eigen-decompositions instead of one of the
// whole element. In A-form the rank-one term is the only coupling between the K tetrahedra, and
// a dense 9K x 9K element makes the Newton system's factorization several times denser
// (docs/measurements.md, PolyCube); so the A-forms declare hessian_block = 9 (their Hessians are
// the diagonal 9 x 9 blocks, side by side) and their project_hessian() replaces the rank-one term's
// blocks by those of its block-diagonal majorizer
//     f'' grad theta grad theta^T  <=  K f'' sum_k grad phi_k grad phi_k^T
// (Cauchy-Schwarz: (sum_k g_k . z_k)^2 <= K sum_k (g_k . z_k)^2), which keeps the Newton step a
// descent direction. value_gradient_hessian() returns the exact Hessian's blocks.

#include <array>
#include <cmath>
#include <vector>

#include "optim/dual.h"
#include "optim/dynamic_element_energy.h"
#include "optim/types.h"

namespace sa {

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

/// The tetrahedra around boundary edges in A-form: per element, each tetrahedron's rest vectors
/// in its rest frame, from the edge's first vertex: the edge and the two other vertices, ordered
/// so that det[edge, u, w] > 0.
struct DihedralFans {
    static constexpr int hessian_block = 9;
    struct Tet {
        Eigen::Vector3d edge, u, w;
    };
    std::vector<std::vector<Tet>> fans;  ///< one per element

    Index num_elements() const { return static_cast<Index>(fans.size()); }
    int element_arity(Index e) const { return 9 * static_cast<int>(fans[e].size()); }
};

/// The tetrahedra around boundary edges in vertex form (variables p (0..2), q (3..5), then ring
/// vertex m at 6 + 3 m): per element, per tetrahedron (p, q, ring[i], ring[j]) its (i, j),
/// ordered so that the rest det[q - p, r_i - p, r_j - p] > 0.
struct DihedralRings {
    std::vector<std::vector<std::array<int, 2>>> tets;

    Index num_elements() const { return static_cast<Index>(tets.size()); }
};

/// The tetrahedra around boundary vertices in A-form: per element, each tetrahedron's rest
/// vectors in its rest frame from the vertex to its three others, ordered so that
/// det[a, b, c] > 0.
struct SolidAngleStars {
    static constexpr int hessian_block = 9;
    struct Tet {
        Eigen::Vector3d a, b, c;
    };
    std::vector<std::vector<Tet>> stars;  ///< one per element

    Index num_elements() const { return static_cast<Index>(stars.size()); }
    int element_arity(Index e) const { return 9 * static_cast<int>(stars[e].size()); }
};

/// The tetrahedra around boundary vertices in vertex form (variables v (0..2), then ring vertex
/// m at 3 + 3 m): per element, per tetrahedron (v, ring[i], ring[j], ring[k]) its (i, j, k),
/// ordered so that the rest det[r_i - v, r_j - v, r_k - v] > 0.
struct SolidAngleRings {
    std::vector<std::vector<std::array<int, 3>>> tets;

    Index num_elements() const { return static_cast<Index>(tets.size()); }
};

/// The barrier on the angle sums of the elements `Geometry` describes (one of the four above),
/// an energy of run-time arity. Compiled once for each, in tet_angle_barriers.cpp.
template <class Geometry>
struct AngleSumEnergy : Geometry {
    static constexpr int arity = kDynamicArity;

    double value(Index e, ConstVectorRef x) const;
    double value_gradient_hessian(Index e, ConstVectorRef x, VectorRef g, MatrixRef h) const;
    bool project_hessian(Index e, ConstVectorRef x, MatrixRef h, ProjectionMode mode,
                         double epsilon) const;
    /// theta of element e at x (+inf when an angle is undefined), and its gradient when
    /// `gradient` is given: defined beyond the limit too, for a descent that brings theta below
    /// it.
    double angle_sum(Index e, ConstVectorRef x, Eigen::VectorXd* gradient = nullptr) const;
};

// The members are compiled in tet_angle_barriers.cpp, for the four geometries below.

/// E_e in A-form over the tetrahedra around a boundary edge.
using DihedralSumEnergy = AngleSumEnergy<DihedralFans>;
/// E_e in vertex form.
using DihedralSumVertexEnergy = AngleSumEnergy<DihedralRings>;
/// E_v in A-form over the tetrahedra around a boundary vertex.
using SolidAngleSumEnergy = AngleSumEnergy<SolidAngleStars>;
/// E_v in vertex form.
using SolidAngleSumVertexEnergy = AngleSumEnergy<SolidAngleRings>;

}  // namespace sa
