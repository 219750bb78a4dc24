#pragma once
// The mapping problem's configuration of the engine (engine.h) for one of the three variants of
// section 5.1: its variables, its assembly terms, its per-simplex energies, and reading linear
// parts and translations back.
//
//   r-SA  variables: vec(A_i) for every simplex, then T_p for the tagged simplices Omega_s of
//         the Steiner tree through the handles (section 4.3), and of loops that generate the
//         mesh's first homology (closing them around holes and handles; assembly_problem.cpp
//         says why) tied to that tree. Terms: edge assembly (Eq. 7) per
//         shared facet; handle assembly (Eq. 8) per handle and tagged simplex containing it;
//         vertex assembly (Eq. 9) between the tagged simplices of tree edges meeting at a tree
//         vertex (a chain of pairs).
//   f-SA  vec(A_i) and T_i for every simplex; Eq. 2 per shared facet vertex, Eq. 3 per handle and
//         simplex containing it.
//   v-SA  D + 1 vertex copies per simplex (the engine's corner layout); copies of a shared vertex
//         must agree, copies of a handle reach its target.
// Then, in every variant, the per-simplex energies (the options' mu E_m + E_C, then the
// problem's own), the boundary-angle barrier E_theta when asked (r-SA and f-SA), and the user's
// linear constraints on linear parts, and the plugins' terms. Anchored simplices (one per
// connected part without handles) keep their linear part, translation and copies fixed, which
// removes the global motion such a part would otherwise have (in r-SA and f-SA, when a plugin
// removes_rigid_motion(), only the translation and, as one assembly row, the trace of A).

#include <memory>
#include <utility>
#include <vector>

#include "frontends/simplex_assembly/assembly_plugin.h"
#include "frontends/simplex_assembly/engine.h"
#include "frontends/simplex_assembly/map_options.h"
#include "frontends/simplex_assembly/simplex_term.h"
#include "frontends/simplex_assembly/steiner_tree.h"
#include "geometry/mesh/boundary_fans.h"
#include "geometry/mesh/mesh_topology.h"
#include "geometry/mesh/rest_frames.h"

namespace sa {

/// An EdgeConstraint in the driver's normalized coordinates, divided by the rest length of the
/// edge so that its residual is that of a unit edge, as in Eq. 7:
///     normal . (x_b - x_a) = value,
/// on the simplex `simplex` containing the edge in the assembly (n^T A_s (u_b - u_a) = value).
template <int D>
struct EdgeRow {
    Index a = -1, b = -1;
    Index simplex = -1;
    Vec<D> normal = Vec<D>::Zero();
    double value = 0.0;
};

/// What the builder needs, in the driver's normalized coordinates.
template <int D>
struct AssemblyInput {
    const SimplicialMesh* mesh = nullptr;
    const MeshTopology* topology = nullptr;
    const RestFrames<D>* frames = nullptr;
    std::vector<Mat<D>> start_linear;       ///< feasible A_i after disassembly
    std::vector<Vec<D>> start_translation;  ///< T_i of the initial map
    std::vector<Mat<D>> reference_linear;   ///< A_i^0 of the initial map (E_m = difference)
    std::vector<Index> handles;
    std::vector<Vec<D>> targets;            ///< one per handle
    std::vector<Index> anchored_simplices;  ///< fixed simplices
    /// Boundary fans for E_theta (section 5.1); empty: no such term. Triangles only.
    std::vector<BoundaryFan> fans;
    /// The per-simplex energies of A: the options' mu E_m + E_C first, then the problem's own.
    std::vector<std::shared_ptr<const SimplexTerm<D>>> energies;
    /// The problem's linear constraints.
    std::vector<EdgeRow<D>> constraints;
    /// The problem's plugins (assembly_plugin.h), added after every other term, and what they
    /// are told (kind kAssembly; its pointers refer to the prepared problem).
    std::vector<std::shared_ptr<const AssemblyPlugin<D>>> plugins;
    PluginStage<D> plugin_stage;
};

template <int D>
class AssemblyProblem {
  public:
    AssemblyProblem(const AssemblyInput<D>& input, const SimplexAssemblyOptions& options);

    SimplexAssemblyEngine<D>& engine() { return *engine_; }
    const SimplexAssemblyEngine<D>& engine() const { return *engine_; }
    const Problem& problem() const { return engine_->problem(); }

    std::vector<Mat<D>> linear_parts(const Eigen::VectorXd& x) const {
        return engine_->linear_parts(x);
    }
    /// The translations the variables determine at x: r-SA the tagged simplices and the anchors,
    /// f-SA and v-SA every simplex.
    std::vector<std::pair<Index, Vec<D>>> known_translations(const Eigen::VectorXd& x) const;

    Index num_tree_edges() const { return static_cast<Index>(tree_.size()); }
    /// r-SA: the loops Omega_s follows (homology_loops.h), 0 for a disk or a ball.
    Index num_loops() const { return num_loops_; }
    Index num_translation_simplices() const { return num_translation_simplices_; }

  private:
    void build_reduced(const AssemblyInput<D>& in);
    void build_full(const AssemblyInput<D>& in);
    void build_vertex(const AssemblyInput<D>& in);
    void add_boundary_angle_terms(const AssemblyInput<D>& in);
    /// The per-simplex energies, E_theta, the linear constraints and the plugins' terms, in that
    /// order.
    void add_energies_and_constraints(const AssemblyInput<D>& in);

    Variant variant_;
    std::unique_ptr<SimplexAssemblyEngine<D>> engine_;
    std::vector<GraphEdge> tree_;
    Index num_translation_simplices_ = 0;
    Index num_loops_ = 0;
    std::vector<std::pair<Index, Vec<D>>> anchor_translations_;  ///< r-SA anchors
};

extern template class AssemblyProblem<2>;
extern template class AssemblyProblem<3>;

}  // namespace sa
