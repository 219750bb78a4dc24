#pragma once
// What both solve modes of the driver share: the input checked, normalized (rest diagonal 1,
// each side centred on its bounding box) and disassembled, with an anchor per connected part
// without handles; vertex recovery with the handles at their targets; verification of output
// positions. Internal to the mesh driver (frontends/simplex_assembly/map_solve.h).

#include <memory>

#include "energies/simplex_energy.h"
#include "frontends/simplex_assembly/detail/assembly_problem.h"
#include "frontends/simplex_assembly/map_solve.h"
#include "geometry/maps/vertex_recovery.h"
#include "geometry/mesh/mesh_topology.h"
#include "geometry/mesh/rest_frames.h"
#include "geometry/quality/local_injectivity.h"

namespace sa {

template <int D>
struct PreparedProblem {
    const MappingProblem* input = nullptr;
    MeshTopology topology;
    /// D = 3: each tetrahedron's edges, for the wrap test of every map tried (empty for D = 2).
    TetEdges tet_edges;
    SimplicialMesh mesh;  ///< normalized rest shape
    RestFrames<D> frames;
    double scale = 1.0;             ///< normalized = (original - center) * scale
    Eigen::RowVectorXd map_center;  ///< of the initial map's bounding box
    Eigen::MatrixXd initial_map;    ///< #V x D, original units
    Eigen::MatrixXd target_rows;    ///< #handles x D, original units
    Eigen::MatrixXd start;          ///< the initial map, normalized
    AssemblyInput<D> assembly;      ///< disassembled; its pointers refer to this object
    /// The options' built-in mu E_m + E_C (also the first of assembly.energies); null with
    /// builtin_energy = false. forced_distortion.h measures its barrier's distortion.
    std::shared_ptr<const SimplexEnergy<D>> energy;
    MapQuality initial_quality;
    /// Eq. 6 with the handles at their targets and the first vertex of every anchored simplex
    /// at its image (`pinned`, normalized; `recovery_fixed` marks those vertices).
    Eigen::MatrixXd pinned;
    std::vector<unsigned char> recovery_fixed;

    /// The Eq. 6 solver, factored on first use (a submesh solve whose start is valid never needs
    /// it; on a million triangles the factorization takes seconds).
    VertexRecovery<D>& recovery() {
        if (!recovery_)
            recovery_ = std::make_unique<VertexRecovery<D>>(mesh, frames, recovery_fixed);
        return *recovery_;
    }

    /// Drops the Eq. 6 solver (after recovery_fixed changed).
    void reset_recovery() { recovery_.reset(); }

    Eigen::MatrixXd to_original(const Eigen::MatrixXd& normalized) const {
        return (normalized / scale).rowwise() + map_center;
    }

  private:
    std::unique_ptr<VertexRecovery<D>> recovery_;
};

/// The vertices the vertex stage keeps fixed: the recovery's (handles, the pinned vertex of each
/// anchored simplex) and every vertex of an anchored simplex, as a free part has no rigid motion
/// left; with a plugin that fixes the rigid motion itself (PolyCube's planes), the handles only.
template <int D>
std::vector<unsigned char> vertex_stage_fixed(const PreparedProblem<D>& p);

/// Checks, normalizes and disassembles `input` (throws InputError on bad input).
template <int D>
std::unique_ptr<PreparedProblem<D>> prepare_problem(const MappingProblem& input,
                                                    const SimplexAssemblyOptions& options,
                                                    StageTimes& times);

/// Restarts `p` (prepared from *p.input) from p.input->initial with the bounds of `options` and of
/// p.input->energies, for another submesh-mode solve of the same mesh and handles (the
/// optimal-bound rounds): what depends on the rest shape only (topology, normalization, frames,
/// anchors, constraints, the Eq. 6 factorization) is kept; the start, its quality, the pinned rows
/// and the energies are replaced, the anchors chosen again; the normalization keeps the first
/// start's map centre. The
/// disassembly (assembly.start_linear, start_translation) is dropped: the submesh mode does not use
/// it, and a full-mode solve needs prepare_problem().
template <int D>
void restart_problem(PreparedProblem<D>& p, const SimplexAssemblyOptions& options,
                     StageTimes& times);

struct VerifiedMap;

/// What run_simplex_assembly() does after prepare_problem(): the mode (choose_mode()), the solve,
/// the verification of the output positions and the last resort. `preparation` holds the stage
/// times so far (its total included in the result's). With `changes` (triangles), the output is
/// verified where it differs from the map `changes` holds (round_verification.h), and `changes`
/// then holds it; the last resort's output is verified whole.
template <int D>
SimplexAssemblyResult solve_prepared(PreparedProblem<D>& p, const SimplexAssemblyOptions& options,
                                     const SimplexAssemblyObserver& observer,
                                     const StageTimes& preparation, VerifiedMap* changes = nullptr);

/// The energy of the per-simplex terms (the options' mu E_m + E_C and the problem's own; + E_theta
/// of the boundary fans, when asked; + the plugins' energy()) of the map `positions`
/// (normalized): +inf unless every simplex is positively oriented (against its rest orientation),
/// under every bound, every boundary angle sum below 2 pi and every plugin barrier finite.
template <int D>
double mesh_energy(const PreparedProblem<D>& p, const Eigen::MatrixXd& positions);

/// The handles' part of a verification: v.handles, the largest distance of a handle in
/// `positions` (#V x D, original units) from its target (or its initial position), and the
/// tolerance (options.handle_tolerance times the initial map's bounding-box diagonal).
template <int D>
void verify_handles(const MappingProblem& input, const SimplexAssemblyOptions& options,
                    const Eigen::MatrixXd& positions, Verification& v);

/// Measures result.positions (original units) against the rest shape and the targets: fills
/// final_quality, verification and success. `topology`, when given, is input.mesh's (it is
/// computed otherwise).
template <int D>
void verify_result(const MappingProblem& input, const SimplexAssemblyOptions& options,
                   SimplexAssemblyResult& result, const MeshTopology* topology = nullptr);

/// E_theta's part of a verification, for a problem with boundary fans (a free-boundary map kept
/// injective on its boundary, 5.1): the boundary vertices whose angle sum is 2 pi or more in the
/// initial map and in result.positions; a result with any has not succeeded. Nothing without fans.
template <int D>
void verify_boundary_angles(const PreparedProblem<D>& p, SimplexAssemblyResult& result);

}  // namespace sa
