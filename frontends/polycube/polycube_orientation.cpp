#include "frontends/polycube/polycube_orientation.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "optim/errors.h"

namespace sa {

namespace {

constexpr double kDegree = M_PI / 180.0;

/// Grid steps per 90 degrees of each Euler angle (z and x over [0, 90), y over [-90, 90): up to
/// the cube's rotations this covers every rotation; with y over [0, 90) only, an eighth of
/// random rotations had no grid point within half a step).
constexpr int kGridSteps = 9;
/// Pattern searches from this many of the best grid rotations (and from the identity).
constexpr int kRefinedStarts = 4;
/// The pattern search's first and last step.
constexpr double kFirstStep = 90.0 / kGridSteps / 2.0 * kDegree;
constexpr double kLastStep = 1e-6 * kDegree;
/// A candidate must lower E by more than this share of it (rounding, not a preference).
constexpr double kRelativeImprovement = 1e-9;

Eigen::Matrix3d about(int axis, double angle) {
    return Eigen::AngleAxisd(angle, Eigen::Vector3d::Unit(axis)).toRotationMatrix();
}

}  // namespace

double l1_alignment(const Eigen::MatrixXd& area_vectors, const Eigen::Matrix3d& rotation) {
    const Eigen::MatrixXd turned = area_vectors * rotation.transpose();
    const double total = area_vectors.rowwise().norm().sum();
    return turned.cwiseAbs().sum() / total;
}

PolycubeOrientation polycube_orientation(const TetBoundary& boundary,
                                         const Eigen::MatrixXd& positions) {
    const Eigen::MatrixXd area_vectors = boundary_area_vectors(boundary, positions);
    const double total = area_vectors.rowwise().norm().sum();
    if (!(total > 0.0))
        throw InvalidArgumentError("polycube orientation: the boundary has no area");
    PolycubeOrientation out;
    auto energy = [&](const Eigen::Matrix3d& r) {  // l1_alignment() with `total` computed once
        ++out.evaluations;
        return (area_vectors * r.transpose()).cwiseAbs().sum() / total;
    };
    auto better = [](double candidate, double best) {
        return candidate < best - kRelativeImprovement * best;
    };

    struct Candidate {
        Eigen::Matrix3d rotation;
        double energy;
    };
    std::vector<Candidate> grid;
    for (int i = 0; i < kGridSteps; ++i) {
        for (int j = -kGridSteps; j < kGridSteps; ++j) {
            for (int k = 0; k < kGridSteps; ++k) {
                const double step = 90.0 / kGridSteps * kDegree;
                const Eigen::Matrix3d r =
                    about(2, i * step) * about(1, j * step) * about(0, k * step);
                grid.push_back({r, energy(r)});
            }
        }
    }
    std::stable_sort(grid.begin(), grid.end(),
                     [](const Candidate& a, const Candidate& b) { return a.energy < b.energy; });

    out.energy_identity = energy(Eigen::Matrix3d::Identity());
    std::vector<Candidate> starts{{Eigen::Matrix3d::Identity(), out.energy_identity}};
    for (int s = 0; s < kRefinedStarts && s < int(grid.size()); ++s) starts.push_back(grid[s]);

    Candidate best = starts.front();
    for (Candidate c : starts) {
        for (double step = kFirstStep; step >= kLastStep; step /= 2.0) {
            bool moved = true;
            while (moved) {
                moved = false;
                for (int axis = 0; axis < 3; ++axis) {
                    for (const double sign : {1.0, -1.0}) {
                        const Eigen::Matrix3d r = about(axis, sign * step) * c.rotation;
                        const double e = energy(r);
                        if (better(e, c.energy)) {
                            c = {r, e};
                            moved = true;
                        }
                    }
                }
            }
        }
        if (better(c.energy, best.energy)) best = c;
    }
    // Re-orthonormalize the product of many small rotations, then take, of the 24 rotations
    // that E cannot tell apart (C R for the cube's rotations C: signed permutations, which keep
    // every l1 norm), the one of smallest angle: the labels keep the input's axis names.
    const Eigen::Matrix3d r = Eigen::Quaterniond(best.rotation).normalized().toRotationMatrix();
    out.rotation = r;
    double smallest = Eigen::AngleAxisd(r).angle();
    const int permutations[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                    {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (const auto& perm : permutations) {
        for (int signs = 0; signs < 8; ++signs) {
            Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
            for (int row = 0; row < 3; ++row) c(row, perm[row]) = (signs >> row) & 1 ? -1.0 : 1.0;
            if (c.determinant() < 0.0) continue;
            const double angle = Eigen::AngleAxisd(Eigen::Matrix3d(c * r)).angle();
            if (angle < smallest - 1e-12) {
                smallest = angle;
                out.rotation = c * r;
            }
        }
    }
    out.energy = energy(out.rotation);
    out.angle_degrees = Eigen::AngleAxisd(out.rotation).angle() / kDegree;
    return out;
}

}  // namespace sa
