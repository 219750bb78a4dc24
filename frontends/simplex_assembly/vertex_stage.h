#pragma once
// The last stage of Simplex Assembly in vertex variables. Once E~_assembly is below its tolerance
// the simplices form a mesh, and what the paper's schedule does next (lambda at 1e16) is to
// minimize mu E_m + E_C over assembled configurations: the same problem as minimizing it over
// the vertex positions with the handles fixed. In vertex variables it has no penalty term, so
// Newton keeps its quadratic convergence instead of fighting a condition number of 1e16
// (measured in BENCHMARKS.md). Starting from the recovered, inversion-free mesh, the barrier and
// the largest feasible step keep every iterate inversion-free and within the bound.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "energies/simplex_energy.h"
#include "frontends/simplex_assembly/simplex_assembly_options.h"
#include "geometry/boundary_fans.h"
#include "geometry/rest_frames.h"
#include "optim/logger.h"
#include "optim/newton_summary.h"

namespace sa {

struct VertexStage {
    bool ran = false;           ///< false when the start was not feasible (an inverted simplex)
    std::string note;           ///< why it did not run, or how it ended
    Eigen::MatrixXd positions;  ///< #V x D (the start when it did not run)
    NewtonSummary newton;
};

/// `start` #V x D in the driver's normalized coordinates; `fixed` flags handles and anchors;
/// `fans` (triangles only) adds the boundary-angle barrier E_theta.
template <int D>
VertexStage run_vertex_stage(const SimplicialMesh& mesh, const RestFrames<D>& frames,
                             const SimplexEnergy<D>& energy, const Eigen::MatrixXd& start,
                             const std::vector<unsigned char>& fixed,
                             const SimplexAssemblyOptions& options, const Logger& logger,
                             const std::vector<BoundaryFan>& fans = {});

}  // namespace sa
