#pragma once
// Turns a disassembled mesh into the optimization problem of Eq. 10 for one of the three variants
// (section 5.1), and reads linear parts and translations back from its variables.
//
//   r-SA  variables: vec(A_i) for every simplex, then T_p for the tagged simplices Omega_s of
//         the Steiner tree through the handles (section 4.3). Terms: the simplex energy
//         mu w_i d_m(A_i) + E_C(A_i); edge assembly (Eq. 7) per shared facet; handle assembly
//         (Eq. 8) per handle and tagged simplex containing it; vertex assembly (Eq. 9) between
//         the tagged simplices of tree edges meeting at a tree vertex (a chain of pairs).
//   f-SA  vec(A_i) and T_i for every simplex; Eq. 2 per shared facet vertex, Eq. 3 per handle and
//         simplex containing it.
//   v-SA  D + 1 vertex copies per simplex; copies of a shared vertex must agree, copies of a
//         handle reach its target.
// The assembly terms share the weight lambda (set by the driver at every iteration). Anchored
// simplices (one per connected part without handles) keep their linear part, translation and
// copies fixed, which removes the global motion such a part would otherwise have.

#include <memory>
#include <utility>
#include <vector>

#include "frontends/simplex_assembly/simplex_assembly_options.h"
#include "geometry/boundary_fans.h"
#include "geometry/mesh_topology.h"
#include "geometry/rest_frames.h"
#include "geometry/steiner_tree.h"
#include "optim/problem.h"

namespace sa {

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
};

template <int D>
class AssemblyProblem {
  public:
    AssemblyProblem(const AssemblyInput<D>& input, const SimplexAssemblyOptions& options);

    Problem& problem() { return *problem_; }
    const Problem& problem() const { return *problem_; }
    TermId simplex_term() const { return simplex_term_; }
    const std::vector<TermId>& assembly_terms() const { return assembly_terms_; }
    /// The block of r-SA's translations (carries the 1e-6 lambda shift); -1 for f-SA and v-SA.
    BlockId shifted_translation_block() const { return shifted_block_; }

    Mat<D> linear_part(const Eigen::VectorXd& x, Index s) const;
    std::vector<Mat<D>> linear_parts(const Eigen::VectorXd& x) const;
    /// The translations the variables determine at x: r-SA the tagged simplices and the anchors,
    /// f-SA and v-SA every simplex.
    std::vector<std::pair<Index, Vec<D>>> known_translations(const Eigen::VectorXd& x) const;

    Index num_tree_edges() const { return static_cast<Index>(tree_.size()); }
    Index num_translation_simplices() const {
        return static_cast<Index>(translation_simplices_.size());
    }

  private:
    void build_reduced(const AssemblyInput<D>& in);
    void build_full(const AssemblyInput<D>& in);
    void build_vertex(const AssemblyInput<D>& in);
    void add_boundary_angle_terms(const AssemblyInput<D>& in);
    Index a_offset(Index s) const { return Index(D * D) * s; }

    Variant variant_;
    const SimplicialMesh* mesh_;
    const RestFrames<D>* frames_;
    std::unique_ptr<Problem> problem_;
    TermId simplex_term_ = -1;
    std::vector<TermId> assembly_terms_;
    BlockId shifted_block_ = -1;
    std::vector<GraphEdge> tree_;
    std::vector<Index> translation_simplices_;  ///< simplices with T variables, in order
    std::vector<Index> translation_offset_;     ///< per simplex: offset of T_s in x, or -1
    std::vector<std::pair<Index, Vec<D>>> anchor_translations_;  ///< r-SA anchors
};

extern template class AssemblyProblem<2>;
extern template class AssemblyProblem<3>;

}  // namespace sa
