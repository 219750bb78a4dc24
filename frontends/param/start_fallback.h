#pragma once
// The parameterization's fallback when the requested start folds beyond repair or its result does
// not verify: a start that cannot fold, kept valid. Tutte's embedding with mean-value weights,
// then with uniform weights (both onto a circle, convex: no foldover in exact arithmetic), each
// checked as a map before it is used:
//  - a start with an inverted triangle (round-off) is rejected and the next one tried;
//  - a start whose triangles are positively oriented but numerically degenerate (Tutte maps of
//    nearly closed surfaces shrink triangles by 1e10 and more: the far end of a tube closed at
//    one end shrinks exponentially with its depth) is repaired first: Newton on the vertex
//    positions with the isometric barrier alone, which grows shrunken triangles back (the
//    conformal barrier is scale-invariant and would leave them); a start it cannot repair is
//    rejected.
// An accepted start goes to Newton on the vertex positions (vertex_descent.h) with the solver's
// options, whose barrier keeps every iterate valid; E_m's reference is that start (E_m =
// difference measures the change from the initial map, and the initial map is now it).

#include <string>
#include <vector>

#include "frontends/param/start_disk.h"
#include "frontends/simplex_assembly/vertex_descent.h"
#include "geometry/mesh_topology.h"

namespace sa {

struct TriedStart {
    std::string name;     ///< "tutte" (mean-value) or "tutte-uniform"
    std::string outcome;  ///< one sentence
    bool valid = false;   ///< the start itself had no inverted or degenerate triangle
    bool verified = false;
    double max_distortion = kInfinity;  ///< of its result, in the barrier's measure
};

struct StartFallback {
    bool used = false;   ///< the fallback ran
    std::string reason;  ///< why the requested start's result was not kept
    std::vector<TriedStart> starts;
    std::string start;           ///< the start whose result is `solve` (empty when none verified)
    Eigen::MatrixXd initial_uv;  ///< that start, #V x 2
    std::vector<DescentRound> rounds;
    SimplexAssemblyResult solve;  ///< its result (verified: no inverted or degenerate triangle)
    double time = 0.0;
    bool verified() const { return !start.empty(); }
};

/// Runs the fallback on `problem.mesh` with the solver's options; `problem` supplies the boundary
/// barrier flag and the source name. The Tutte starts are computed on `disk` (start_disk.h).
/// Keeps the first start whose result verifies within the bound, else the verified one of least
/// distortion.
StartFallback fall_back_to_tutte(const MappingProblem& problem, const StartDisk& disk,
                                 const SimplexAssemblyOptions& solver,
                                 const SimplexAssemblyObserver& observer, std::string reason);

}  // namespace sa
