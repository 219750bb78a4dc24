#include "frontends/simplex_assembly/detail/forced_distortion.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <cmath>
#include <functional>

#include "energies/barrier.h"
#include "geometry/quality/map_quality.h"

namespace sa {

template <int D>
std::vector<Index> barrier_forced_simplices(const PreparedProblem<D>& p,
                                            const SimplexAssemblyOptions& options,
                                            double exponent) {
    if (!p.energy) return {};  // only the problem's own energies: no built-in barrier to measure
    std::vector<Index> handle_row(p.mesh.num_vertices(), -1);
    for (std::size_t k = 0; k < p.input->handles.size(); ++k)
        handle_row[p.input->handles[k]] = static_cast<Index>(k);
    const double limit = exponent >= 0.0 ? exponent : std::log(options.lambda_max);
    std::vector<Index> forced;
    for (Index s = 0; s < p.mesh.num_simplices(); ++s) {
        Eigen::Matrix<double, D, D + 1> image;
        bool all = true;
        for (int k = 0; k <= D && all; ++k) {
            const Index row = handle_row[p.mesh.simplices(s, k)];
            all = row >= 0;
            if (all) image.col(k) = p.assembly.targets[row];
        }
        if (!all) continue;
        const double d = p.energy->barrier_distortion(linear_part<D>(p.frames, s, image));
        // d is +inf for an inverted simplex: infeasible data, diagnosed elsewhere.
        if (std::isfinite(d) && options.s * d >= limit) forced.push_back(s);
    }
    return forced;
}

template <int D>
Index simplices_beyond_barrier_cap(const PreparedProblem<D>& p, const Eigen::MatrixXd& positions) {
    std::vector<unsigned char> is_handle(p.mesh.num_vertices(), 0);
    for (Index h : p.input->handles) is_handle[h] = 1;
    const std::vector<Mat<D>> A = linear_parts<D>(p.mesh, p.frames, positions);
    return tbb::parallel_reduce(
        tbb::blocked_range<Index>(0, p.mesh.num_simplices(), 4096), Index(0),
        [&](const tbb::blocked_range<Index>& r, Index count) {
            for (Index s = r.begin(); s != r.end(); ++s) {
                bool free = false;
                for (int k = 0; k <= D; ++k) free |= !is_handle[p.mesh.simplices(s, k)];
                if (!free) continue;
                for (const auto& energy : p.assembly.energies) {
                    if (energy->beyond_exponent_cap(A[s])) {
                        ++count;
                        break;
                    }
                }
            }
            return count;
        },
        std::plus<Index>());
}

template std::vector<Index> barrier_forced_simplices<2>(const PreparedProblem<2>&,
                                                        const SimplexAssemblyOptions&, double);
template Index simplices_beyond_barrier_cap<2>(const PreparedProblem<2>&, const Eigen::MatrixXd&);
template Index simplices_beyond_barrier_cap<3>(const PreparedProblem<3>&, const Eigen::MatrixXd&);
template std::vector<Index> barrier_forced_simplices<3>(const PreparedProblem<3>&,
                                                        const SimplexAssemblyOptions&, double);

}  // namespace sa
