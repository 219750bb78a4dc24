#pragma once
// Mesh disassembly (section 4.2): each simplex's linear part A_i is replaced by a matrix inside
// the barrier's feasible set, so that E_C is finite at the start.
//
//   closest_rotation(A)    R = U V^T with det R = +1: for det A < 0 the smallest singular
//                          direction is flipped first (a rotation, never a reflection)
//   closest_similarity(A)  s R with R as above and s the mean singular value
//   bounded:K              the closest matrix with sigma_max / sigma_min <= K (Kovalsky et al.
//                          2015, Figure 6(c);
//                          frontends/simplex_assembly/bounded_distortion_projection.h)
// project_linear_parts() applies one of them to every simplex, or sets the identity, or random
// matrices projected to rotations (Figure 6); a near-zero or non-finite scale (a degenerate
// initial simplex) is replaced by the median scale of the mesh.

#include <cstdint>
#include <string>
#include <vector>

#include "optim/types.h"

namespace sa {

/// How the disassembly projects each A_i: a kind, and for the bounded-distortion projection its
/// bound. Initialization::kClosestSimilarity etc. name the kinds without a parameter;
/// Initialization::bounded_distortion(K) the projection onto sigma_max / sigma_min <= K.
struct Initialization {
    enum class Kind {
        kClosestSimilarity,
        kClosestRotation,
        kIdentity,
        kRandomRotation,
        kBoundedDistortion
    };
    Kind kind = Kind::kClosestSimilarity;
    double bound = kInfinity;  ///< kBoundedDistortion only: K >= 1 on sigma_max / sigma_min

    static const Initialization kClosestSimilarity, kClosestRotation, kIdentity, kRandomRotation;
    /// Throws InvalidArgumentError unless K >= 1 (kInfinity allowed).
    static Initialization bounded_distortion(double K);

    bool operator==(const Initialization& o) const {
        return kind == o.kind && (kind != Kind::kBoundedDistortion || bound == o.bound);
    }
    bool operator!=(const Initialization& o) const { return !(*this == o); }
};

inline const Initialization Initialization::kClosestSimilarity{Kind::kClosestSimilarity};
inline const Initialization Initialization::kClosestRotation{Kind::kClosestRotation};
inline const Initialization Initialization::kIdentity{Kind::kIdentity};
inline const Initialization Initialization::kRandomRotation{Kind::kRandomRotation};

/// "similarity", "rotation", "identity", "random", "bounded:K" (K as %g, or inf).
std::string to_string(Initialization init);
/// The names of to_string(); "bounded:K" takes a number K >= 1 or inf. Throws
/// InvalidArgumentError naming the text otherwise.
Initialization parse_initialization(const std::string& name);

template <int D>
Mat<D> closest_rotation(const Mat<D>& A);

template <int D>
Mat<D> closest_similarity(const Mat<D>& A);

/// Replaces every A_i in place as `init` says; `seed` drives kRandomRotation.
template <int D>
void project_linear_parts(std::vector<Mat<D>>& A, Initialization init, std::uint64_t seed = 1);

}  // namespace sa
