#pragma once
// Forward-mode automatic differentiation to second order: Dual<N> carries a value, its gradient
// (N) and its Hessian (N x N) with respect to N variables. Write an energy once as a template on
// its scalar type and evaluate it with double (value only) or Dual<N> (value, gradient, Hessian):
//
// clang-format off
//   template <class T> T energy(const Eigen::Matrix<T, 2, 1>& x) {
//       using std::exp;  // so that exp(...) finds sa::exp for Dual and std::exp for double
//       return exp(x[0]) * x[1];
//   }
//   auto xd = sa::Dual<2>::variables(Vec<2>(1.0, 2.0));
//   sa::Dual<2> e = energy(xd);  // e.value, e.gradient, e.hessian
// clang-format on
//
// Dual<N> works inside fixed-size Eigen matrices (determinant(), inverse(), squaredNorm(), ...).
// Each operation costs O(N^2): meant for elements of a few to a few dozen variables.

#include <Eigen/Core>
#include <cmath>
#include <ostream>

#include "optim/types.h"

namespace sa {

template <int N>
struct Dual {
    double value = 0.0;
    Vec<N> gradient = Vec<N>::Zero();
    Mat<N> hessian = Mat<N>::Zero();

    Dual() = default;
    Dual(double v) : value(v) {}  // NOLINT: constants mix freely with duals
    Dual(double v, const Vec<N>& g, const Mat<N>& h) : value(v), gradient(g), hessian(h) {}

    /// The i-th of N independent variables, with value v.
    static Dual variable(double v, int i) {
        Dual d(v);
        d.gradient[i] = 1.0;
        return d;
    }
    /// All N variables at once, valued x.
    static Eigen::Matrix<Dual, N, 1> variables(const Vec<N>& x) {
        Eigen::Matrix<Dual, N, 1> d;
        for (int i = 0; i < N; ++i) d[i] = variable(x[i], i);
        return d;
    }

    /// f(this) given f, f' and f'' at this->value (the chain rule to second order).
    Dual chain(double f, double df, double ddf) const {
        return Dual(f, df * gradient, df * hessian + ddf * gradient * gradient.transpose());
    }

    Dual& operator+=(const Dual& b) {
        value += b.value;
        gradient += b.gradient;
        hessian += b.hessian;
        return *this;
    }
    Dual& operator-=(const Dual& b) {
        value -= b.value;
        gradient -= b.gradient;
        hessian -= b.hessian;
        return *this;
    }
    Dual& operator*=(const Dual& b) { return *this = *this * b; }
    Dual& operator/=(const Dual& b) { return *this = *this / b; }
    Dual& operator+=(double b) {
        value += b;
        return *this;
    }
    Dual& operator-=(double b) {
        value -= b;
        return *this;
    }
    Dual& operator*=(double b) {
        value *= b;
        gradient *= b;
        hessian *= b;
        return *this;
    }
    Dual& operator/=(double b) { return *this *= 1.0 / b; }

    friend Dual operator-(const Dual& a) { return Dual(-a.value, -a.gradient, -a.hessian); }
    friend Dual operator+(Dual a, const Dual& b) { return a += b; }
    friend Dual operator-(Dual a, const Dual& b) { return a -= b; }
    friend Dual operator+(Dual a, double b) { return a += b; }
    friend Dual operator+(double a, Dual b) { return b += a; }
    friend Dual operator-(Dual a, double b) { return a -= b; }
    friend Dual operator-(double a, const Dual& b) { return -b + a; }
    friend Dual operator*(Dual a, double b) { return a *= b; }
    friend Dual operator*(double a, Dual b) { return b *= a; }
    friend Dual operator/(Dual a, double b) { return a /= b; }
    friend Dual operator*(const Dual& a, const Dual& b) {
        const Mat<N> cross = a.gradient * b.gradient.transpose();
        return Dual(a.value * b.value, b.value * a.gradient + a.value * b.gradient,
                    b.value * a.hessian + a.value * b.hessian + cross + cross.transpose());
    }
    friend Dual operator/(const Dual& a, const Dual& b) { return a * inverse(b); }
    friend Dual operator/(double a, const Dual& b) { return a * inverse(b); }

    friend Dual inverse(const Dual& a) {
        const double r = 1.0 / a.value;
        return a.chain(r, -r * r, 2.0 * r * r * r);
    }

    friend bool operator<(const Dual& a, const Dual& b) { return a.value < b.value; }
    friend bool operator<=(const Dual& a, const Dual& b) { return a.value <= b.value; }
    friend bool operator>(const Dual& a, const Dual& b) { return a.value > b.value; }
    friend bool operator>=(const Dual& a, const Dual& b) { return a.value >= b.value; }
    friend bool operator==(const Dual& a, const Dual& b) { return a.value == b.value; }
    friend bool operator!=(const Dual& a, const Dual& b) { return a.value != b.value; }

    friend std::ostream& operator<<(std::ostream& out, const Dual& a) { return out << a.value; }
};

template <int N>
Dual<N> sqrt(const Dual<N>& a) {
    const double s = std::sqrt(a.value);
    return a.chain(s, 0.5 / s, -0.25 / (s * a.value));
}
template <int N>
Dual<N> exp(const Dual<N>& a) {
    const double e = std::exp(a.value);
    return a.chain(e, e, e);
}
template <int N>
Dual<N> log(const Dual<N>& a) {
    return a.chain(std::log(a.value), 1.0 / a.value, -1.0 / (a.value * a.value));
}
template <int N>
Dual<N> pow(const Dual<N>& a, double p) {
    const double f = std::pow(a.value, p);
    const double df = p * std::pow(a.value, p - 1.0);
    const double ddf = p * (p - 1.0) * std::pow(a.value, p - 2.0);
    return a.chain(f, df, ddf);
}
template <int N>
Dual<N> sin(const Dual<N>& a) {
    const double s = std::sin(a.value), c = std::cos(a.value);
    return a.chain(s, c, -s);
}
template <int N>
Dual<N> cos(const Dual<N>& a) {
    const double s = std::sin(a.value), c = std::cos(a.value);
    return a.chain(c, -s, -c);
}
template <int N>
Dual<N> acos(const Dual<N>& a) {
    const double q = 1.0 - a.value * a.value;
    const double r = 1.0 / std::sqrt(q);
    return a.chain(std::acos(a.value), -r, -a.value * r / q);
}
template <int N>
Dual<N> abs(const Dual<N>& a) {
    return a.value < 0.0 ? -a : a;
}
/// atan2(y, x): the angle of the vector (x, y).
template <int N>
Dual<N> atan2(const Dual<N>& y, const Dual<N>& x) {
    const double r2 = x.value * x.value + y.value * y.value;
    const double tx = -y.value / r2, ty = x.value / r2;  // first derivatives
    const double txx = 2.0 * x.value * y.value / (r2 * r2);
    const double txy = (y.value * y.value - x.value * x.value) / (r2 * r2);
    const Mat<N> gxy = x.gradient * y.gradient.transpose();
    return Dual<N>(
        std::atan2(y.value, x.value), tx * x.gradient + ty * y.gradient,
        tx * x.hessian + ty * y.hessian +
            txx * (x.gradient * x.gradient.transpose() - y.gradient * y.gradient.transpose()) +
            txy * (gxy + gxy.transpose()));
}
template <int N>
bool isfinite(const Dual<N>& a) {
    return std::isfinite(a.value);
}

/// The value of a double or a Dual.
inline double value_of(double a) {
    return a;
}
template <int N>
double value_of(const Dual<N>& a) {
    return a.value;
}

}  // namespace sa

namespace Eigen {

template <int N>
struct NumTraits<sa::Dual<N>> : NumTraits<double> {
    using Real = sa::Dual<N>;
    using NonInteger = sa::Dual<N>;
    using Nested = sa::Dual<N>;
    using Literal = sa::Dual<N>;
    enum {
        IsComplex = 0,
        IsInteger = 0,
        IsSigned = 1,
        RequireInitialization = 1,
        ReadCost = 1,
        AddCost = 3,
        MulCost = 3,
    };
};

template <int N, typename BinaryOp>
struct ScalarBinaryOpTraits<sa::Dual<N>, double, BinaryOp> {
    using ReturnType = sa::Dual<N>;
};
template <int N, typename BinaryOp>
struct ScalarBinaryOpTraits<double, sa::Dual<N>, BinaryOp> {
    using ReturnType = sa::Dual<N>;
};

}  // namespace Eigen
