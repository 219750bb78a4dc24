#pragma once
// What the handles alone decide about a mapping problem, checked before any optimization: a
// problem whose handles already force an inverted or flat simplex has no inversion-free solution,
// and no solver should spend minutes finding that out.
//
// Three checks, each on the handles and their targets only:
//   fixed simplices    every vertex a handle: the map of the simplex is fixed. It is inverted
//                      when its orientation differs from its rest one (triangles of a surface
//                      mapped to the plane are positively oriented at rest), and flat when its
//                      volume is at most 1e-14 of the largest fixed simplex's volume: the rule by
//                      which the verification of a result calls a simplex degenerate (every fixed
//                      simplex is in the result as it is, so the result's largest volume is at
//                      least theirs). Both tests are invariant to scaling the rest shape or the
//                      targets.
//   conflicting handle a vertex listed twice with targets farther apart than `tolerance`.
//   collapsed edge     a rest edge whose two vertices are handles with the same target (within
//                      1e-14 of the targets' bounding-box diagonal): every simplex around it is
//                      flat.
//   fixed boundary     (given the mesh's topology) a connected part whose boundary vertices are
//                      all handles. Whatever its interior vertices do, the signed volumes (areas)
//                      of its simplices' images sum to the volume its boundary's image encloses
//                      (each simplex is the sum of the cones from one point to its facets; the
//                      cones on interior facets cancel), so that volume must be positive. For
//                      triangles mapped to the plane, the boundary loops' total turning number
//                      must also be at least the part's Euler characteristic (Gauss-Bonnet: a
//                      disk's boundary turns once, plus once for every time the map wraps around
//                      a boundary vertex or an interior one): a mirrored boundary turns -1, a
//                      figure eight 0. Both are necessary conditions; neither is sufficient.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "geometry/mesh/mesh_topology.h"
#include "geometry/mesh/simplicial_mesh.h"
#include "optim/errors.h"

namespace sa {

struct HandleConflict {
    Index vertex = -1;
    Eigen::RowVectorXd first, second;  ///< the two targets
};

/// A connected part (over shared facets) whose boundary vertices are all handles, and what the
/// handles decide about it.
struct FixedBoundaryPart {
    int dimension = 0;  ///< of its simplices
    Index simplices = 0;
    Index first_simplex = -1;  ///< its lowest-numbered simplex
    /// The signed volume (area for triangles) its boundary's image encloses, in the targets' units.
    double volume = 0.0;
    bool encloses_volume = true;  ///< volume is positive (beyond round-off)
    /// Triangles mapped to the plane: the boundary loops' total turning number and the part's
    /// Euler characteristic V - E + F (not measured on a boundary that is not a set of loops).
    bool turning_measured = false;
    int turning = 0;
    Index euler = 0;
};

struct HandleFeasibility {
    Index fixed_simplices = 0;    ///< simplices whose vertices are all handles
    std::vector<Index> inverted;  ///< fixed simplices whose orientation is reversed
    std::vector<Index> flat;      ///< fixed simplices of (numerically) zero volume
    std::vector<HandleConflict> conflicts;
    std::vector<std::array<Index, 2>> collapsed_edges;
    /// Parts with a fixed boundary that encloses no positive volume or turns too few times.
    std::vector<FixedBoundaryPart> enclosing;

    bool feasible() const {
        return inverted.empty() && flat.empty() && conflicts.empty() && collapsed_edges.empty() &&
               enclosing.empty();
    }
    /// One sentence naming each count and the first `shown` elements of each kind.
    std::string describe(std::size_t shown = 5) const;
};

/// `mesh` is the rest shape (#V x 2 or #V x 3; triangles or tetrahedra), `handles` the handle
/// vertices (indices in [0, #V), possibly repeated), `targets` their positions (#handles x d, d the
/// simplex dimension, one row per entry of `handles`), `tolerance` the distance within which two
/// targets of one vertex agree (in the targets' units). The fixed-boundary check runs when
/// `topology` (mesh_topology(mesh)) is given.
HandleFeasibility check_handle_feasibility(const SimplicialMesh& mesh,
                                           const std::vector<Index>& handles,
                                           const Eigen::MatrixXd& targets, double tolerance,
                                           const MeshTopology* topology = nullptr);

/// The problem has no solution as posed: what() is "SOURCE: infeasible: " + describe().
class InfeasibleProblemError : public NoSolutionError {
  public:
    InfeasibleProblemError(const std::string& source, HandleFeasibility diagnosis);
    const HandleFeasibility& diagnosis() const { return diagnosis_; }

  private:
    HandleFeasibility diagnosis_;
};

}  // namespace sa
