#pragma once
// A harmonic map of a triangle mesh with prescribed positions on some vertices (usually the
// boundary): each free vertex is the weighted average of its neighbours,
//     sum_j w_ij (x_i - x_j) = 0,
// with cotangent weights (the discrete harmonic map) or uniform weights (Tutte's embedding when
// the boundary is convex). On a non-convex boundary both may fold: the usual folded start that
// Simplex Assembly repairs (the paper's Figure 1).

#include <Eigen/Core>
#include <vector>

#include "geometry/mesh/simplicial_mesh.h"

namespace sa {

enum class LaplacianWeights { kCotangent, kUniform };

/// `fixed_vertices` with their positions (rows of `fixed_positions`, #fixed x c); returns #V x c
/// positions. Throws InvalidArgumentError when a connected part has no fixed vertex.
Eigen::MatrixXd harmonic_map(const SimplicialMesh& mesh, const std::vector<Index>& fixed_vertices,
                             const Eigen::MatrixXd& fixed_positions,
                             LaplacianWeights weights = LaplacianWeights::kCotangent);

}  // namespace sa
