#pragma once
// Mesh disassembly (section 4.2): each simplex's linear part A_i is replaced by a matrix inside
// the barrier's feasible set, so that E_C is finite at the start.
//
//   closest_rotation(A)    R = U V^T with det R = +1: for det A < 0 the smallest singular
//                          direction is flipped first (DESIGN.md)
//   closest_similarity(A)  s R with R as above and s the mean singular value
// project_linear_parts() applies one of them to every simplex, or sets the identity, or random
// matrices projected to rotations (Figure 6); a near-zero or non-finite scale (a degenerate
// initial simplex) is replaced by the median scale of the mesh.

#include <cstdint>
#include <string>
#include <vector>

#include "optim/types.h"

namespace sa {

enum class Initialization { kClosestSimilarity, kClosestRotation, kIdentity, kRandomRotation };

std::string to_string(Initialization init);
/// "similarity", "rotation", "identity", "random"; throws InvalidArgumentError otherwise.
Initialization parse_initialization(const std::string& name);

template <int D>
Mat<D> closest_rotation(const Mat<D>& A);

template <int D>
Mat<D> closest_similarity(const Mat<D>& A);

/// Replaces every A_i in place as `init` says; `seed` drives kRandomRotation.
template <int D>
void project_linear_parts(std::vector<Mat<D>>& A, Initialization init, std::uint64_t seed = 1);

}  // namespace sa
