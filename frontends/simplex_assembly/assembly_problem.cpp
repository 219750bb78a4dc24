#include "frontends/simplex_assembly/detail/assembly_problem.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "energies/affine_point_energies.h"
#include "energies/boundary_angle_energy.h"
#include "energies/edge_assembly_energy.h"
#include "energies/vertex_copy_energies.h"
#include "frontends/simplex_assembly/tagged_simplices.h"
#include "geometry/mesh/homology_loops.h"

namespace sa {

namespace {

/// The local index of vertex v in simplex s (-1 when absent).
int local_index(const SimplicialMesh& mesh, Index s, Index v) {
    for (int k = 0; k < mesh.simplices.cols(); ++k) {
        if (mesh.simplices(s, k) == v) return k;
    }
    return -1;
}

/// The surface whose loops are the mesh's (homology_loops.h): the triangles themselves, or a
/// tetrahedral mesh's boundary facets.
std::vector<std::array<Index, 3>> surface_triangles(const SimplicialMesh& mesh,
                                                    const MeshTopology& topology) {
    std::vector<std::array<Index, 3>> triangles;
    if (mesh.simplices.cols() == 3) {
        for (Index t = 0; t < mesh.num_simplices(); ++t)
            triangles.push_back({mesh.simplices(t, 0), mesh.simplices(t, 1), mesh.simplices(t, 2)});
    } else {
        for (const BoundaryFacet& f : topology.boundary_facets) triangles.push_back(f.vertices);
    }
    return triangles;
}

template <int N, int M>
std::array<Index, N + M> concat(const std::array<Index, N>& a, const std::array<Index, M>& b) {
    std::array<Index, N + M> c;
    std::copy(a.begin(), a.end(), c.begin());
    std::copy(b.begin(), b.end(), c.begin() + N);
    return c;
}

}  // namespace

template <int D>
AssemblyProblem<D>::AssemblyProblem(const AssemblyInput<D>& in,
                                    const SimplexAssemblyOptions& options)
    : variant_(options.variant) {
    if (variant_ == Variant::kVertex) {
        if (!in.fans.empty()) {
            throw InvalidArgumentError("the boundary-angle barrier needs the r-SA or f-SA variant");
        }
        build_vertex(in);
    } else if (variant_ == Variant::kReduced) {
        build_reduced(in);
    } else {
        build_full(in);
    }
    add_energies_and_constraints(in);
    // A plugin whose terms fix the rigid motion (PolyCube's axis-aligned planes) would conflict
    // with an anchor's fixed linear part: the anchors then keep their translations only.
    bool plugins_fix_motion = false;
    for (const auto& plugin : in.plugins) plugins_fix_motion |= plugin->removes_rigid_motion();
    // Its scale stays, though: a conformal barrier does not see the map's scale and E~_assembly
    // shrinks with it, so without it the assembly drifted towards a point (pente, 200 iterations
    // at lambda_max: a map 3e-9 across). One row, trace(A_s) = D |det A_s^0|^(1/D) (D times the
    // start similarity's scale: the trace of A_s once it is that similarity without rotation).
    std::vector<LinearPartConstraint<D, 1>> scale_rows;
    for (Index s : in.anchored_simplices) {
        if (!plugins_fix_motion || variant_ == Variant::kVertex) {
            engine_->fix_simplex(s);
            continue;
        }
        if (engine_->has_translation(s)) {
            for (Index v : engine_->translation_variables(s)) engine_->problem().set_fixed(v);
        }
        LinearPartConstraint<D, 1> row;
        row.simplex = s;
        row.rows.coefficients.setZero();
        for (int i = 0; i < D; ++i) row.rows.coefficients(0, i + D * i) = 1.0;
        row.rows.rhs[0] = D * std::pow(std::abs(in.start_linear[s].determinant()), 1.0 / D);
        scale_rows.push_back(row);
    }
    if (!scale_rows.empty())
        engine_->template add_linear_part_constraints<1>("anchor scale", scale_rows);
}

template <int D>
void AssemblyProblem<D>::add_energies_and_constraints(const AssemblyInput<D>& in) {
    for (const auto& energy : in.energies) energy->add_to(*engine_);
    if constexpr (D == 2) {
        add_boundary_angle_terms(in);
    }
    if (!in.constraints.empty()) {
        const SimplicialMesh& mesh = *in.mesh;
        const RestFrames<D>& frames = *in.frames;
        std::vector<LinearPartConstraint<D, 1>> rows;
        rows.reserve(in.constraints.size());
        for (const EdgeRow<D>& c : in.constraints) {
            const Index s = c.simplex;
            const Vec<D> e = frames.corner(s, local_index(mesh, s, c.b)) -
                             frames.corner(s, local_index(mesh, s, c.a));
            // n^T A e = sum_ij n_i A_ij e_j; vec(A) is column-major: A_ij at i + D j.
            LinearPartConstraint<D, 1> row;
            row.simplex = s;
            for (int j = 0; j < D; ++j)
                row.rows.coefficients.template block<1, D>(0, D * j) = e[j] * c.normal.transpose();
            row.rows.rhs[0] = c.value;
            rows.push_back(row);
        }
        engine_->template add_linear_part_constraints<1>("edge constraints", rows);
    }
    for (const auto& plugin : in.plugins) plugin->add_assembly_terms(*engine_, in.plugin_stage);
}

template <int D>
void AssemblyProblem<D>::add_boundary_angle_terms(const AssemblyInput<D>& in) {
    if constexpr (D == 2) {
        // E_theta on the linear parts of each fan's triangles: one term for fans of any size.
        BoundaryAngleEnergy energy;
        RaggedElements elements;
        for (const BoundaryFan& fan : in.fans) {
            std::vector<Mat<2>>& edges = energy.edges.emplace_back();
            std::vector<Index> element;
            for (std::size_t t = 0; t < fan.triangles.size(); ++t) {
                edges.push_back(fan_edges(*in.mesh, *in.frames, fan, int(t)));
                const auto a = engine_->linear_variables(fan.triangles[t]);
                element.insert(element.end(), a.begin(), a.end());
            }
            elements.push_back(element);
        }
        if (!elements.empty())
            engine_->add_barrier("boundary angle", std::move(energy), std::move(elements));
    }
}

template <int D>
void AssemblyProblem<D>::build_reduced(const AssemblyInput<D>& in) {
    const SimplicialMesh& mesh = *in.mesh;
    const MeshTopology& topology = *in.topology;
    const RestFrames<D>& frames = *in.frames;

    // Eq. 7 alone glues the simplices only along contractible loops (the Appendix glues simplex
    // by simplex): around a hole or a handle the A_i may agree across every facet and still
    // integrate to a map that does not close. Omega_s therefore also follows loops generating the
    // mesh's H1 (geometry/mesh/homology_loops.h; a solid's lie on its boundary): with Eq. 9 at each
    // loop vertex, sum_k A_{p_k} e_k over a loop telescopes to zero. The Steiner tree ties the
    // loops to the handles or, in a part without handles, to its anchored simplex, which joins
    // Omega_s so that its fixed translation removes the loops' common translation.
    const std::vector<std::vector<Index>> loops =
        homology_loops(mesh.num_vertices(), surface_triangles(mesh, topology));
    std::vector<Index> terminals = in.handles;
    std::vector<std::pair<Index, Index>> anchors;  // (simplex, its vertex in the tree)
    if (!loops.empty()) {
        for (const auto& loop : loops) terminals.push_back(loop.front());
        for (Index s : in.anchored_simplices) {
            anchors.emplace_back(s, mesh.simplices(s, 0));
            terminals.push_back(mesh.simplices(s, 0));
        }
        std::sort(terminals.begin(), terminals.end());
        terminals.erase(std::unique(terminals.begin(), terminals.end()), terminals.end());
    }
    tree_ = approximate_steiner_tree(mesh.num_vertices(), topology.edges, terminals);
    num_loops_ = static_cast<Index>(loops.size());
    if (!loops.empty()) {
        std::set<GraphEdge> edges(tree_.begin(), tree_.end());
        for (const auto& loop : loops) {
            for (std::size_t k = 0; k < loop.size(); ++k) {
                const Index a = loop[k], b = loop[(k + 1) % loop.size()];
                edges.insert({std::min(a, b), std::max(a, b)});
            }
        }
        tree_.assign(edges.begin(), edges.end());
    }
    // Omega_s: a simplex per tree (and loop) edge, plus one per handle no tagged simplex contains.
    const std::vector<Index> edge_simplex = tag_simplices(mesh, topology, tree_);
    std::set<Index> tagged(edge_simplex.begin(), edge_simplex.end());
    for (const auto& [s, v] : anchors) tagged.insert(s);
    for (Index h : in.handles) {
        // Covered when a tagged simplex contains h: one of the simplices around it.
        bool covered = false;
        for (Index i = topology.vertex_begin[h]; i < topology.vertex_begin[h + 1] && !covered; ++i)
            covered = tagged.count(topology.simplices_of_vertex[i]) > 0;
        if (!covered) tagged.insert(topology.simplices_of_vertex[topology.vertex_begin[h]]);
    }
    std::vector<std::pair<Index, Vec<D>>> translations;
    for (Index s : tagged) translations.emplace_back(s, in.start_translation[s]);
    num_translation_simplices_ = static_cast<Index>(translations.size());
    engine_ = std::make_unique<SimplexAssemblyEngine<D>>(in.start_linear, translations);
    SimplexAssemblyEngine<D>& engine = *engine_;
    for (Index s : in.anchored_simplices)
        anchor_translations_.emplace_back(s, in.start_translation[s]);

    // Edge assembly (Eq. 7): the facet's edges in each simplex's frame, normalized.
    std::vector<SharedFacetEdges<D>> facets;
    std::vector<std::array<Index, 2 * D * D>> facet_elements;
    for (const InteriorFacet& f : topology.interior_facets) {
        SharedFacetEdges<D> edges;
        const Index i = f.simplex[0], j = f.simplex[1];
        for (int k = 0; k < SharedFacetEdges<D>::kEdges; ++k) {
            const Index a = f.vertices[k], b = f.vertices[(k + 1) % D];
            const Vec<D> ei = frames.corner(i, local_index(mesh, i, b)) -
                              frames.corner(i, local_index(mesh, i, a));
            const Vec<D> ej = frames.corner(j, local_index(mesh, j, b)) -
                              frames.corner(j, local_index(mesh, j, a));
            edges.in_i.col(k) = ei / ei.norm();
            edges.in_j.col(k) = ej / ej.norm();
        }
        facets.push_back(edges);
        facet_elements.push_back(
            concat<D * D, D * D>(engine.linear_variables(i), engine.linear_variables(j)));
    }
    engine.add_assembly_term("edge assembly", EdgeAssemblyEnergy<D>(std::move(facets)),
                             std::move(facet_elements));

    // Handle assembly (Eq. 8).
    std::vector<typename AffinePointTargetEnergy<D>::Target> targets;
    std::vector<std::array<Index, D * D + D>> target_elements;
    std::vector<Index> tagged_around;  // the tagged simplices around a handle, increasing
    for (std::size_t k = 0; k < in.handles.size(); ++k) {
        const Index h = in.handles[k];
        tagged_around.clear();
        for (Index i = topology.vertex_begin[h]; i < topology.vertex_begin[h + 1]; ++i) {
            const Index s = topology.simplices_of_vertex[i];
            if (tagged.count(s) > 0) tagged_around.push_back(s);
        }
        std::sort(tagged_around.begin(), tagged_around.end());
        for (Index s : tagged_around) {
            targets.push_back({frames.corner(s, local_index(mesh, s, h)), in.targets[k]});
            target_elements.push_back(engine.affine_variables(s));
        }
    }
    if (!targets.empty()) {
        engine.add_assembly_term("handle assembly", AffinePointTargetEnergy<D>(std::move(targets)),
                                 std::move(target_elements));
    }
    // Vertex assembly (Eq. 9): the tagged simplices of the tree edges at each tree vertex agree
    // on it (a chain of pairs joins them all).
    std::vector<std::vector<Index>> at_vertex(mesh.num_vertices());
    for (std::size_t e = 0; e < tree_.size(); ++e) {
        for (Index v : tree_[e]) at_vertex[v].push_back(edge_simplex[e]);
    }
    for (const auto& [s, v] : anchors) at_vertex[v].push_back(s);
    std::vector<typename AffinePointAgreementEnergy<D>::Point> points;
    std::vector<std::array<Index, 2 * (D * D + D)>> point_elements;
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        std::vector<Index>& list = at_vertex[v];
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
        for (std::size_t k = 0; k + 1 < list.size(); ++k) {
            const Index p = list[k], q = list[k + 1];
            points.push_back({frames.corner(p, local_index(mesh, p, v)),
                              frames.corner(q, local_index(mesh, q, v))});
            point_elements.push_back(concat<D * D + D, D * D + D>(engine.affine_variables(p),
                                                                  engine.affine_variables(q)));
        }
    }
    if (!points.empty()) {
        engine.add_assembly_term("vertex assembly",
                                 AffinePointAgreementEnergy<D>(std::move(points)),
                                 std::move(point_elements));
    }
}

template <int D>
void AssemblyProblem<D>::build_full(const AssemblyInput<D>& in) {
    const SimplicialMesh& mesh = *in.mesh;
    const RestFrames<D>& frames = *in.frames;
    const Index n = mesh.num_simplices();
    std::vector<std::pair<Index, Vec<D>>> translations;
    for (Index s = 0; s < n; ++s) translations.emplace_back(s, in.start_translation[s]);
    num_translation_simplices_ = n;
    engine_ = std::make_unique<SimplexAssemblyEngine<D>>(in.start_linear, translations);
    SimplexAssemblyEngine<D>& engine = *engine_;
    // Eq. 2: both simplices of a facet agree on each of its vertices.
    std::vector<typename AffinePointAgreementEnergy<D>::Point> points;
    std::vector<std::array<Index, 2 * (D * D + D)>> point_elements;
    for (const InteriorFacet& f : in.topology->interior_facets) {
        const Index i = f.simplex[0], j = f.simplex[1];
        for (int k = 0; k < D; ++k) {
            const Index v = f.vertices[k];
            points.push_back({frames.corner(i, local_index(mesh, i, v)),
                              frames.corner(j, local_index(mesh, j, v))});
            point_elements.push_back(concat<D * D + D, D * D + D>(engine.affine_variables(i),
                                                                  engine.affine_variables(j)));
        }
    }
    engine.add_assembly_term("facet vertex assembly",
                             AffinePointAgreementEnergy<D>(std::move(points)),
                             std::move(point_elements));
    // Eq. 3: every simplex containing a handle maps it to its target.
    std::vector<typename AffinePointTargetEnergy<D>::Target> targets;
    std::vector<std::array<Index, D * D + D>> target_elements;
    const MeshTopology& topology = *in.topology;
    for (std::size_t k = 0; k < in.handles.size(); ++k) {
        const Index h = in.handles[k];
        for (Index i = topology.vertex_begin[h]; i < topology.vertex_begin[h + 1]; ++i) {
            const Index s = topology.simplices_of_vertex[i];
            targets.push_back({frames.corner(s, local_index(mesh, s, h)), in.targets[k]});
            target_elements.push_back(engine.affine_variables(s));
        }
    }
    if (!targets.empty()) {
        engine.add_assembly_term("handle assembly", AffinePointTargetEnergy<D>(std::move(targets)),
                                 std::move(target_elements));
    }
}

template <int D>
void AssemblyProblem<D>::build_vertex(const AssemblyInput<D>& in) {
    const SimplicialMesh& mesh = *in.mesh;
    const RestFrames<D>& frames = *in.frames;
    const Index n = mesh.num_simplices();
    std::vector<Eigen::Matrix<double, D, D + 1>> corners(n);
    for (Index s = 0; s < n; ++s) {
        for (int k = 0; k <= D; ++k)
            corners[s].col(k) = in.start_linear[s] * frames.corner(s, k) + in.start_translation[s];
    }
    num_translation_simplices_ = 0;  // no translation variables: copies
    engine_ = std::make_unique<SimplexAssemblyEngine<D>>(
        SimplexAssemblyEngine<D>::corner_copies(corners, frames.corners, frames.edge_inverse));
    SimplexAssemblyEngine<D>& engine = *engine_;
    auto copy = [&](Index s, Index v) {
        const auto all = engine.affine_variables(s);
        std::array<Index, D> c;
        std::copy_n(all.begin() + D * local_index(mesh, s, v), D, c.begin());
        return c;
    };
    std::vector<std::array<Index, 2 * D>> pairs;
    for (const InteriorFacet& f : in.topology->interior_facets) {
        for (int k = 0; k < D; ++k)
            pairs.push_back(
                concat<D, D>(copy(f.simplex[0], f.vertices[k]), copy(f.simplex[1], f.vertices[k])));
    }
    engine.add_assembly_term("copy assembly", VertexCopyAgreementEnergy<D>{}, std::move(pairs));
    VertexCopyTargetEnergy<D> target_energy;
    std::vector<std::array<Index, D>> target_elements;
    const MeshTopology& topology = *in.topology;
    for (std::size_t k = 0; k < in.handles.size(); ++k) {
        const Index h = in.handles[k];
        for (Index i = topology.vertex_begin[h]; i < topology.vertex_begin[h + 1]; ++i) {
            target_energy.targets.push_back(in.targets[k]);
            target_elements.push_back(copy(topology.simplices_of_vertex[i], h));
        }
    }
    if (!target_elements.empty()) {
        engine.add_assembly_term("handle assembly", std::move(target_energy),
                                 std::move(target_elements));
    }
}

template <int D>
std::vector<std::pair<Index, Vec<D>>> AssemblyProblem<D>::known_translations(
    const Eigen::VectorXd& x) const {
    std::vector<std::pair<Index, Vec<D>>> known = engine_->known_translations(x);
    if (variant_ == Variant::kReduced)
        known.insert(known.end(), anchor_translations_.begin(), anchor_translations_.end());
    return known;
}

template class AssemblyProblem<2>;
template class AssemblyProblem<3>;

}  // namespace sa
