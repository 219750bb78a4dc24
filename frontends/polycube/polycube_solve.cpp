#include "frontends/polycube/polycube_solve.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <sstream>
#include <tuple>

#include "frontends/polycube/boundary_angle_sums.h"
#include "frontends/polycube/cube_cover.h"
#include "frontends/polycube/polycube_constraints.h"
#include "frontends/polycube/polycube_planes.h"
#include "frontends/polycube/polycube_terms.h"
#include "frontends/simplex_assembly/untangle.h"
#include "geometry/mesh/rest_frames.h"
#include "geometry/mesh/submesh.h"
#include "geometry/mesh/tet_boundary.h"
#include "optim/errors.h"
#include "optim/stopwatch.h"

namespace sa {

namespace {

/// The PolyCube terms of polycube_solve.h as a plugin of the mesh driver.
class PolycubePlugin final : public AssemblyPlugin<3> {
  public:
    PolycubePlugin(const PreparedPolycube& prepared, double angle_weight,
                   const PolycubePluginOptions& options)
        : AssemblyPlugin<3>("polycube"), p_(prepared), weight_(angle_weight), options_(options) {
        build_planes();
        const std::vector<double>& held = options_.plane_coordinates;
        if (!held.empty() && held.size() != plane_axis_.size()) {
            throw InvalidArgumentError("polycube: " + std::to_string(held.size()) +
                                       " plane coordinates for " +
                                       std::to_string(plane_axis_.size()) + " planes");
        }
        for (const double c : held) {
            if (!std::isfinite(c))
                throw InvalidArgumentError("polycube: a plane coordinate is not finite");
        }
    }

    void add_assembly_terms(SimplexAssemblyEngine<3>& engine,
                            const PluginStage<3>& stage) const override {
        using Engine = SimplexAssemblyEngine<3>;
        if (engine.layout() != Engine::Layout::kLinearParts) {
            throw InvalidArgumentError(
                "polycube: the assembly stage takes the linear parts (r-SA or f-SA), not v-SA");
        }
        const PlanarityElements planarity = planarity_elements(p_);
        std::vector<LinearPartConstraint<3, 2>> rows;
        rows.reserve(planarity.rows.size());
        for (std::size_t k = 0; k < planarity.rows.size(); ++k)
            rows.push_back({planarity.tet[k], planarity.rows[k]});
        engine.add_linear_part_constraints<2>("polycube planarity", rows);
        add_plane_offsets(engine, stage);

        // The angle barriers in A-form: vec(A_t) of each tetrahedron of the fan or star, on
        // every boundary edge and vertex.
        auto add = [&](const char* name, const char* where, auto barrier) {
            RaggedElements elements;
            int largest = 0;
            for (Index e = 0; e < barrier.items.size(); ++e) {
                std::vector<Index> variables;
                for (const Index t : barrier.items[e]) {
                    const auto linear = engine.linear_variables(t);
                    variables.insert(variables.end(), linear.begin(), linear.end());
                }
                elements.push_back(variables);
                largest = std::max(largest, barrier.items.arity(e));
            }
            const Index count = elements.size();
            if (count > 0)
                engine.add_barrier(name, std::move(barrier.energy), std::move(elements), weight_);
            return std::to_string(count) + " boundary " + where + " (up to " +
                   std::to_string(largest) + " tetrahedra)";
        };
        const std::string edges =
            add("dihedral-angle sums, A-form", "edges", dihedral_sum_elements(p_));
        const std::string vertices =
            add("solid-angle sums, A-form", "vertices", solid_angle_sum_elements(p_));
        log_line(options_.logger, "polycube: angle barriers on " + edges + " and " + vertices);
    }

    bool project(Eigen::MatrixXd& positions, const PluginStage<3>& stage) const override {
        std::vector<double> sum(plane_axis_.size(), 0.0);
        std::vector<Index> count(plane_axis_.size(), 0);
        for (const auto& [v, plane] : members_) {
            sum[plane] += positions(v, plane_axis_[plane]);
            ++count[plane];
        }
        for (const auto& [v, plane] : members_) {
            positions(v, plane_axis_[plane]) =
                planes_held() ? held_coordinate(plane, stage) : sum[plane] / double(count[plane]);
        }
        if (!positions.allFinite()) return false;
        // Flattening the charts onto their planes folds tetrahedra along the boundary where the
        // assembly has not made the charts planar yet (S3: 25 of 43,224 at the first hand-over
        // test, with every angle sum below its limit): untangle them on the planes.
        if (stage.mesh != nullptr && stage.frames != nullptr)
            untangle_on_planes(positions, *stage.mesh, *stage.frames, stage.fixed);
        return true;
    }

    /// When `positions` (on the planes) has an inverted or degenerate tetrahedron: untangles
    /// them in vertex variables (untangle.h), each plane one variable as in the vertex stage, the
    /// outermost ones fixed (and the vertices `fixed` flags, when given), and keeps the result
    /// when it is inversion-free with every angle sum below its limit; otherwise leaves
    /// `positions`. The bad tetrahedra are few and local (the plane projection folds them along
    /// the charts' borders), so the vertices within kLocalRings rings of them are untangled
    /// first, the rest (and so every plane they touch) fixed; the whole mesh only when that
    /// fails. Rest `mesh` and `positions` in the same units (any). Each try costs up to
    /// untangle_iterations steps, and far from planarity (cup: thousands folded after the first
    /// assembly iterations) it fails every time: after a failure with n bad tetrahedra, the next
    /// try waits until fewer than n / 2 are. Returns the number of tetrahedra that were inverted
    /// or degenerate, and sets `*untangled` when it replaced the positions.
    Index untangle_on_planes(Eigen::MatrixXd& positions, const SimplicialMesh& mesh,
                             const RestFrames<3>& frames, const std::vector<unsigned char>* fixed,
                             bool* untangled = nullptr) const {
        if (untangled != nullptr) *untangled = false;
        const MapQuality quality =
            map_quality<3>(linear_parts<3>(mesh, frames, positions), frames.volume);
        const Index bad = quality.inverted + quality.degenerate;
        if (bad == 0 || bad >= retry_below_ || options_.untangle_iterations <= 0) return bad;
        std::vector<unsigned char> held(mesh.num_vertices(), 0);
        if (fixed != nullptr) held = *fixed;
        // The local tries need the prepared mesh's adjacency: the driver's mesh is that mesh.
        if (mesh.num_simplices() == p_.mesh.num_simplices() &&
            mesh.num_vertices() == p_.mesh.num_vertices()) {
            std::vector<Index> seeds;
            for (Index s = 0; s < mesh.num_simplices(); ++s) {
                if (quality.per_simplex[s].inverted || quality.per_simplex[s].degenerate)
                    seeds.push_back(s);
            }
            std::vector<unsigned char> outside(mesh.num_vertices(), 1);
            for (const Index s : grow_rings(mesh, p_.topology, seeds, kLocalRings)) {
                for (int k = 0; k < 4; ++k) outside[mesh.simplices(s, k)] = 0;
            }
            for (std::size_t v = 0; v < outside.size(); ++v) outside[v] |= held[v];
            // A region that frees every vertex the whole mesh frees is the whole-mesh try.
            if (outside != held) {
                const std::string note =
                    untangle_try(positions, mesh, frames, outside, bad,
                                 "in " + std::to_string(kLocalRings) + " rings around them");
                if (note.empty()) {
                    if (untangled != nullptr) *untangled = true;
                    return bad;
                }
            }
        }
        const std::string note =
            untangle_try(positions, mesh, frames, held, bad, "on the whole mesh");
        if (!note.empty()) retry_below_ = bad / 2;
        if (untangled != nullptr) *untangled = note.empty();
        return bad;
    }

    /// One untangle_on_planes() try with the vertices `fixed` flags held; replaces `positions`
    /// and returns "" when the result is inversion-free over the whole mesh with every angle sum
    /// below its limit, why not otherwise. `where` names the region in the log line.
    std::string untangle_try(Eigen::MatrixXd& positions, const SimplicialMesh& mesh,
                             const RestFrames<3>& frames, const std::vector<unsigned char>& fixed,
                             Index bad, const std::string& where) const {
        const double left = options_.max_time - clock_.seconds();
        if (!(left > 0.0)) return "out of time";
        UntangleOptions u;
        // To the untangling energy's convergence, not the first valid iterate: its near-flat
        // tetrahedra would put the conformal barrier beyond what the vertex stage can start from.
        u.until_valid = false;
        u.max_iterations = options_.untangle_iterations;
        u.max_time_seconds = left;
        u.num_threads = options_.threads;
        // The planes move, each as one variable, but the two outermost of each axis: at a large
        // eps the untangling energy is lowest with the map shrunk to a point.
        u.shared_coordinates = shared_coordinates(positions, PluginStage<3>{});
        u.fixed_coordinates.assign(u.shared_coordinates.size(), 0);
        const std::vector<Index> leader = plane_leaders();
        if (planes_held()) {
            for (const Index coordinate : leader) u.fixed_coordinates[coordinate] = 1;
        }
        for (const auto& [low, high] : outer_planes(positions)) {
            if (low < 0) continue;
            u.fixed_coordinates[leader[low]] = u.fixed_coordinates[leader[high]] = 1;
        }
        const PluginStage<3> stage;
        u.accept = [&](const Eigen::MatrixXd& x) { return std::isfinite(energy(x, stage)); };
        const UntangleResult r = untangle<3>(mesh, frames, positions, fixed, u);
        // untangle() checks the tetrahedra with a free vertex only.
        std::string note = r.untangled ? "" : to_string(r.outcome) + ": " + to_string(r.stop);
        if (note.empty()) {
            const MapQuality q =
                map_quality<3>(linear_parts<3>(mesh, frames, r.positions), frames.volume);
            if (q.inverted + q.degenerate > 0) note = "bad tetrahedra with no free vertex";
        }
        if (note.empty() && !std::isfinite(energy(r.positions, stage)))
            note = "an angle sum at its limit";
        log_line(options_.logger,
                 "polycube: " + std::to_string(bad) +
                     " tetrahedra inverted or degenerate on the planes; untangled " + where +
                     " in " + std::to_string(r.iterations) +
                     " steps: " + (note.empty() ? "kept" : "not kept (" + note + ")"));
        if (note.empty()) positions = r.positions;
        return note;
    }

    std::vector<Index> shared_coordinates(const Eigen::MatrixXd& positions,
                                          const PluginStage<3>&) const override {
        std::vector<Index> shared(3 * positions.rows());
        std::iota(shared.begin(), shared.end(), Index(0));
        const std::vector<Index> leader = plane_leaders();
        for (const auto& [v, plane] : members_) shared[3 * v + plane_axis_[plane]] = leader[plane];
        return shared;
    }

    void add_vertex_terms(SimplexAssemblyEngine<3>& engine, const PluginStage<3>&) const override {
        // Sliding: each plane is one variable (shared_coordinates()), so its vertices move in it,
        // a vertex of two planes along their line, a corner with its three, and the planes move
        // too. E_C and the angle sums do not see translations and scalings: one plane per axis
        // is fixed, and a second one on the axis of largest extent. The angle barriers are not
        // needed here: with every chart exactly in its plane, a boundary
        // edge's dihedral sum can only be pi (inside a chart) or pi/2, 3 pi/2 (between two), plus
        // multiples of 2 pi, and a vertex's solid-angle sum likewise a multiple of pi/2; both are
        // continuous while no tetrahedron degenerates, which E_C prevents. So they keep the
        // values of the start, which energy() checked below their limits before the hand-over.
        const Eigen::MatrixXd positions = engine.positions(engine.problem().variables());
        const std::vector<Index> leader = plane_leaders();
        if (planes_held()) {
            for (const Index coordinate : leader)
                engine.problem().set_fixed(engine.coordinate_variable(coordinate));
            return;
        }
        const auto outer = outer_planes(positions);
        int widest = -1;
        double widest_extent = -1.0;
        for (int axis = 0; axis < 3; ++axis) {
            const auto& [low, high] = outer[axis];
            if (low < 0) continue;
            engine.problem().set_fixed(engine.coordinate_variable(leader[low]));
            const double extent =
                positions(leader[high] / 3, axis) - positions(leader[low] / 3, axis);
            if (extent > widest_extent) {
                widest = axis;
                widest_extent = extent;
            }
        }
        if (widest >= 0)
            engine.problem().set_fixed(engine.coordinate_variable(leader[outer[widest].second]));
    }

    double energy(const Eigen::MatrixXd& positions, const PluginStage<3>&) const override {
        double e = 0.0;
        for (const double theta : dihedral_angle_sums(p_.fans, positions)) {
            if (!(theta < 2.0 * M_PI)) return kInfinity;
            e += 1.0 / (2.0 * M_PI - theta);
        }
        for (const double theta : solid_angle_sums(p_.stars, positions)) {
            if (!(theta < 4.0 * M_PI)) return kInfinity;
            e += 1.0 / (4.0 * M_PI - theta);
        }
        return weight_ * e;
    }

    bool removes_rigid_motion() const override { return true; }

  private:
    /// Whether every plane stays at PolycubePluginOptions::plane_coordinates.
    bool planes_held() const { return !options_.plane_coordinates.empty(); }

    /// Where `plane` is held, in `stage`'s coordinates (the driver's are normalized).
    double held_coordinate(int plane, const PluginStage<3>& stage) const {
        const double c = options_.plane_coordinates[plane];
        const int axis = plane_axis_[plane];
        return stage.map_center.size() == 3 ? (c - stage.map_center[axis]) * stage.scale
                                            : c * stage.scale;
    }

    /// Per plane: the coordinate D v + axis of its first vertex, which its other vertices share.
    std::vector<Index> plane_leaders() const {
        std::vector<Index> leader(plane_axis_.size(), -1);
        for (const auto& [v, plane] : members_)
            if (leader[plane] < 0) leader[plane] = 3 * v + plane_axis_[plane];
        return leader;
    }

    /// Per axis, its planes' lowest and highest at `positions` (#V x 3), -1 when it has none.
    std::array<std::pair<int, int>, 3> outer_planes(const Eigen::MatrixXd& positions) const {
        const std::vector<Index> leader = plane_leaders();
        std::array<std::pair<int, int>, 3> out;
        out.fill({-1, -1});
        for (int plane = 0; plane < int(plane_axis_.size()); ++plane) {
            const int axis = plane_axis_[plane];
            auto at = [&](int p) { return positions(leader[p] / 3, axis); };
            auto& [low, high] = out[axis];
            if (low < 0 || at(plane) < at(low)) low = plane;
            if (high < 0 || at(plane) > at(high)) high = plane;
        }
        return out;
    }

    /// Every boundary vertex on its planes at their start offsets, a^T (A_t u + T_t) = c, per
    /// labelled triangle and its tetrahedron t, when every such t has a translation (f-SA; in
    /// r-SA the planes stay free and only the anchored simplex's trace holds the scale).
    /// Planarity alone (on A) is homogeneous in the map's scale, as are the conformal and angle
    /// barriers, so E~_assembly fell by shrinking the map where its residuals were large (the
    /// median simplex scale fell several times while the anchor's stayed near 1;
    /// docs/measurements.md, PolyCube). The paper's 5.3 keeps the planes of the initial map; the
    /// vertex stage moves them again (each plane one variable).
    void add_plane_offsets(SimplexAssemblyEngine<3>& engine, const PluginStage<3>& stage) const {
        if (stage.mesh == nullptr || stage.frames == nullptr) return;
        for (Index b = 0; b < p_.boundary.size(); ++b)
            if (!engine.has_translation(p_.boundary.tet(b))) return;
        // Rows a^T (A_t u_v + T_t) per labelled triangle; each plane's offset is the mean of its
        // rows at the start, and becomes their right-hand side.
        std::vector<LinearConstraint<12, 3>> rows(p_.boundary.size());
        std::vector<double> sum(plane_axis_.size(), 0.0);
        std::vector<Index> count(plane_axis_.size(), 0);
        const Eigen::VectorXd& x = engine.problem().variables();
        for (Index b = 0; b < p_.boundary.size(); ++b) {
            const int axis = label_axis(p_.labels[b]);
            const Index t = p_.boundary.tet(b);
            LinearConstraint<12, 3>& c = rows[b];
            c.variables = engine.affine_variables(t);
            Eigen::Matrix<double, 12, 1> start;
            for (int i = 0; i < 12; ++i) start[i] = x[c.variables[i]];
            for (int k = 0; k < 3; ++k) {
                const Index v = p_.boundary.triangles(b, k);
                int local = 0;
                while (stage.mesh->simplices(t, local) != v) ++local;
                c.rows.coefficients.row(k) =
                    engine.image_coefficients(t, stage.frames->corner(t, local)).row(axis);
                const int plane = plane_of_vertex_[v][axis];
                sum[plane] += c.rows.coefficients.row(k).dot(start);
                ++count[plane];
            }
        }
        for (Index b = 0; b < p_.boundary.size(); ++b) {
            const int axis = label_axis(p_.labels[b]);
            for (int k = 0; k < 3; ++k) {
                const int plane = plane_of_vertex_[p_.boundary.triangles(b, k)][axis];
                rows[b].rows.rhs[k] = planes_held() ? held_coordinate(plane, stage)
                                                    : sum[plane] / double(count[plane]);
            }
        }
        engine.add_linear_constraints<12, 3>(
            planes_held() ? "polycube planes where held" : "polycube planes at their start", rows);
    }

    /// Planes (frontends/polycube/polycube_planes.h), and each boundary vertex's planes.
    void build_planes() {
        const PolycubePlanes planes =
            polycube_planes(p_.boundary, p_.charts, p_.mesh.num_vertices());
        plane_axis_ = planes.axis;
        plane_of_vertex_ = planes.plane_of_vertex;
        for (Index v = 0; v < p_.mesh.num_vertices(); ++v) {
            std::vector<int> mine;
            for (const int plane : planes.plane_of_vertex[v])
                if (plane >= 0) mine.push_back(plane);
            std::sort(mine.begin(), mine.end());
            for (const int plane : mine) members_.push_back({v, plane});
        }
    }

    const PreparedPolycube& p_;
    double weight_;

    PolycubePluginOptions options_;
    Stopwatch clock_;  ///< since the plugin was made: options_.max_time counts from there
    /// Rings of tetrahedra around the bad ones that untangle_on_planes() frees first.
    static constexpr int kLocalRings = 4;
    /// untangle_on_planes() tries only below this many bad tetrahedra (the driver calls it from
    /// one thread: at the start, then once per assembly iteration).
    mutable Index retry_below_ = std::numeric_limits<Index>::max();
    std::vector<int> plane_axis_;                      ///< per plane: its axis
    std::vector<std::pair<Index, int>> members_;       ///< (boundary vertex, one of its planes)
    std::vector<std::array<int, 3>> plane_of_vertex_;  ///< PolycubePlanes::plane_of_vertex
};

}  // namespace

std::shared_ptr<const AssemblyPlugin<3>> polycube_plugin(const PreparedPolycube& prepared,
                                                         double angle_weight,
                                                         const PolycubePluginOptions& options) {
    if (!(angle_weight > 0.0) || !std::isfinite(angle_weight)) {
        throw InvalidArgumentError("polycube: angle_weight = " + std::to_string(angle_weight) +
                                   ": must be a finite number > 0");
    }
    return std::make_shared<const PolycubePlugin>(prepared, angle_weight, options);
}

namespace {

/// Checks `options` against `prepared` before any work (see solve_polycube()).
void check_solve_options(const PreparedPolycube& prepared, const PolycubeSolveOptions& options) {
    if (options.optimal_bound && std::isfinite(options.bound)) {
        throw InvalidArgumentError("polycube: bound = " + std::to_string(options.bound) +
                                   " with the optimal bound: give one or the other");
    }
    if (!(options.bound > 1.0)) {
        throw InvalidArgumentError("polycube: bound = " + std::to_string(options.bound) +
                                   ": must be > 1 or +inf");
    }
    // What the labels force (polycube_angle_bound.h): a bound below it has no solution.
    if (options.bound < prepared.angle_bound.bound) {
        auto number = [](double x, int digits = 6) {
            char text[40];
            std::snprintf(text, sizeof text, "%.*g", digits, x);
            return std::string(text);
        };
        throw NoSolutionError("polycube: bound " + number(options.bound, 10) +
                              ": no valid PolyCube map of these labels has conformal distortion "
                              "below " +
                              number(prepared.angle_bound.bound) + ": " +
                              prepared.angle_bound.worst.front().describe());
    }
}

/// Steps 2 to 4 of polycube_solve.h from out.start (set, with its quality and
/// out.cube_cover_seconds), the planes free or held at `plane_coordinates`.
void solve_from_start(const PreparedPolycube& prepared, const PolycubeSolveOptions& options,
                      const std::vector<double>& plane_coordinates, const RestFrames<3>& frames,
                      PolycubeSolve& out, const Logger& logger) {
    Stopwatch stage;
    PolycubePluginOptions plugin_options;
    plugin_options.max_time = options.max_time - out.cube_cover_seconds;
    plugin_options.threads = options.threads;
    plugin_options.untangle_iterations = options.untangle_iterations;
    plugin_options.logger = logger;
    plugin_options.plane_coordinates = plane_coordinates;
    polycube_plugin(prepared, options.angle_weight, plugin_options);  // checks the options
    const auto plugin =
        std::make_shared<const PolycubePlugin>(prepared, options.angle_weight, plugin_options);

    // A folded start is untangled on its planes first: the driver's disassembly then starts
    // from a valid map, and so does the recovered mesh of its first hand-over test, up to the
    // few tetrahedra that the plane projection folds again.
    MappingProblem problem;
    problem.mesh = prepared.mesh;
    problem.initial = out.start;
    problem.source = "polycube";
    if (!plane_coordinates.empty()) plugin->project(problem.initial, PluginStage<3>{});
    plugin->untangle_on_planes(problem.initial, prepared.mesh, frames, nullptr,
                               &out.start_untangled);
    out.untangle_seconds = stage.lap();
    problem.plugins.push_back(plugin);
    SimplexAssemblyOptions& o = out.options;
    o.distortion = DistortionType::kConformal;
    o.bound = options.bound;
    o.max_time_seconds =
        std::max(options.max_time - out.cube_cover_seconds - out.untangle_seconds, 1e-3);
    o.num_threads = options.threads;
    o.mode = SolveMode::kFull;
    if (!plane_coordinates.empty()) {
        // Planes held where given: a start that is inversion-free on them is already a PolyCube
        // of those planes, and the vertex stage alone (the descent mode) improves it. The
        // assembly would only fold it again: its recovered meshes are projected onto planes
        // that cannot follow it (robustPolycube M1_tet: 1,748 folded tetrahedra after the first
        // iterations, from a start with none).
        const MapQuality q =
            map_quality<3>(linear_parts<3>(prepared.mesh, frames, problem.initial), frames.volume);
        if (q.inverted + q.degenerate == 0) o.mode = SolveMode::kDescent;
    }
    // f-SA: the assembly holds every boundary vertex on its plane at the start's offset
    // (add_plane_offsets), which needs each boundary tetrahedron's translation. Without the
    // offsets the assembly shrank the map (with r-SA the median simplex scale could fall tenfold,
    // the smallest a hundredfold more), so a tiny E~ did not mean planar charts, and runs ended
    // assembled and unverified (docs/measurements.md, PolyCube).
    o.variant = Variant::kFull;
    log_line(logger, "polycube: " + std::to_string(independent_loops(prepared.boundary)) +
                         " independent loops (handles) in the solid; f-SA, the planes held " +
                         (plane_coordinates.empty() ? "at the start's offsets" : "where given"));
    o.untangle_fallback = false;
    o.handover_ratio = options.handover_ratio;
    SimplexAssemblyObserver observer;
    observer.logger = logger;
    if (options.optimal_bound) {
        OptimalBoundOptions schedule;
        schedule.rounds = options.rounds;
        schedule.tolerance = 1e-3;
        // A round counts only when its map is a PolyCube (one cut short by the time limit before
        // the vertex stage is not planar, though the driver finds no inverted tetrahedron).
        schedule.accept = [&prepared](const SimplexAssemblyResult& r) {
            return verify_polycube(prepared.layout(), r.positions, prepared.input_volume).passed;
        };
        OptimalBound rounds = optimal_bound(problem, o, schedule, observer);
        out.solve = std::move(rounds.solve);
        out.rounds = std::move(rounds.rounds);
        out.bound = out.rounds.front().bound;
        for (const BoundRound& r : out.rounds)
            if (r.success) out.bound = r.bound;
    } else {
        out.solve = run_simplex_assembly(problem, o, observer);
        out.bound = o.bound;
    }
    out.positions = out.solve.positions;
    out.solve_seconds = stage.lap();
    out.verification = verify_polycube(prepared.layout(), out.positions, prepared.input_volume);
    out.verify_seconds = stage.lap();
    out.success = out.solve.success && out.verification.passed;
    std::ostringstream message;
    message << (out.success ? "success: " : "FAILED: ") << "PolyCube "
            << (out.verification.passed ? "verified" : "NOT verified") << " from the output ("
            << out.verification.quality.inverted << " inverted, "
            << out.verification.quality.degenerate << " degenerate, largest chart spread "
            << out.verification.max_planarity << " of the diagonal, "
            << out.verification.zero_length_edges << " zero-length PolyCube edges, "
            << out.verification.edge_angle_violations + out.verification.vertex_angle_violations
            << " angle sums at their limit); conformal distortion max "
            << out.verification.quality.conformal.max << ", mean "
            << out.verification.quality.conformal.mean;
    if (!out.rounds.empty()) message << "; " << out.rounds.size() << " optimal-bound rounds";
    message << ". " << out.solve.message;
    out.message = message.str();
}

}  // namespace

PolycubeSolve solve_polycube(const PreparedPolycube& prepared, const PolycubeSolveOptions& options,
                             const Logger& logger) {
    check_solve_options(prepared, options);
    PolycubeSolve out;
    Stopwatch stage;
    const CubeCover cover = cube_cover_map(prepared.mesh, prepared.boundary, prepared.charts);
    out.start = cover.positions;
    const RestFrames<3> frames = rest_frames<3>(prepared.mesh);
    out.start_quality =
        map_quality<3>(linear_parts<3>(prepared.mesh, frames, out.start), frames.volume);
    out.cube_cover_seconds = stage.lap();
    log_line(logger, "cube-cover start: " + std::to_string(out.start_quality.inverted) +
                         " inverted and " + std::to_string(out.start_quality.degenerate) +
                         " degenerate of " + std::to_string(prepared.mesh.num_simplices()) +
                         " tetrahedra; of its " + std::to_string(cover.edge_orders) +
                         " PolyCube edges, " + std::to_string(cover.lengthened_edges) +
                         " kept in rest order by tying their corners' planes, " +
                         std::to_string(cover.unordered_edges) + " still out of order, " +
                         std::to_string(cover.collapsed_edges) + " with both corners on one plane");

    solve_from_start(prepared, options, {}, frames, out, logger);
    return out;
}

PolycubeSolve solve_polycube_on_planes(const PreparedPolycube& prepared,
                                       const Eigen::MatrixXd& start,
                                       const std::vector<double>& plane_coordinates,
                                       const PolycubeSolveOptions& options, const Logger& logger) {
    check_solve_options(prepared, options);
    if (options.optimal_bound) {
        throw InvalidArgumentError("polycube: the optimal bound is not taken on held planes");
    }
    if (start.rows() != prepared.mesh.num_vertices() || start.cols() != 3 || !start.allFinite()) {
        throw InvalidArgumentError(
            "polycube: the start must be #V x 3 = " + std::to_string(prepared.mesh.num_vertices()) +
            " x 3 finite positions");
    }
    if (plane_coordinates.empty())
        throw InvalidArgumentError("polycube: no plane coordinates to hold the planes at");
    PolycubeSolve out;
    out.start = start;
    const RestFrames<3> frames = rest_frames<3>(prepared.mesh);
    out.start_quality =
        map_quality<3>(linear_parts<3>(prepared.mesh, frames, start), frames.volume);
    solve_from_start(prepared, options, plane_coordinates, frames, out, logger);
    return out;
}

}  // namespace sa
