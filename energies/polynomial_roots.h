#pragma once
// The smallest positive real root of a polynomial of degree <= 3, for largest-feasible-step
// computations: det(A + t dA) = 0 is quadratic in 2D and cubic in 3D.

namespace sa {

/// Smallest t > 0 with c0 + c1 t + c2 t^2 + c3 t^3 = 0, or +inf when there is none. Roots are
/// polished with Newton steps. Coefficients that are negligible relative to the others are
/// treated as zero (the degree drops).
double smallest_positive_root(double c0, double c1, double c2, double c3 = 0.0);

}  // namespace sa
