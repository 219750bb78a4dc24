#include "frontends/polycube/tet_angle_barriers.h"

#include <type_traits>

#include "optim/hessian_projection.h"

namespace sa {

namespace {

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

/// The index array of block k in the A-form: vec(A_k) at 9 k.
std::array<int, 9> contiguous_block(int k) {
    std::array<int, 9> at;
    for (int i = 0; i < 9; ++i) at[i] = 9 * k + i;
    return at;
}

/// What each geometry gives the evaluation below: the limit of its angle sums, B (the variables
/// of one angle), whether its Hessian is blocked (the angles' variables disjoint, hessian_block
/// = B: A-form), parts(g, e) (the angles of element e), index(g, e, k) (angle k's B variables
/// within the element) and angle(g, e, k, y, defined) on them (double or Dual<B>).
template <class Geometry>
struct Angles;

template <>
struct Angles<DihedralFans> {
    static constexpr double kLimit = 2.0 * M_PI;
    static constexpr int B = 9;
    static constexpr bool kBlocked = true;
    static int parts(const DihedralFans& g, Index e) { return static_cast<int>(g.fans[e].size()); }
    static std::array<int, B> index(const DihedralFans&, Index, int k) {
        return contiguous_block(k);
    }
    template <class Y>
    static auto angle(const DihedralFans& g, Index e, int k, const Y& y, bool* defined) {
        using T = std::decay_t<decltype(y[0])>;
        const DihedralFans::Tet& t = g.fans[e][k];
        return dihedral_angle<T>(apply<T>(y, t.edge), apply<T>(y, t.u), apply<T>(y, t.w), defined);
    }
};

template <>
struct Angles<DihedralRings> {
    static constexpr double kLimit = 2.0 * M_PI;
    static constexpr int B = 12;
    static constexpr bool kBlocked = false;
    static int parts(const DihedralRings& g, Index e) { return static_cast<int>(g.tets[e].size()); }
    static std::array<int, B> index(const DihedralRings& g, Index e, int k) {
        std::array<int, B> at;
        for (int c = 0; c < 3; ++c) {
            at[c] = c;
            at[3 + c] = 3 + c;
            at[6 + c] = 6 + 3 * g.tets[e][k][0] + c;
            at[9 + c] = 6 + 3 * g.tets[e][k][1] + c;
        }
        return at;
    }
    template <class Y>
    static auto angle(const DihedralRings&, Index, int, const Y& y, bool* defined) {
        using T = std::decay_t<decltype(y[0])>;
        const Vec3T<T> p = point<T>(y, 0);
        return dihedral_angle<T>(point<T>(y, 1) - p, point<T>(y, 2) - p, point<T>(y, 3) - p,
                                 defined);
    }
};

template <>
struct Angles<SolidAngleStars> {
    static constexpr double kLimit = 4.0 * M_PI;
    static constexpr int B = 9;
    static constexpr bool kBlocked = true;
    static int parts(const SolidAngleStars& g, Index e) {
        return static_cast<int>(g.stars[e].size());
    }
    static std::array<int, B> index(const SolidAngleStars&, Index, int k) {
        return contiguous_block(k);
    }
    template <class Y>
    static auto angle(const SolidAngleStars& g, Index e, int k, const Y& y, bool* defined) {
        using T = std::decay_t<decltype(y[0])>;
        const SolidAngleStars::Tet& t = g.stars[e][k];
        return solid_angle<T>(apply<T>(y, t.a), apply<T>(y, t.b), apply<T>(y, t.c), defined);
    }
};

template <>
struct Angles<SolidAngleRings> {
    static constexpr double kLimit = 4.0 * M_PI;
    static constexpr int B = 12;
    static constexpr bool kBlocked = false;
    static int parts(const SolidAngleRings& g, Index e) {
        return static_cast<int>(g.tets[e].size());
    }
    static std::array<int, B> index(const SolidAngleRings& g, Index e, int k) {
        std::array<int, B> at;
        for (int c = 0; c < 3; ++c) {
            at[c] = c;
            for (int m = 0; m < 3; ++m) at[3 + 3 * m + c] = 3 + 3 * g.tets[e][k][m] + c;
        }
        return at;
    }
    template <class Y>
    static auto angle(const SolidAngleRings&, Index, int, const Y& y, bool* defined) {
        using T = std::decay_t<decltype(y[0])>;
        const Vec3T<T> v = point<T>(y, 0);
        return solid_angle<T>(point<T>(y, 1) - v, point<T>(y, 2) - v, point<T>(y, 3) - v, defined);
    }
};

/// Entry (r, c) of an element Hessian in its stored form: the whole n x n matrix, or (blocked)
/// the diagonal B x B blocks side by side, where r and c are in the same block.
template <bool blocked, int B>
double& entry(MatrixRef& h, int r, int c) {
    if constexpr (blocked) {
        return h(r % B, c);
    } else {
        return h(r, c);
    }
}

/// theta = sum_k phi_k(x[index_k]) over element e's angles, and E = 1 / (limit - theta). With
/// `dtheta_out`: the gradient of theta. With g and h: E's gradient and Hessian (in the stored
/// form above; blocked: the exact Hessian's diagonal blocks); with `projection` set, the Hessian
/// is projected angle by angle (see the header), `changed` telling whether a block changed, and
/// with `majorize` (blocked) the rank-one term is replaced by its block-diagonal majorizer.
/// Returns E, +inf when an angle is undefined or theta reaches the limit (theta is still
/// returned in `theta_out` then, +inf for an undefined angle).
template <class Geometry>
double evaluate(const Geometry& geometry, Index e, const ConstVectorRef& x, double* theta_out,
                Eigen::VectorXd* dtheta_out, VectorRef* g, MatrixRef* h,
                const ProjectionMode* projection = nullptr, double epsilon = 0.0,
                bool* changed = nullptr, bool majorize = false) {
    using A = Angles<Geometry>;
    constexpr int B = A::B;
    const int parts = A::parts(geometry, e);
    double theta = 0.0;
    const bool derivatives = g != nullptr || dtheta_out != nullptr;
    std::vector<Dual<B>> phi(derivatives ? parts : 0);
    for (int k = 0; k < parts; ++k) {
        const std::array<int, B> at = A::index(geometry, e, k);
        Vec<B> y;
        for (int i = 0; i < B; ++i) y[i] = x[at[i]];
        bool defined = true;
        if (derivatives) {
            phi[k] = A::angle(geometry, e, k, Dual<B>::variables(y), &defined);
            theta += phi[k].value;
        } else {
            theta += A::angle(geometry, e, k, y, &defined);
        }
        if (!defined) {
            if (theta_out != nullptr) *theta_out = kInfinity;
            return kInfinity;
        }
    }
    if (theta_out != nullptr) *theta_out = theta;
    Eigen::VectorXd dtheta;
    if (derivatives) {
        dtheta.setZero(x.size());
        for (int k = 0; k < parts; ++k) {
            const std::array<int, B> at = A::index(geometry, e, k);
            for (int i = 0; i < B; ++i) dtheta[at[i]] += phi[k].gradient[i];
        }
    }
    if (dtheta_out != nullptr) *dtheta_out = dtheta;
    const double energy = angle_sum_barrier(theta, A::kLimit);
    if (!std::isfinite(energy)) return kInfinity;
    if (g == nullptr) return energy;
    // E' = E^2 and E'' = 2 E^3 with respect to theta.
    const double d1 = energy * energy, d2 = 2.0 * d1 * energy;
    MatrixRef& H = *h;
    H.setZero();
    for (int k = 0; k < parts; ++k) {
        const std::array<int, B> at = A::index(geometry, e, k);
        Mat<B> block = phi[k].hessian;
        if (projection != nullptr) {
            const bool c = project_hessian_block<B>(block, *projection, epsilon / d1);
            if (changed != nullptr) *changed = *changed || c;
        }
        for (int i = 0; i < B; ++i) {
            for (int j = 0; j < B; ++j) entry<A::kBlocked, B>(H, at[i], at[j]) += d1 * block(i, j);
        }
    }
    *g = d1 * dtheta;
    if constexpr (A::kBlocked) {
        for (int k = 0; k < parts; ++k) {
            const std::array<int, B> at = A::index(geometry, e, k);
            for (int i = 0; i < B; ++i) {
                for (int j = 0; j < B; ++j) {
                    entry<true, B>(H, at[i], at[j]) +=
                        majorize ? double(parts) * d2 * phi[k].gradient[i] * phi[k].gradient[j]
                                 : d2 * dtheta[at[i]] * dtheta[at[j]];
                }
            }
        }
    } else {
        H.noalias() += d2 * dtheta * dtheta.transpose();
    }
    return energy;
}

}  // namespace

template <class Geometry>
double AngleSumEnergy<Geometry>::value(Index e, ConstVectorRef x) const {
    return evaluate<Geometry>(*this, e, x, nullptr, nullptr, nullptr, nullptr);
}

template <class Geometry>
double AngleSumEnergy<Geometry>::value_gradient_hessian(Index e, ConstVectorRef x, VectorRef g,
                                                        MatrixRef h) const {
    return evaluate<Geometry>(*this, e, x, nullptr, nullptr, &g, &h);
}

template <class Geometry>
double AngleSumEnergy<Geometry>::angle_sum(Index e, ConstVectorRef x,
                                           Eigen::VectorXd* gradient) const {
    double theta = 0.0;
    evaluate<Geometry>(*this, e, x, &theta, gradient, nullptr, nullptr);
    return theta;
}

template <class Geometry>
bool AngleSumEnergy<Geometry>::project_hessian(Index e, ConstVectorRef x, MatrixRef h,
                                               ProjectionMode mode, double epsilon) const {
    if (mode == ProjectionMode::kNone) return false;
    constexpr bool blocked = Angles<Geometry>::kBlocked;
    // The projection is computed from x, block by block; `h` holds the term's weight times the
    // exact Hessian (its diagonal blocks when blocked), so that weight is measured against the
    // exact Hessian and carried over to the result.
    Eigen::VectorXd g(x.size());
    Eigen::MatrixXd exact(h.rows(), h.cols());
    VectorRef g_view(g);
    MatrixRef exact_view(exact);
    if (!std::isfinite(evaluate<Geometry>(*this, e, x, nullptr, nullptr, &g_view, &exact_view)))
        return false;
    double along = 0.0, norm = 0.0;
    for (Eigen::Index j = 0; j < h.cols(); ++j) {
        for (Eigen::Index i = 0; i < h.rows(); ++i) {
            along += h(i, j) * exact(i, j);
            norm += exact(i, j) * exact(i, j);
        }
    }
    const double weight = norm > 0.0 ? along / norm : 1.0;
    if (!(weight > 0.0) || !std::isfinite(weight)) return false;
    bool changed = false;
    Eigen::MatrixXd projected(h.rows(), h.cols());
    MatrixRef projected_view(projected);
    const double energy =
        evaluate<Geometry>(*this, e, x, nullptr, nullptr, &g_view, &projected_view, &mode,
                           epsilon / weight, &changed, blocked);
    // The majorizer changes the Hessian whether or not a block was projected.
    if (!std::isfinite(energy) || !(changed || blocked)) return false;
    h = weight * projected;
    return true;
}

template struct AngleSumEnergy<DihedralFans>;
template struct AngleSumEnergy<DihedralRings>;
template struct AngleSumEnergy<SolidAngleStars>;
template struct AngleSumEnergy<SolidAngleRings>;

}  // namespace sa
