#include "optim/anderson_acceleration.h"

#include <Eigen/QR>

#include "optim/errors.h"

namespace sa {

AndersonAcceleration::AndersonAcceleration(int history) : history_(history) {
    if (history < 1) {
        throw InvalidArgumentError("Anderson acceleration: history = " + std::to_string(history) +
                                   ": must be >= 1");
    }
}

Eigen::VectorXd AndersonAcceleration::next(const Eigen::VectorXd& x, const Eigen::VectorXd& g) {
    Eigen::VectorXd f = g - x;
    if (last_g_.size() == g.size()) {
        dG_.push_back(g - last_g_);
        dF_.push_back(f - last_f_);
        if (int(dG_.size()) > history_) {
            dG_.pop_front();
            dF_.pop_front();
        }
    } else {
        reset();
    }
    last_g_ = g;
    last_f_ = f;
    if (dF_.empty()) return g;
    const Eigen::Index m = static_cast<Eigen::Index>(dF_.size());
    Eigen::MatrixXd dF(f.size(), m);
    for (Eigen::Index j = 0; j < m; ++j) dF.col(j) = dF_[j];
    // Rank-revealing: repeated or vanishing differences get theta_j = 0.
    const Eigen::VectorXd theta = dF.colPivHouseholderQr().solve(f);
    if (!theta.allFinite()) return g;
    Eigen::VectorXd result = g;
    for (Eigen::Index j = 0; j < m; ++j) result -= theta[j] * dG_[j];
    return result;
}

void AndersonAcceleration::reset() {
    dG_.clear();
    dF_.clear();
    last_g_.resize(0);
    last_f_.resize(0);
}

}  // namespace sa
