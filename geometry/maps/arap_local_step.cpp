#include "geometry/maps/arap_local_step.h"

#include <tbb/parallel_for.h>

#include "geometry/maps/rotation_fit.h"

namespace sa {

template <int D>
double fit_rigid_parts(const RestFrames<D>& frames, const std::vector<Mat<D>>& A, bool similarity,
                       std::vector<Mat<D>>& M) {
    const bool warm = M.size() == A.size();  // the last fit's M_i (s R_i) start the new one
    M.resize(A.size());
    std::vector<double> terms(A.size(), 0.0);
    tbb::parallel_for(std::size_t(0), A.size(), [&](std::size_t i) {
        if (!A[i].allFinite()) {
            M[i].setIdentity();
            return;
        }
        const Mat<D> C = double(D + 1) * frames.corners[i] * frames.corners[i].transpose();
        const Mat<D> AC = A[i] * C;
        M[i] = warm ? fit_rotation<D>(AC, M[i]) : fit_rotation<D>(AC);
        if (similarity) M[i] *= std::max((M[i].transpose() * AC).trace() / C.trace(), 0.0);
        const Mat<D> difference = M[i] - A[i];
        terms[i] = (difference * C * difference.transpose()).trace();
    });
    double energy = 0.0;
    for (double t : terms) energy += t;  // in a fixed order
    return energy;
}

template double fit_rigid_parts<2>(const RestFrames<2>&, const std::vector<Mat<2>>&, bool,
                                   std::vector<Mat<2>>&);
template double fit_rigid_parts<3>(const RestFrames<3>&, const std::vector<Mat<3>>&, bool,
                                   std::vector<Mat<3>>&);

}  // namespace sa
