#pragma once
// Verification of a map that differs from an already verified one on a few vertices (the
// optimal-bound rounds in the submesh mode, which move the vertices of their regions only).
// Internal to the mesh driver (frontends/simplex_assembly/map_solve.h).
//
// It measures what verify_result() measures (prepared_problem.h), from the positions, but only
// on the simplices that have a vertex whose position changed (inverted, degenerate, the barrier's
// distortion, the problem's own bounded distortions) and on the vertices of those simplices
// (branch points: every other vertex keeps its whole star, so its angle sum); the other
// simplices keep their measurements from the verified map. Handles and edge constraints are
// measured whole. Triangles only; for tetrahedra (branched edges) the whole map is measured.
// The map a run finally returns is to be verified whole, once (verify_result()).

#include <vector>

#include "frontends/simplex_assembly/detail/prepared_problem.h"

namespace sa {

/// The per-simplex and per-vertex measurements of the last verified map.
struct VerifiedMap {
    Eigen::MatrixXd positions;  ///< #V x d, original units; empty: nothing measured yet
    std::vector<double> det;    ///< per simplex: det A (map_quality()'s inverted and degenerate)
    std::vector<double> distortion;           ///< per simplex, the barrier's measure
    std::vector<std::vector<double>> bounds;  ///< per own bounded distortion, per simplex
    std::vector<unsigned char> branched;      ///< per vertex
    RestFrames<2> frames;                     ///< of the rest mesh at the verification's scale
    double unit = 1.0;                        ///< that scale
};

/// Fills result.verification (and result.success) for result.positions, measured on the
/// simplices around the vertices that moved since `state` (all of them when `state` is empty),
/// and records the new measurements in `state`. result.final_quality is left empty. Triangle
/// meshes only (D = 2); throws InvalidArgumentError otherwise.
template <int D>
void verify_changes(const PreparedProblem<D>& p, const SimplexAssemblyOptions& options,
                    SimplexAssemblyResult& result, VerifiedMap& state);

}  // namespace sa
