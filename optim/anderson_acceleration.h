#pragma once
// Anderson acceleration of a fixed-point iteration x <- G(x) (type II, Walker & Ni 2011), as
// Peng et al. ("Anderson Acceleration for Geometry Optimization and Physics Simulation", 2018)
// use it for local/global solvers such as ARAP. With f = G(x) - x and the differences of the last
// m pairs (g_j, f_j),
//     theta = argmin |f_k - dF theta|,    x_{k+1} = g_k - dG theta,
// which extrapolates where plain iteration creeps. Nothing guarantees a decrease: callers keep
// an energy and, when the accelerated point raises it, take the plain g_k instead (reset()).

#include <Eigen/Core>
#include <deque>

namespace sa {

class AndersonAcceleration {
  public:
    /// `history` (m >= 1) pairs of differences kept.
    explicit AndersonAcceleration(int history);

    /// x_k and g = G(x_k) (same size every call) -> x_{k+1}. The first call after construction
    /// or reset() returns g.
    Eigen::VectorXd next(const Eigen::VectorXd& x, const Eigen::VectorXd& g);

    /// Forgets the history (after a rejected step).
    void reset();

  private:
    int history_;
    Eigen::VectorXd last_g_, last_f_;
    std::deque<Eigen::VectorXd> dG_, dF_;
};

}  // namespace sa
