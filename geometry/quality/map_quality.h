#pragma once
// Quality of a piecewise affine map, measured from its linear parts A_i (section 5, "Quality
// metrics"), with sigma the singular values of A_i:
//   conformal   delta_con = sigma_max / sigma_min
//   isometric   delta_iso = max(sigma_max, 1 / sigma_min)
//   volumetric  delta_vol = max(det A, 1 / det A)
// A simplex is inverted when det A_i < 0 (its orientation differs from its rest one) and
// degenerate when |det A_i| vol_i <= 1e-14 max_j |det A_j| vol_j (the rule of
// ../shared/tools/check_map.py). Maxima and area-weighted means run over the simplices that are
// neither inverted nor degenerate.

#include <Eigen/Core>
#include <vector>

#include "geometry/mesh/rest_frames.h"

namespace sa {

struct SimplexQuality {
    double det = 0.0;  ///< det A_i
    double conformal = kInfinity;
    double isometric = kInfinity;
    double volumetric = kInfinity;
    bool inverted = false;
    bool degenerate = false;
};

struct QualityStat {
    double max = 0.0;
    double mean = 0.0;  ///< weighted by rest volume
};

/// The degenerate simplices of map_quality() (its rule above, non-finite det A_i included),
/// counted from the determinants alone.
template <int D>
Index count_degenerate(const std::vector<Mat<D>>& A, const std::vector<double>& rest_volume);

struct MapQuality {
    Index simplices = 0;
    Index inverted = 0;
    Index degenerate = 0;
    QualityStat conformal, isometric, volumetric;
    std::vector<SimplexQuality> per_simplex;
};

template <int D>
MapQuality map_quality(const std::vector<Mat<D>>& A, const std::vector<double>& rest_volume);

/// Linear parts A_i of the map that sends each vertex to its row of `positions` (#V x D).
template <int D>
std::vector<Mat<D>> linear_parts(const SimplicialMesh& mesh, const RestFrames<D>& frames,
                                 const Eigen::MatrixXd& positions);

}  // namespace sa
