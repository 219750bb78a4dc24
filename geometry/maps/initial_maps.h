#pragma once
// Initial maps of a disk-topology triangle mesh to the plane: the usual starts of a
// parameterization (section 5.2). Each returns #V x 2 positions.
//
//   tutte_embedding   the boundary loop on the unit circle by arc length, each interior vertex at
//                     a weighted average of its neighbours: uniform weights (Tutte 1963) or
//                     mean-value weights (Floater 2003). The boundary is convex: no foldovers.
//   harmonic_circle   the same boundary, cotangent weights (the discrete harmonic map); may fold
//                     where cotangent weights are negative (they are clamped at a tiny positive
//                     value, see harmonic_map.h).
//   lscm              least-squares conformal map (Lévy et al. 2002): minimizes
//                     sum_t area_t |A_t|^2 - 2 det A_t (the LSCM distortion of energies/) with
//                     two boundary vertices far apart pinned at (0, 0) and (their rest distance,
//                     0); the boundary is free. It may fold.
// The mesh must be a disk (require_disk in boundary_loops.h).

#include <Eigen/Core>

#include "geometry/mesh/mesh_topology.h"

namespace sa {

enum class TutteWeights { kUniform, kMeanValue };

Eigen::MatrixXd tutte_embedding(const SimplicialMesh& mesh, const MeshTopology& topology,
                                TutteWeights weights = TutteWeights::kMeanValue);

Eigen::MatrixXd harmonic_circle(const SimplicialMesh& mesh, const MeshTopology& topology);

Eigen::MatrixXd lscm(const SimplicialMesh& mesh, const MeshTopology& topology);

/// The boundary loop's vertices on the unit circle, spaced by arc length (#loop x 2).
Eigen::MatrixXd circle_boundary(const SimplicialMesh& mesh, const std::vector<Index>& loop);

}  // namespace sa
