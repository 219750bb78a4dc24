#pragma once
// A front-end's own assembly terms (kind 2 of engine.h) and barriers over several simplices
// (kind 3) for the mesh driver (frontends/simplex_assembly/map_solve.h): the hook through which a
// problem such as PolyCube (planarity of the boundary charts, a sliding boundary, the 3D
// boundary-angle barriers) is a configuration of the one driver and engine, with no schedule of its
// own.
//
// A MappingProblem holds plugins (MappingProblem::plugins); the driver calls each in every place
// where it builds an engine for the whole mesh:
//   - the assembly stage (r-SA and f-SA: the linear-part layout; v-SA: corner copies), after its
//     own terms: add_assembly_terms(engine, stage). The plugin names its variables through the
//     engine (linear_variables(s), affine_variables(s), linear_part_map(s), ...) and adds
//     linear constraints (add_linear_part_constraints, add_linear_constraints: weighted by lambda
//     in E~_assembly) and barriers (add_barrier: on the barrier side of the schedule).
//   - the vertex stage (vertex positions): first project(positions, stage) may move the start
//     onto the plugin's constraint set (PolyCube: each chart's vertices onto one plane), returning
//     false when it cannot; shared_coordinates(positions, stage) may make single coordinates of
//     several vertices one variable (a PolyCube plane); then add_vertex_terms(engine, stage) adds
//     its terms and may fix single variables (engine.problem().set_fixed).
//   - the hand-over test and the vertex stage's feasibility: energy(positions, stage) is the
//     plugin's barrier at a mesh (+inf when infeasible), added to the per-simplex energies, and the
//     recovered mesh is handed over only once project() accepts it.
// Everything the plugin sees is in the driver's normalized coordinates (PluginStage): rest and map
// both centred and scaled by the same factor, so linear parts A are those of the user's units.
//
// Limits: the submesh mode refuses problems with plugins (restricting a plugin's terms to a
// region is not available: choose_mode throws for SolveMode::kSubmesh and kAuto takes the full
// solve), and the last-resort untangling (untangle_fallback.h) does not run for them, since it
// would ignore their terms.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "frontends/simplex_assembly/engine.h"
#include "geometry/mesh/rest_frames.h"
#include "geometry/mesh/simplicial_mesh.h"

namespace sa {

/// Where the driver calls a plugin, with what it knows there.
template <int D>
struct PluginStage {
    enum class Kind { kAssembly, kVertex };
    Kind kind = Kind::kAssembly;
    const SimplicialMesh* mesh = nullptr;  ///< the rest mesh, normalized
    const RestFrames<D>* frames = nullptr;
    /// normalized = (original - map_center) * scale, for the map's coordinates.
    double scale = 1.0;
    Eigen::RowVectorXd map_center;
    /// Vertex stage: the vertices the driver keeps fixed (handles; anchors unless a plugin
    /// removes_rigid_motion()); null in the assembly stage.
    const std::vector<unsigned char>* fixed = nullptr;
};

/// What every plugin is, whatever its dimension: held by MappingProblem.
class AssemblyPluginBase {
  public:
    explicit AssemblyPluginBase(std::string name) : name_(std::move(name)) {}
    virtual ~AssemblyPluginBase() = default;
    const std::string& name() const { return name_; }
    virtual int dimension() const = 0;

  private:
    std::string name_;
};

template <int D>
class AssemblyPlugin : public AssemblyPluginBase {
  public:
    using AssemblyPluginBase::AssemblyPluginBase;
    int dimension() const final { return D; }

    /// The assembly stage: adds the plugin's terms to `engine` (any of its two assembly layouts;
    /// throw InvalidArgumentError for one it does not support).
    virtual void add_assembly_terms(SimplexAssemblyEngine<D>& engine,
                                    const PluginStage<D>& stage) const = 0;
    /// The vertex stage's start: may move `positions` (#V x D, normalized) onto the plugin's
    /// constraint set; false when it cannot (the vertex stage does not run from them).
    virtual bool project(Eigen::MatrixXd& /*positions*/, const PluginStage<D>& /*stage*/) const {
        return true;
    }
    /// The vertex stage: coordinates that are one variable (SimplexAssemblyEngine::
    /// vertex_positions' `shared`: D #V entries, or empty for none) at the projected start
    /// `positions`. PolyCube: the vertices of a plane share their coordinate along its normal, so
    /// the plane moves as one. At most one plugin of a problem may share coordinates.
    virtual std::vector<Index> shared_coordinates(const Eigen::MatrixXd& /*positions*/,
                                                  const PluginStage<D>& /*stage*/) const {
        return {};
    }
    /// The vertex stage: adds terms to `engine` (vertex layout, at the projected start, with the
    /// shared coordinates above) and may fix variables.
    virtual void add_vertex_terms(SimplexAssemblyEngine<D>& engine,
                                  const PluginStage<D>& stage) const = 0;
    /// The plugin's barriers at the mesh `positions` (normalized): +inf when infeasible, 0 when it
    /// has none.
    virtual double energy(const Eigen::MatrixXd& /*positions*/,
                          const PluginStage<D>& /*stage*/) const {
        return 0.0;
    }
    /// True when the vertex-stage terms fix the map's rigid motion themselves (PolyCube's planes
    /// do): the vertex stage then does not keep the anchored simplices (a part without handles)
    /// in place.
    virtual bool removes_rigid_motion() const { return false; }
};

}  // namespace sa
