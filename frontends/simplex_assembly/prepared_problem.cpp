#include "frontends/simplex_assembly/detail/prepared_problem.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <cmath>
#include <set>
#include <sstream>

#include "energies/boundary_angle_energy.h"
#include "energies/distortion.h"
#include "energies/simplex_energy.h"
#include "frontends/simplex_assembly/disassembly.h"
#include "geometry/maps/vertex_recovery.h"
#include "geometry/mesh/boundary_fans.h"
#include "geometry/quality/handle_feasibility.h"
#include "geometry/quality/local_injectivity.h"
#include "optim/errors.h"
#include "optim/stopwatch.h"

namespace sa {

namespace {

/// Makes every boundary angle sum of the disassembled triangles smaller than 2 pi, as section 5.1
/// says: a triangle's angle at a boundary vertex is narrowed by a stretch along its bisector
/// (determinant > 0, so no triangle is inverted). Similarities keep the rest angles, whose sum
/// exceeds 2 pi at saddle-shaped boundary vertices of a surface.
void open_boundary_angles(const SimplicialMesh& mesh, const std::vector<BoundaryFan>& fans,
                          const RestFrames<2>& frames, std::vector<Mat<2>>& A,
                          const std::string& source) {
    auto angle = [](const Mat<2>& A, const Mat<2>& E) {
        const Eigen::Vector2d a = A * E.col(0), b = A * E.col(1);
        return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    };
    auto angle_sum = [&](const BoundaryFan& fan) {
        double theta = 0.0;
        for (std::size_t k = 0; k < fan.triangles.size(); ++k) {
            theta += angle(A[fan.triangles[k]], fan_edges(mesh, frames, fan, k));
        }
        return theta;
    };
    const double target = 0.95 * 2.0 * M_PI;
    for (int pass = 0; pass < 10; ++pass) {
        bool changed = false;
        for (const BoundaryFan& fan : fans) {
            const double theta = angle_sum(fan);
            if (theta < target) continue;
            changed = true;
            const double ratio = target / theta;
            for (std::size_t k = 0; k < fan.triangles.size(); ++k) {
                Mat<2>& a = A[fan.triangles[k]];
                const Mat<2> E = fan_edges(mesh, frames, fan, k);
                const double alpha = angle(a, E);
                // Stretch across the bisector: tan(alpha' / 2) = f tan(alpha / 2).
                const Eigen::Vector2d d =
                    ((a * E.col(0)).normalized() + (a * E.col(1)).normalized()).normalized();
                const Eigen::Vector2d n(-d.y(), d.x());
                const double f = std::tan(0.5 * ratio * alpha) / std::tan(0.5 * alpha);
                a = (d * d.transpose() + f * n * n.transpose()) * a;
            }
        }
        if (!changed) return;
    }
    for (const BoundaryFan& fan : fans) {
        if (!(angle_sum(fan) < 2.0 * M_PI)) {
            throw InputError(source + ": cannot start with the angle sum at boundary vertex " +
                             std::to_string(fan.vertex) + " below 2 pi");
        }
    }
}

void check_input(const MappingProblem& p, const SimplexAssemblyOptions& options, int d) {
    const std::string& src = p.source;
    for (std::size_t k = 0; k < p.energies.size(); ++k) {
        if (p.energies[k] == nullptr)
            throw InvalidArgumentError(src + ": energy " + std::to_string(k) + " is null");
        if (p.energies[k]->dimension() != d) {
            throw InvalidArgumentError(
                src + ": energy '" + p.energies[k]->name() + "' is an energy of " +
                std::to_string(p.energies[k]->dimension()) + "x" +
                std::to_string(p.energies[k]->dimension()) + " matrices, the mesh's simplices " +
                "have dimension " + std::to_string(d));
        }
    }
    for (std::size_t k = 0; k < p.plugins.size(); ++k) {
        if (p.plugins[k] == nullptr)
            throw InvalidArgumentError(src + ": plugin " + std::to_string(k) + " is null");
        if (p.plugins[k]->dimension() != d) {
            throw InvalidArgumentError(src + ": plugin '" + p.plugins[k]->name() +
                                       "' is for simplices of dimension " +
                                       std::to_string(p.plugins[k]->dimension()) +
                                       ", the mesh's have dimension " + std::to_string(d));
        }
    }
    if (!options.builtin_energy && p.energies.empty()) {
        throw InvalidArgumentError(
            src +
            ": builtin_energy = false and the problem has no energy of its own: nothing "
            "keeps the simplices from inverting");
    }
    if (p.initial.rows() != p.mesh.num_vertices()) {
        throw InputError(src + ": the initial map has " + std::to_string(p.initial.rows()) +
                         " vertices, the rest mesh " + std::to_string(p.mesh.num_vertices()));
    }
    if (p.initial.cols() < d) {
        throw InputError(src + ": the initial map has " + std::to_string(p.initial.cols()) +
                         " coordinates per vertex, a map of " +
                         (d == 2 ? "triangles" : "tetrahedra") + " needs " + std::to_string(d));
    }
    if (!p.initial.leftCols(d).allFinite())
        throw InputError(src + ": the initial map has a non-finite coordinate");
    for (Index h : p.handles) {
        if (h < 0 || h >= p.mesh.num_vertices()) {
            throw InputError(src + ": handle vertex " + std::to_string(h) + " outside [0, " +
                             std::to_string(p.mesh.num_vertices()) + ")");
        }
    }
    if (p.reference.size() > 0 &&
        (p.reference.rows() != p.mesh.num_vertices() || p.reference.cols() < d)) {
        throw InputError(src + ": the reference map has " + std::to_string(p.reference.rows()) +
                         " rows for " + std::to_string(p.mesh.num_vertices()) + " vertices");
    }
    if (p.targets.size() > 0 &&
        (p.targets.rows() != Index(p.handles.size()) || p.targets.cols() < d)) {
        throw InputError(src + ": " + std::to_string(p.targets.rows()) + " handle targets for " +
                         std::to_string(p.handles.size()) + " handles");
    }
}

/// Coordinates that are finite but near the largest double overflow in the initial map's affine
/// parts (a 1e308 on a free vertex made the solve run and write -inf): an InputError naming the
/// simplex and its vertices, before anything is solved. `A` are the linear parts, `start` the
/// normalized positions whose centroids are the translations.
template <int D>
void check_finite_affine_parts(const MappingProblem& input, const std::vector<Mat<D>>& A,
                               const Eigen::MatrixXd& start) {
    for (Index s = 0; s < Index(A.size()); ++s) {
        Vec<D> centroid = Vec<D>::Zero();
        for (int k = 0; k <= D; ++k) centroid += start.row(input.mesh.simplices(s, k)).transpose();
        if (A[s].allFinite() && centroid.allFinite()) continue;
        std::ostringstream msg;
        msg << input.source << ": the initial map's affine part of simplex " << s
            << " is not finite (its vertices";
        double largest = 0.0;
        for (int k = 0; k <= D; ++k) {
            const Index v = input.mesh.simplices(s, k);
            msg << (k ? ", " : " ") << v;
            largest = std::max(largest, input.initial.row(v).head(D).cwiseAbs().maxCoeff());
        }
        msg << " have coordinates up to " << largest
            << "): the map's coordinates overflow; scale the map down";
        throw InputError(msg.str());
    }
}

/// What the handles alone decide (handle_feasibility.h): throws InfeasibleProblemError before
/// anything is optimized when they force an inverted or flat simplex, fix a vertex at two places,
/// collapse a rest edge or fix a boundary that encloses nothing; a vertex listed twice at one place
/// is a malformed list (InputError).
void require_feasible_handles(const MappingProblem& p, const Eigen::MatrixXd& targets,
                              double tolerance, const MeshTopology& topology) {
    const HandleFeasibility f =
        check_handle_feasibility(p.mesh, p.handles, targets, tolerance, &topology);
    if (!f.feasible()) throw InfeasibleProblemError(p.source, f);
    std::set<Index> seen;
    for (Index h : p.handles) {
        if (!seen.insert(h).second)
            throw InputError(p.source + ": handle vertex " + std::to_string(h) +
                             " is listed twice");
    }
}

/// The problem's edge constraints, checked, in normalized units (EdgeRow).
template <int D>
std::vector<EdgeRow<D>> edge_rows(const MappingProblem& p, const SimplicialMesh& normalized,
                                  const MeshTopology& topology, double scale) {
    std::vector<EdgeRow<D>> rows;
    const Index nv = p.mesh.num_vertices();
    for (std::size_t k = 0; k < p.constraints.size(); ++k) {
        const EdgeConstraint& c = p.constraints[k];
        const std::string what = p.source + ": constraint " + std::to_string(k) + " on edge (" +
                                 std::to_string(c.a) + ", " + std::to_string(c.b) + ")";
        if (c.a < 0 || c.a >= nv || c.b < 0 || c.b >= nv)
            throw InputError(what + ": a vertex outside [0, " + std::to_string(nv) + ")");
        if (c.normal.size() != D) {
            throw InputError(what + ": its normal has " + std::to_string(c.normal.size()) +
                             " entries, the map " + std::to_string(D));
        }
        if (!c.normal.allFinite() || !std::isfinite(c.value))
            throw InputError(what + ": a non-finite normal or value");
        const double length = c.normal.norm();
        if (!(length > 0.0)) throw InputError(what + ": its normal is zero");
        EdgeRow<D> row;
        row.a = c.a;
        row.b = c.b;
        for (Index i = topology.vertex_begin[c.a]; i < topology.vertex_begin[c.a + 1]; ++i) {
            const Index s = topology.simplices_of_vertex[i];
            for (int m = 0; m < normalized.simplices.cols(); ++m)
                if (c.a != c.b && normalized.simplices(s, m) == c.b) row.simplex = s;
            if (row.simplex >= 0) break;
        }
        if (row.simplex < 0) throw InputError(what + ": not an edge of the mesh");
        const double rest_length =
            (normalized.vertices.row(c.b) - normalized.vertices.row(c.a)).norm();
        if (!(rest_length > 0.0)) throw InputError(what + ": the rest edge has length zero");
        row.normal = c.normal / (length * rest_length);
        row.value = c.value * scale / (length * rest_length);
        rows.push_back(row);
    }
    return rows;
}

/// An anchor for every connected part without a handle: its least distorted non-inverted
/// simplex in the start (its first simplex if all are inverted), by p.initial_quality.
template <int D>
void choose_anchors(PreparedProblem<D>& p) {
    const MappingProblem& input = *p.input;
    AssemblyInput<D>& in = p.assembly;
    const Index n = p.mesh.num_simplices();
    in.anchored_simplices.clear();
    Index components = 0;
    const std::vector<Index> component = p.topology.simplex_components(&components);
    std::vector<unsigned char> has_handle(components, 0);
    for (Index h : input.handles) {
        has_handle[component[p.topology.simplices_of_vertex[p.topology.vertex_begin[h]]]] = 1;
    }
    std::vector<Index> anchor(components, -1);
    for (Index s = 0; s < n; ++s) {
        const Index c = component[s];
        if (has_handle[c]) continue;
        if (anchor[c] < 0) {
            anchor[c] = s;
            continue;
        }
        const SimplexQuality& q = p.initial_quality.per_simplex[s];
        const SimplexQuality& best = p.initial_quality.per_simplex[anchor[c]];
        const bool usable = !q.inverted && !q.degenerate,
                   best_usable = !best.inverted && !best.degenerate;
        if ((usable && !best_usable) || (usable == best_usable && q.conformal < best.conformal))
            anchor[c] = s;
    }
    for (Index c = 0; c < components; ++c) {
        if (anchor[c] >= 0) in.anchored_simplices.push_back(anchor[c]);
    }
}

/// The options' mu E_m + E_C (with the options' bound) and the problem's own energies.
template <int D>
void set_energies(PreparedProblem<D>& p, const SimplexAssemblyOptions& options) {
    AssemblyInput<D>& in = p.assembly;
    in.energies.clear();
    p.energy = nullptr;
    if (options.builtin_energy) {
        p.energy = std::make_shared<const SimplexEnergy<D>>(
            simplex_energy_options(options), p.frames.volume,
            options.mapping_distortion == DistortionType::kDifference ? in.reference_linear
                                                                      : std::vector<Mat<D>>{});
        in.energies.push_back(
            std::make_shared<SimplexTermOf<D, SimplexEnergy<D>>>("simplex energy", p.energy));
    }
    for (const auto& energy : p.input->energies)
        in.energies.push_back(std::static_pointer_cast<const SimplexTerm<D>>(energy));
}

/// Eq. 6's fixed rows: the handles at their targets, the first vertex of each anchored simplex
/// at the image of its disassembled simplex (`disassembled`) or at its start position.
template <int D>
void set_pinned(PreparedProblem<D>& p, bool disassembled) {
    const AssemblyInput<D>& in = p.assembly;
    p.pinned = p.start;
    for (std::size_t k = 0; k < in.handles.size(); ++k)
        p.pinned.row(in.handles[k]) = in.targets[k].transpose();
    if (!disassembled) return;
    for (Index s : in.anchored_simplices) {
        const Index v = p.mesh.simplices(s, 0);
        p.pinned.row(v) =
            (in.start_linear[s] * p.frames.corner(s, 0) + in.start_translation[s]).transpose();
    }
}

}  // namespace

template <int D>
std::unique_ptr<PreparedProblem<D>> prepare_problem(const MappingProblem& input,
                                                    const SimplexAssemblyOptions& options,
                                                    StageTimes& times) {
    Stopwatch stage;
    auto p = std::make_unique<PreparedProblem<D>>();
    p->input = &input;
    const SimplicialMesh& original = input.mesh;
    validate_mesh(original, input.source);
    check_input(input, options, D);
    p->topology = mesh_topology(original, input.source);
    if constexpr (D == 3) p->tet_edges = tet_edges(original, p->topology);
    for (Index h : input.handles) {
        if (!p->topology.used_vertex[h]) {
            throw InputError(input.source + ": handle vertex " + std::to_string(h) +
                             " belongs to no simplex");
        }
    }
    const Index n = original.num_simplices();
    p->initial_map = input.initial.leftCols(D);
    p->target_rows.resize(input.handles.size(), D);
    for (std::size_t k = 0; k < input.handles.size(); ++k) {
        p->target_rows.row(k) = input.targets.size() > 0
                                    ? Eigen::RowVectorXd(input.targets.row(k).head(D))
                                    : Eigen::RowVectorXd(p->initial_map.row(input.handles[k]));
    }
    require_feasible_handles(input, p->target_rows,
                             options.handle_tolerance * bounding_box_diagonal(p->initial_map),
                             p->topology);

    // Normalize by the rest diagonal; each side centred on its own bounding box.
    p->scale = 1.0 / bounding_box_diagonal(original.vertices);
    const Eigen::RowVectorXd rest_center =
        0.5 * (original.vertices.colwise().minCoeff() + original.vertices.colwise().maxCoeff());
    p->map_center =
        0.5 * (p->initial_map.colwise().minCoeff() + p->initial_map.colwise().maxCoeff());
    p->mesh = original;
    p->mesh.vertices = (original.vertices.rowwise() - rest_center) * p->scale;
    p->start = (p->initial_map.rowwise() - p->map_center) * p->scale;
    p->frames = rest_frames<D>(p->mesh);
    times.setup += stage.lap();

    // Disassembly (section 4.2).
    AssemblyInput<D>& in = p->assembly;
    in.mesh = &p->mesh;
    in.topology = &p->topology;
    in.frames = &p->frames;
    in.start_linear = linear_parts<D>(p->mesh, p->frames, p->start);
    check_finite_affine_parts<D>(input, in.start_linear, p->start);
    p->initial_quality = map_quality<D>(in.start_linear, p->frames.volume);
    in.reference_linear =
        input.reference.size() > 0
            ? linear_parts<D>(p->mesh, p->frames,
                              (input.reference.leftCols(D).rowwise() - p->map_center) * p->scale)
            : in.start_linear;
    project_linear_parts<D>(in.start_linear, options.effective_initialization(), options.seed);
    in.start_translation.resize(n);
    for (Index s = 0; s < n; ++s) {
        Vec<D> centroid = Vec<D>::Zero();
        for (int k = 0; k <= D; ++k) centroid += p->start.row(original.simplices(s, k)).transpose();
        in.start_translation[s] = centroid / double(D + 1);
    }
    times.disassembly += stage.lap();

    // Handles, targets and an anchor for every connected part without a handle: its least
    // distorted non-inverted simplex in the initial map (its first simplex if all are inverted).
    in.handles = input.handles;
    for (Index k = 0; k < p->target_rows.rows(); ++k) {
        in.targets.push_back(((p->target_rows.row(k) - p->map_center) * p->scale).transpose());
    }
    choose_anchors(*p);
    if (input.boundary_injective) {
        if constexpr (D != 2) {
            throw InvalidArgumentError(
                input.source + ": the boundary-angle barrier is for triangles mapped to the plane");
        } else {
            in.fans = boundary_fans(original, p->topology);
            open_boundary_angles(original, in.fans, p->frames, in.start_linear, input.source);
        }
    }
    set_energies(*p, options);
    in.constraints = edge_rows<D>(input, p->mesh, p->topology, p->scale);
    for (const auto& plugin : input.plugins)
        in.plugins.push_back(std::static_pointer_cast<const AssemblyPlugin<D>>(plugin));
    in.plugin_stage.mesh = &p->mesh;
    in.plugin_stage.frames = &p->frames;
    in.plugin_stage.scale = p->scale;
    in.plugin_stage.map_center = p->map_center;

    // Eq. 6: handles at their targets, one vertex of each anchored simplex at its start image.
    set_pinned(*p, true);
    std::vector<unsigned char> fixed(p->mesh.num_vertices(), 0);
    for (Index h : in.handles) fixed[h] = 1;
    for (Index s : in.anchored_simplices) fixed[p->mesh.simplices(s, 0)] = 1;
    p->recovery_fixed = std::move(fixed);
    times.setup += stage.lap();
    return p;
}

template <int D>
void restart_problem(PreparedProblem<D>& p, const SimplexAssemblyOptions& options,
                     StageTimes& times) {
    Stopwatch stage;
    const MappingProblem& input = *p.input;
    if (input.initial.rows() != p.mesh.num_vertices() || input.initial.cols() < D ||
        !input.initial.leftCols(D).allFinite()) {
        throw InputError(input.source + ": the restarted map has " +
                         std::to_string(input.initial.rows()) + " rows for " +
                         std::to_string(p.mesh.num_vertices()) +
                         " vertices, or a non-finite coordinate");
    }
    p.initial_map = input.initial.leftCols(D);
    p.start = (p.initial_map.rowwise() - p.map_center) * p.scale;
    p.assembly.start_linear.clear();
    p.assembly.start_translation.clear();
    // The anchors of the parts without a handle are chosen again, as prepare_problem() would
    // from this start (the vertex stage keeps their simplices fixed).
    p.initial_quality = map_quality<D>(linear_parts<D>(p.mesh, p.frames, p.start), p.frames.volume);
    const std::vector<Index> anchors = p.assembly.anchored_simplices;
    choose_anchors(p);
    if (anchors != p.assembly.anchored_simplices) {
        std::vector<unsigned char> fixed(p.mesh.num_vertices(), 0);
        for (Index h : p.assembly.handles) fixed[h] = 1;
        for (Index s : p.assembly.anchored_simplices) fixed[p.mesh.simplices(s, 0)] = 1;
        p.recovery_fixed = std::move(fixed);
        p.reset_recovery();
    }
    set_pinned(p, false);
    set_energies(p, options);
    times.setup += stage.lap();
}

template <int D>
double mesh_energy(const PreparedProblem<D>& p, const Eigen::MatrixXd& positions) {
    const std::vector<Mat<D>> A = linear_parts<D>(p.mesh, p.frames, positions);
    double boundary = 0.0;
    for (double theta : boundary_angle_sums(p.assembly.fans, positions))
        boundary += boundary_angle_barrier(theta);
    double simplices = 0.0;
    for (const auto& energy : p.assembly.energies) simplices += energy->sum(A);
    PluginStage<D> stage = p.assembly.plugin_stage;
    stage.kind = PluginStage<D>::Kind::kVertex;
    double plugins = 0.0;
    for (const auto& plugin : p.assembly.plugins) plugins += plugin->energy(positions, stage);
    return boundary + simplices + plugins;
}

template <int D>
void verify_handles(const MappingProblem& input, const SimplexAssemblyOptions& options,
                    const Eigen::MatrixXd& positions, Verification& v) {
    v.handles = static_cast<Index>(input.handles.size());
    for (std::size_t k = 0; k < input.handles.size(); ++k) {
        const Eigen::RowVectorXd target =
            input.targets.size() > 0
                ? Eigen::RowVectorXd(input.targets.row(k).head(D))
                : Eigen::RowVectorXd(input.initial.row(input.handles[k]).head(D));
        v.handle_error =
            std::max(v.handle_error, (positions.row(input.handles[k]) - target).norm());
    }
    v.handle_tolerance =
        options.handle_tolerance * bounding_box_diagonal(input.initial.leftCols(D));
}

template <int D>
void verify_result(const MappingProblem& input, const SimplexAssemblyOptions& options,
                   SimplexAssemblyResult& result, const MeshTopology* topology) {
    const SimplicialMesh& original = input.mesh;
    // Measured on both sides scaled by the power of two nearest the rest diagonal's inverse:
    // the linear parts keep every bit, and volumes neither overflow nor underflow on a mesh at
    // 1e200 or 1e-200 (in original units every simplex was reported degenerate there).
    const double unit = std::ldexp(1.0, -scale_exponent(original.vertices));
    SimplicialMesh scaled = original;
    scaled.vertices *= unit;
    const RestFrames<D> rest = rest_frames<D>(scaled);
    const std::vector<Mat<D>> out =
        linear_parts<D>(scaled, rest, Eigen::MatrixXd(result.positions * unit));
    result.final_quality = map_quality<D>(out, rest.volume);
    Verification& v = result.verification;
    v = Verification{};
    v.simplices = original.num_simplices();
    v.inverted = result.final_quality.inverted;
    v.degenerate = result.final_quality.degenerate;
    if (v.inverted == 0 && v.degenerate == 0) {
        // Every simplex positive does not make the map locally injective: a branch point wraps
        // its star twice with every simplex positive (geometry/quality/local_injectivity.h).
        const MeshTopology own = topology ? MeshTopology{} : mesh_topology(original, input.source);
        const MeshTopology& t = topology ? *topology : own;
        if constexpr (D == 2) {
            const std::vector<Index> branched = branched_vertices(original, t, result.positions);
            v.branched = static_cast<Index>(branched.size());
            if (!branched.empty()) v.first_branch = "vertex " + std::to_string(branched[0]);
        } else {
            const std::vector<Index> branched = branched_edges(original, t, result.positions);
            v.branched = static_cast<Index>(branched.size());
            if (!branched.empty()) {
                v.first_branch = "edge " + std::to_string(t.edges[branched[0]][0]) + "-" +
                                 std::to_string(t.edges[branched[0]][1]);
            }
        }
    }
    verify_handles<D>(input, options, result.positions, v);
    v.bound = options.builtin_energy ? options.bound : kInfinity;
    v.max_distortion = tbb::parallel_reduce(
        tbb::blocked_range<Index>(0, original.num_simplices()), v.max_distortion,
        [&](const tbb::blocked_range<Index>& r, double largest) {
            for (Index s = r.begin(); s != r.end(); ++s) {
                const MatrixInvariants<double> m = matrix_invariants<D>(out[s], false);
                largest = std::max(
                    largest,
                    m.J > 0.0 ? distortion<D>(options.distortion, m, options.gamma) : kInfinity);
            }
            return largest;
        },
        [](double a, double b) { return std::max(a, b); });
    for (const auto& base : input.energies) {
        const auto& energy = static_cast<const SimplexTerm<D>&>(*base);
        if (energy.bounds_a_distortion())
            v.bounds.push_back({energy.name(), energy.bound(), energy.max_distortion(out)});
    }
    v.constraints = static_cast<Index>(input.constraints.size());
    v.constraint_tolerance = v.handle_tolerance;
    for (const EdgeConstraint& c : input.constraints) {
        const double length = c.normal.norm();
        const Eigen::VectorXd edge =
            (result.positions.row(c.b) - result.positions.row(c.a)).head(D).transpose();
        const double residual = std::abs(c.normal.dot(edge) / length - c.value / length);
        v.constraint_error = std::max(v.constraint_error, residual);
    }
    result.success = v.passed();
}

template std::unique_ptr<PreparedProblem<2>> prepare_problem<2>(const MappingProblem&,
                                                                const SimplexAssemblyOptions&,
                                                                StageTimes&);
template std::unique_ptr<PreparedProblem<3>> prepare_problem<3>(const MappingProblem&,
                                                                const SimplexAssemblyOptions&,
                                                                StageTimes&);
template void restart_problem<2>(PreparedProblem<2>&, const SimplexAssemblyOptions&, StageTimes&);
template void restart_problem<3>(PreparedProblem<3>&, const SimplexAssemblyOptions&, StageTimes&);
template double mesh_energy<2>(const PreparedProblem<2>&, const Eigen::MatrixXd&);
template double mesh_energy<3>(const PreparedProblem<3>&, const Eigen::MatrixXd&);
template void verify_handles<2>(const MappingProblem&, const SimplexAssemblyOptions&,
                                const Eigen::MatrixXd&, Verification&);
template void verify_handles<3>(const MappingProblem&, const SimplexAssemblyOptions&,
                                const Eigen::MatrixXd&, Verification&);
template <int D>
void verify_boundary_angles(const PreparedProblem<D>& p, SimplexAssemblyResult& result) {
    if (p.assembly.fans.empty()) return;
    result.boundary_violations_before = count_boundary_violations(p.assembly.fans, p.initial_map);
    result.boundary_violations_after = count_boundary_violations(p.assembly.fans, result.positions);
    if (result.boundary_violations_after > 0) result.success = false;
}

template <int D>
std::vector<unsigned char> vertex_stage_fixed(const PreparedProblem<D>& p) {
    for (const auto& plugin : p.assembly.plugins) {
        if (plugin->removes_rigid_motion()) {
            std::vector<unsigned char> fixed(p.recovery_fixed.size(), 0);
            for (Index h : p.assembly.handles) fixed[h] = 1;
            return fixed;
        }
    }
    std::vector<unsigned char> fixed = p.recovery_fixed;
    for (Index s : p.assembly.anchored_simplices) {
        for (int k = 0; k <= D; ++k) fixed[p.mesh.simplices(s, k)] = 1;
    }
    return fixed;
}

template std::vector<unsigned char> vertex_stage_fixed<2>(const PreparedProblem<2>&);
template std::vector<unsigned char> vertex_stage_fixed<3>(const PreparedProblem<3>&);
template void verify_boundary_angles<2>(const PreparedProblem<2>&, SimplexAssemblyResult&);
template void verify_boundary_angles<3>(const PreparedProblem<3>&, SimplexAssemblyResult&);
template void verify_result<2>(const MappingProblem&, const SimplexAssemblyOptions&,
                               SimplexAssemblyResult&, const MeshTopology*);
template void verify_result<3>(const MappingProblem&, const SimplexAssemblyOptions&,
                               SimplexAssemblyResult&, const MeshTopology*);

}  // namespace sa
