#include "frontends/simplex_assembly/assembly_problem.h"

#include <algorithm>
#include <set>

#include "energies/affine_point_energies.h"
#include "energies/boundary_angle_energy.h"
#include "energies/edge_assembly_energy.h"
#include "energies/simplex_energy.h"
#include "energies/vertex_copy_energies.h"
#include "geometry/tagged_simplices.h"

namespace sa {

namespace {

/// The local index of vertex v in simplex s (-1 when absent).
int local_index(const SimplicialMesh& mesh, Index s, Index v) {
    for (int k = 0; k < mesh.simplices.cols(); ++k) {
        if (mesh.simplices(s, k) == v) return k;
    }
    return -1;
}

template <int N>
std::array<Index, N> consecutive(Index first) {
    std::array<Index, N> a;
    for (int k = 0; k < N; ++k) a[k] = first + k;
    return a;
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
    : variant_(options.variant), mesh_(in.mesh), frames_(in.frames) {
    const Index n = in.mesh->num_simplices();
    const SimplexEnergy<D> simplex_energy(simplex_energy_options(options), in.frames->volume,
                                          options.mapping_distortion == DistortionType::kDifference
                                              ? in.reference_linear
                                              : std::vector<Mat<D>>{});
    translation_offset_.assign(n, -1);
    if (variant_ == Variant::kVertex) {
        if (!in.fans.empty()) {
            throw InvalidArgumentError("the boundary-angle barrier needs the r-SA or f-SA variant");
        }
        build_vertex(in);
        std::vector<Mat<D>> rest_inverse = in.frames->edge_inverse;
        std::vector<std::array<Index, D*(D + 1)>> elements(n);
        for (Index s = 0; s < n; ++s) elements[s] = consecutive<D*(D + 1)>(Index(D * (D + 1)) * s);
        simplex_term_ = problem_->add_term(
            "simplex energy", VertexSimplexEnergy<D>(simplex_energy, std::move(rest_inverse)),
            std::move(elements));
        problem_->add_variable_block("vertex copies", 0, problem_->num_variables());
        return;
    }
    if (variant_ == Variant::kReduced) {
        build_reduced(in);
    } else {
        build_full(in);
    }
    std::vector<std::array<Index, D * D>> elements(n);
    for (Index s = 0; s < n; ++s) elements[s] = consecutive<D * D>(a_offset(s));
    simplex_term_ = problem_->add_term("simplex energy", simplex_energy, std::move(elements));
    if constexpr (D == 2) {
        add_boundary_angle_terms(in);
    }
    problem_->add_variable_block("linear parts", 0, a_offset(n));
    if (!translation_simplices_.empty()) {
        const BlockId b =
            problem_->add_variable_block("translations", a_offset(n), problem_->num_variables());
        if (variant_ == Variant::kReduced) shifted_block_ = b;
    }
    for (Index s : in.anchored_simplices) {
        for (int k = 0; k < D * D; ++k) problem_->set_fixed(a_offset(s) + k);
        if (translation_offset_[s] >= 0) {
            for (int k = 0; k < D; ++k) problem_->set_fixed(translation_offset_[s] + k);
        }
    }
}

template <int D>
void AssemblyProblem<D>::add_boundary_angle_terms(const AssemblyInput<D>& in) {
    if constexpr (D == 2) {
        for (const BoundaryFan& fan : in.fans) {
            if (fan.triangles.size() > std::size_t(kMaxFan)) {
                throw InvalidArgumentError("boundary vertex " + std::to_string(fan.vertex) +
                                           " has " + std::to_string(fan.triangles.size()) +
                                           " triangles; the boundary-angle "
                                           "barrier (--free-boundary-injective) handles at most " +
                                           std::to_string(kMaxFan));
            }
        }
        // One term per fan size K: E_theta on the linear parts of the fan's triangles.
        [&]<int... k>(std::integer_sequence<int, k...>) {
            (
                [&] {
                    constexpr int K = k + 1;
                    BoundaryAngleEnergy<K> energy;
                    std::vector<std::array<Index, 4 * K>> elements;
                    for (const BoundaryFan& fan : in.fans) {
                        if (int(fan.triangles.size()) != K) continue;
                        std::array<Mat<2>, K> edges;
                        std::array<Index, 4 * K> element;
                        for (int t = 0; t < K; ++t) {
                            edges[t] = fan_edges(*in.mesh, *in.frames, fan, t);
                            for (int c = 0; c < 4; ++c)
                                element[4 * t + c] = a_offset(fan.triangles[t]) + c;
                        }
                        energy.edges.push_back(edges);
                        elements.push_back(element);
                    }
                    if (!elements.empty()) {
                        problem_->add_term("boundary angle " + std::to_string(K), std::move(energy),
                                           std::move(elements));
                    }
                }(),
                ...);
        }
        (std::make_integer_sequence<int, kMaxFan>{});
    }
}

template <int D>
void AssemblyProblem<D>::build_reduced(const AssemblyInput<D>& in) {
    const SimplicialMesh& mesh = *in.mesh;
    const MeshTopology& topology = *in.topology;
    const RestFrames<D>& frames = *in.frames;
    const Index n = mesh.num_simplices();

    // Omega_s: a simplex per tree edge, plus one per handle no tagged simplex contains.
    tree_ = approximate_steiner_tree(mesh.num_vertices(), topology.edges, in.handles);
    const std::vector<Index> edge_simplex = tag_simplices(mesh, topology, tree_);
    std::set<Index> tagged(edge_simplex.begin(), edge_simplex.end());
    for (Index h : in.handles) {
        bool covered = false;
        for (Index s : tagged) covered |= local_index(mesh, s, h) >= 0;
        if (!covered) tagged.insert(topology.simplices_of_vertex[topology.vertex_begin[h]]);
    }
    translation_simplices_.assign(tagged.begin(), tagged.end());

    Eigen::VectorXd x(a_offset(n) + Index(D) * translation_simplices_.size());
    for (Index s = 0; s < n; ++s)
        x.template segment<D * D>(a_offset(s)) =
            Eigen::Map<const Vec<D * D>>(in.start_linear[s].data());
    for (std::size_t k = 0; k < translation_simplices_.size(); ++k) {
        const Index s = translation_simplices_[k];
        translation_offset_[s] = a_offset(n) + Index(D) * Index(k);
        x.template segment<D>(translation_offset_[s]) = in.start_translation[s];
    }
    problem_ = std::make_unique<Problem>(std::move(x));
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
            concat<D * D, D * D>(consecutive<D * D>(a_offset(i)), consecutive<D * D>(a_offset(j))));
    }
    assembly_terms_.push_back(problem_->add_term(
        "edge assembly", EdgeAssemblyEnergy<D>(std::move(facets)), std::move(facet_elements)));

    auto affine_block = [&](Index s) {
        return concat<D * D, D>(consecutive<D * D>(a_offset(s)),
                                consecutive<D>(translation_offset_[s]));
    };
    // Handle assembly (Eq. 8).
    std::vector<typename AffinePointTargetEnergy<D>::Target> targets;
    std::vector<std::array<Index, D * D + D>> target_elements;
    for (std::size_t k = 0; k < in.handles.size(); ++k) {
        const Index h = in.handles[k];
        for (Index s : translation_simplices_) {
            const int local = local_index(mesh, s, h);
            if (local < 0) continue;
            targets.push_back({frames.corner(s, local), in.targets[k]});
            target_elements.push_back(affine_block(s));
        }
    }
    if (!targets.empty()) {
        assembly_terms_.push_back(problem_->add_term("handle assembly",
                                                     AffinePointTargetEnergy<D>(std::move(targets)),
                                                     std::move(target_elements)));
    }
    // Vertex assembly (Eq. 9): the tagged simplices of the tree edges at each tree vertex agree
    // on it (a chain of pairs joins them all).
    std::vector<std::vector<Index>> at_vertex(mesh.num_vertices());
    for (std::size_t e = 0; e < tree_.size(); ++e) {
        for (Index v : tree_[e]) at_vertex[v].push_back(edge_simplex[e]);
    }
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
            point_elements.push_back(
                concat<D * D + D, D * D + D>(affine_block(p), affine_block(q)));
        }
    }
    if (!points.empty()) {
        assembly_terms_.push_back(
            problem_->add_term("vertex assembly", AffinePointAgreementEnergy<D>(std::move(points)),
                               std::move(point_elements)));
    }
}

template <int D>
void AssemblyProblem<D>::build_full(const AssemblyInput<D>& in) {
    const SimplicialMesh& mesh = *in.mesh;
    const RestFrames<D>& frames = *in.frames;
    const Index n = mesh.num_simplices();
    Eigen::VectorXd x(a_offset(n) + Index(D) * n);
    for (Index s = 0; s < n; ++s) {
        x.template segment<D * D>(a_offset(s)) =
            Eigen::Map<const Vec<D * D>>(in.start_linear[s].data());
        translation_offset_[s] = a_offset(n) + Index(D) * s;
        x.template segment<D>(translation_offset_[s]) = in.start_translation[s];
        translation_simplices_.push_back(s);
    }
    problem_ = std::make_unique<Problem>(std::move(x));
    auto affine_block = [&](Index s) {
        return concat<D * D, D>(consecutive<D * D>(a_offset(s)),
                                consecutive<D>(translation_offset_[s]));
    };
    // Eq. 2: both simplices of a facet agree on each of its vertices.
    std::vector<typename AffinePointAgreementEnergy<D>::Point> points;
    std::vector<std::array<Index, 2 * (D * D + D)>> point_elements;
    for (const InteriorFacet& f : in.topology->interior_facets) {
        const Index i = f.simplex[0], j = f.simplex[1];
        for (int k = 0; k < D; ++k) {
            const Index v = f.vertices[k];
            points.push_back({frames.corner(i, local_index(mesh, i, v)),
                              frames.corner(j, local_index(mesh, j, v))});
            point_elements.push_back(
                concat<D * D + D, D * D + D>(affine_block(i), affine_block(j)));
        }
    }
    assembly_terms_.push_back(problem_->add_term("facet vertex assembly",
                                                 AffinePointAgreementEnergy<D>(std::move(points)),
                                                 std::move(point_elements)));
    // Eq. 3: every simplex containing a handle maps it to its target.
    std::vector<typename AffinePointTargetEnergy<D>::Target> targets;
    std::vector<std::array<Index, D * D + D>> target_elements;
    const MeshTopology& topology = *in.topology;
    for (std::size_t k = 0; k < in.handles.size(); ++k) {
        const Index h = in.handles[k];
        for (Index i = topology.vertex_begin[h]; i < topology.vertex_begin[h + 1]; ++i) {
            const Index s = topology.simplices_of_vertex[i];
            targets.push_back({frames.corner(s, local_index(mesh, s, h)), in.targets[k]});
            target_elements.push_back(affine_block(s));
        }
    }
    if (!targets.empty()) {
        assembly_terms_.push_back(problem_->add_term("handle assembly",
                                                     AffinePointTargetEnergy<D>(std::move(targets)),
                                                     std::move(target_elements)));
    }
}

template <int D>
void AssemblyProblem<D>::build_vertex(const AssemblyInput<D>& in) {
    const SimplicialMesh& mesh = *in.mesh;
    const RestFrames<D>& frames = *in.frames;
    const Index n = mesh.num_simplices();
    constexpr int kCopies = D * (D + 1);
    Eigen::VectorXd x(Index(kCopies) * n);
    for (Index s = 0; s < n; ++s) {
        for (int k = 0; k <= D; ++k) {
            x.template segment<D>(kCopies * s + D * k) =
                in.start_linear[s] * frames.corner(s, k) + in.start_translation[s];
        }
    }
    problem_ = std::make_unique<Problem>(std::move(x));
    auto copy = [&](Index s, Index v) {
        return consecutive<D>(Index(kCopies) * s + D * local_index(mesh, s, v));
    };
    std::vector<std::array<Index, 2 * D>> pairs;
    for (const InteriorFacet& f : in.topology->interior_facets) {
        for (int k = 0; k < D; ++k)
            pairs.push_back(
                concat<D, D>(copy(f.simplex[0], f.vertices[k]), copy(f.simplex[1], f.vertices[k])));
    }
    assembly_terms_.push_back(
        problem_->add_term("copy assembly", VertexCopyAgreementEnergy<D>{}, std::move(pairs)));
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
        assembly_terms_.push_back(problem_->add_term("handle assembly", std::move(target_energy),
                                                     std::move(target_elements)));
    }
    for (Index s : in.anchored_simplices) {
        for (int k = 0; k < kCopies; ++k) problem_->set_fixed(kCopies * s + k);
    }
}

template <int D>
Mat<D> AssemblyProblem<D>::linear_part(const Eigen::VectorXd& x, Index s) const {
    if (variant_ == Variant::kVertex) {
        Eigen::Matrix<double, D, D + 1> copies;
        for (int k = 0; k <= D; ++k) copies.col(k) = x.template segment<D>(D * (D + 1) * s + D * k);
        return sa::linear_part<D>(*frames_, s, copies);
    }
    return Eigen::Map<const Mat<D>>(x.data() + a_offset(s));
}

template <int D>
std::vector<Mat<D>> AssemblyProblem<D>::linear_parts(const Eigen::VectorXd& x) const {
    std::vector<Mat<D>> A(mesh_->num_simplices());
    for (Index s = 0; s < mesh_->num_simplices(); ++s) A[s] = linear_part(x, s);
    return A;
}

template <int D>
std::vector<std::pair<Index, Vec<D>>> AssemblyProblem<D>::known_translations(
    const Eigen::VectorXd& x) const {
    std::vector<std::pair<Index, Vec<D>>> known;
    if (variant_ == Variant::kVertex) {
        for (Index s = 0; s < mesh_->num_simplices(); ++s) {
            Vec<D> centroid = Vec<D>::Zero();  // the frame's origin is the rest centroid
            for (int k = 0; k <= D; ++k) centroid += x.template segment<D>(D * (D + 1) * s + D * k);
            known.emplace_back(s, centroid / double(D + 1));
        }
        return known;
    }
    for (Index s : translation_simplices_)
        known.emplace_back(s, x.template segment<D>(translation_offset_[s]));
    known.insert(known.end(), anchor_translations_.begin(), anchor_translations_.end());
    return known;
}

template class AssemblyProblem<2>;
template class AssemblyProblem<3>;

}  // namespace sa
