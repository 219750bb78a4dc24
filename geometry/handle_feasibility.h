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

#include <Eigen/Core>
#include <string>
#include <vector>

#include "geometry/simplicial_mesh.h"
#include "optim/errors.h"

namespace sa {

struct HandleConflict {
    Index vertex = -1;
    Eigen::RowVectorXd first, second;  ///< the two targets
};

struct HandleFeasibility {
    Index fixed_simplices = 0;    ///< simplices whose vertices are all handles
    std::vector<Index> inverted;  ///< fixed simplices whose orientation is reversed
    std::vector<Index> flat;      ///< fixed simplices of (numerically) zero volume
    std::vector<HandleConflict> conflicts;
    std::vector<std::array<Index, 2>> collapsed_edges;

    bool feasible() const {
        return inverted.empty() && flat.empty() && conflicts.empty() && collapsed_edges.empty();
    }
    /// One sentence naming each count and the first `shown` elements of each kind.
    std::string describe(std::size_t shown = 5) const;
};

/// `mesh` is the rest shape (#V x 2 or #V x 3; triangles or tetrahedra), `handles` the handle
/// vertices (indices in [0, #V), possibly repeated), `targets` their positions (#handles x d, d the
/// simplex dimension, one row per entry of `handles`), `tolerance` the distance within which two
/// targets of one vertex agree (in the targets' units).
HandleFeasibility check_handle_feasibility(const SimplicialMesh& mesh,
                                           const std::vector<Index>& handles,
                                           const Eigen::MatrixXd& targets, double tolerance);

/// The problem has no solution as posed: what() is "SOURCE: infeasible: " + describe().
class InfeasibleProblemError : public Error {
  public:
    InfeasibleProblemError(const std::string& source, HandleFeasibility diagnosis);
    const HandleFeasibility& diagnosis() const { return diagnosis_; }

  private:
    HandleFeasibility diagnosis_;
};

}  // namespace sa
