#pragma once
// Cone configurations that no seamless parameterization can have, named before anything is
// optimized.
//
// A seamless parameterization (quarter-turn rotations plus translations across its seams) makes
// the surface a euclidean cone metric whose holonomy lies in the quarter turns, with cone angle
// 2 pi (1 - index) at each singularity of its field. On a torus with exactly two cone points of
// angles 3 pi / 2 and 5 pi / 2 (indices +1/4 and -1/4), no such metric exists: Izmestiev, Kusner,
// Rote, Springborn and Sullivan (Geometriae Dedicata 166, 2013) prove that the holonomy group of a
// euclidean cone metric on the torus with two cone points of curvature +theta and -theta is not
// contained in the rotations by multiples of theta (the reason why no quad mesh of the torus has
// exactly one vertex of valence 3 and one of valence 5); Campen et al. (2019) name it as the one
// exception to the existence of seamless parameterizations with prescribed cones. Simplex
// Assembly then cannot assemble the field (its edge curl stalls near 1e-11 while the frames next
// to the singularities shrink toward zero) and the Poisson map folds.

#include <string>
#include <vector>

#include "frontends/seamless/cross_field.h"
#include "geometry/mesh/mesh_topology.h"

namespace sa {

/// Empty when the singularities of a field on `mesh` (a closed or bounded triangle surface) can
/// be the cones of a seamless parameterization as far as this check knows; otherwise one
/// sentence saying why not.
std::string seamless_cone_obstruction(const SimplicialMesh& mesh, const MeshTopology& topology,
                                      const std::vector<Singularity>& singularities);

}  // namespace sa
