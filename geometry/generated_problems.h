#pragma once
// Mapping problems generated from a tetrahedral (or planar triangle) mesh, feasible by
// construction, for tests and benchmarks of two hard classes:
//
//   fixed_boundary_problem   the Locally Injective Mappings benchmark's hard class: every
//                            boundary vertex is a handle
//                            at its image under a smooth deformation; the interior is placed by
//                            a Tutte solve (uniform weights, boundary fixed) and moved by seeded
//                            noise, which tangles it. The deformed mesh itself solves it.
//   handle_slab_problem      a large deformation with handles moved: the
//                            vertices of two end slabs are handles at their deformed positions,
//                            every other vertex stays at rest, so the simplices next to the
//                            slabs fold.
//
// Deformations (rest coordinates; the axis runs along the mesh's longest bounding-box side):
//   twist  rotation about the axis through the box's centre by `amount` radians times the
//          position along the axis, from 0 at one end to 1 at the other;
//   bend   the axis bent into a circular arc of `amount` radians (lengths along the axis kept);
// then, when `flatten` < 1, the coordinate along the box's shortest side scaled by `flatten`:
// every simplex gets conformal distortion about 1 / flatten, so that the handles alone force the
// barrier e^{s d} far beyond lambda_max (as that benchmark's hard class does).

#include <cstdint>
#include <vector>

#include "geometry/simplicial_mesh.h"

namespace sa {

enum class GeneratedDeformation { kTwist, kBend };

struct GeneratedProblem {
    SimplicialMesh rest;
    Eigen::MatrixXd solution;  ///< #V x d: a valid map with the handles at their targets
    Eigen::MatrixXd initial;   ///< #V x d: the initial map (handles at their targets)
    std::vector<Index> handles;
};

/// The deformed positions of `rest` (#V x 3, or #V x 2 for a planar mesh: bend only, no twist).
Eigen::MatrixXd deform(const Eigen::MatrixXd& rest, GeneratedDeformation deformation, double amount,
                       double flatten = 1.0);

/// Noise: each interior vertex moves by a vector uniform in the ball of radius `noise` times the
/// mean edge length (seeded). Throws InvalidArgumentError when the deformation inverts a simplex
/// of `rest` (the problem would not be feasible by construction) or the mesh has no interior
/// vertex.
GeneratedProblem fixed_boundary_problem(const SimplicialMesh& rest,
                                        GeneratedDeformation deformation, double amount,
                                        double noise, std::uint64_t seed, double flatten = 1.0);

/// Handles: the vertices within `slab` (a fraction of the axis length) of either end of the axis.
/// Throws InvalidArgumentError when the deformation inverts a simplex of `rest`.
GeneratedProblem handle_slab_problem(const SimplicialMesh& rest, GeneratedDeformation deformation,
                                     double amount, double slab);

}  // namespace sa
