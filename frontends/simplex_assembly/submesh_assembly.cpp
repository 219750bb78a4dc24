#include "frontends/simplex_assembly/detail/submesh_assembly.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstdio>
#include <set>
#include <unordered_map>

#include "energies/distortion.h"
#include "frontends/simplex_assembly/detail/forced_distortion.h"
#include "frontends/simplex_assembly/detail/submesh_start.h"
#include "frontends/simplex_assembly/detail/vertex_stage.h"
#include "geometry/mesh/submesh.h"
#include "geometry/quality/handle_feasibility.h"
#include "geometry/quality/map_quality.h"
#include "optim/parallel.h"
#include "optim/stopwatch.h"

namespace sa {

namespace {

/// bad_simplices() of `positions` (original units).
template <int D>
std::vector<Index> bad_simplices_at(const PreparedProblem<D>& p, const Eigen::MatrixXd& positions,
                                    bool beyond_cap_allowed) {
    return bad_simplices<D>(
        p, linear_parts<D>(p.mesh, p.frames, (positions.rowwise() - p.map_center) * p.scale),
        beyond_cap_allowed);
}

/// Every boundary vertex of the mesh is a handle (and there is one): the Locally Injective
/// Mappings benchmark's class, where the interior is to be untangled inside a fixed boundary.
template <int D>
bool boundary_fixed(const PreparedProblem<D>& p) {
    std::vector<unsigned char> handle(p.mesh.num_vertices(), 0);
    for (Index h : p.input->handles) handle[h] = 1;
    bool any = false;
    for (Index v = 0; v < p.mesh.num_vertices(); ++v) {
        if (!p.topology.used_vertex[v] || !p.topology.boundary_vertex[v]) continue;
        if (!handle[v]) return false;
        any = true;
    }
    return any;
}

struct Region {
    std::vector<Index> simplices;
    int rings = 0;
};

/// Solves one region on `positions` (original units) in `mode`; returns the local result. The
/// region gets the problem's own energies restricted to its simplices and its constraints on the
/// region's edges (the others have both ends fixed, outside the region or on its boundary).
template <int D>
SimplexAssemblyResult solve_region(const MappingProblem& input, const MeshTopology& topology,
                                   const Eigen::MatrixXd& positions,
                                   const std::vector<unsigned char>& is_handle,
                                   const Region& region, SolveMode mode,
                                   const SimplexAssemblyOptions& options, int threads,
                                   const Logger& logger, Submesh& sub) {
    sub = extract_submesh(input.mesh, topology, region.simplices);
    MappingProblem local;
    local.source =
        input.source + " (submesh of " + std::to_string(region.simplices.size()) + " simplices)";
    local.mesh = sub.mesh;
    local.initial.resize(sub.vertices.size(), positions.cols());
    for (std::size_t i = 0; i < sub.vertices.size(); ++i) {
        local.initial.row(i) = positions.row(sub.vertices[i]);
        if (sub.on_region_boundary[i] || is_handle[sub.vertices[i]])
            local.handles.push_back(static_cast<Index>(i));
    }
    for (const auto& energy : input.energies)
        local.energies.push_back(
            static_cast<const SimplexTerm<D>&>(*energy).restricted(sub.simplices));
    if (!input.constraints.empty()) {
        std::unordered_map<Index, Index> local_vertex;
        for (std::size_t i = 0; i < sub.vertices.size(); ++i)
            local_vertex.emplace(sub.vertices[i], static_cast<Index>(i));
        std::set<std::pair<Index, Index>> edges;
        for (Index s = 0; s < sub.mesh.num_simplices(); ++s) {
            for (int i = 0; i <= D; ++i) {
                for (int j = i + 1; j <= D; ++j) {
                    const Index a = sub.mesh.simplices(s, i), b = sub.mesh.simplices(s, j);
                    edges.emplace(std::min(a, b), std::max(a, b));
                }
            }
        }
        for (const EdgeConstraint& c : input.constraints) {
            const auto a = local_vertex.find(c.a), b = local_vertex.find(c.b);
            if (a == local_vertex.end() || b == local_vertex.end()) continue;
            if (!edges.count({std::min(a->second, b->second), std::max(a->second, b->second)}))
                continue;
            local.constraints.push_back({a->second, b->second, c.normal, c.value});
        }
    }
    SimplexAssemblyOptions o = options;
    o.mode = mode;
    o.num_threads = threads;
    SimplexAssemblyObserver observer;
    if (logger) observer.logger = [&logger](const std::string& line) { logger("    " + line); };
    try {
        return run_simplex_assembly(local, o, observer);
    } catch (const InfeasibleProblemError& e) {
        // The region's fixed outer vertices already force a bad simplex: it must grow.
        SimplexAssemblyResult failed;
        failed.message = e.what();
        return failed;
    }
}

}  // namespace

template <int D>
SolveMode choose_mode(const PreparedProblem<D>& p, const SimplexAssemblyOptions& options) {
    if (!p.input->plugins.empty()) {
        // A plugin's terms cannot be restricted to a region yet (assembly_plugin.h). The descent
        // is the vertex stage alone, which projects its start onto the plugin's constraints
        // (vertex_stage.h) as it does a hand-over.
        if (options.mode == SolveMode::kSubmesh) {
            throw InvalidArgumentError("plugin '" + p.input->plugins.front()->name() +
                                       "': problems with plugins run in the full or the descent "
                                       "mode (mode full, descent or auto)");
        }
        return options.mode == SolveMode::kDescent ? SolveMode::kDescent : SolveMode::kFull;
    }
    if (options.mode == SolveMode::kDescent) return SolveMode::kDescent;
    if (p.input->boundary_injective) {
        if (options.mode == SolveMode::kSubmesh) {
            throw InvalidArgumentError(
                "the boundary-angle barrier runs in the full mode only (--mode full or auto)");
        }
        return SolveMode::kFull;
    }
    if (options.mode != SolveMode::kAuto) return options.mode;
    // Handles that force the barrier beyond what lambda_max can balance (forced_distortion.h):
    // the full solve cannot assemble, the submesh mode's start untangles in vertex variables.
    if (!barrier_forced_simplices<D>(p, options).empty()) return SolveMode::kSubmesh;
    const Index n = p.mesh.num_simplices();
    if (n <= (D == 2 ? options.auto_full_triangles : options.auto_full_tetrahedra))
        return SolveMode::kFull;
    const double bad =
        double(p.initial_quality.inverted + p.initial_quality.degenerate) / double(n);
    if (bad <= options.auto_bad_share) return SolveMode::kSubmesh;
    // A fixed boundary around a widespread tangle: the submesh start untangles it in vertex
    // variables (untangle.h) in a few Newton steps on #V x D unknowns, where the full solve's
    // (D + 1) D per simplex couple through the assembly (a 30k-tet hand with 28% of its tets
    // inverted found no map in the full solve; docs/measurements.md, "The fixed-boundary hard
    // class").
    return boundary_fixed(p) ? SolveMode::kSubmesh : SolveMode::kFull;
}

template <int D>
void solve_submeshes(PreparedProblem<D>& p, const SimplexAssemblyOptions& options,
                     const TimeBudget& budget, const SimplexAssemblyObserver& observer,
                     SimplexAssemblyResult& result) {
    Stopwatch stage;
    SubmeshStats& stats = result.submesh;
    const MappingProblem& input = *p.input;
    const int threads = options.num_threads > 0 ? options.num_threads : default_thread_count();
    tbb::task_arena arena(threads);

    SubmeshStart start = submesh_start<D>(p, options, budget, observer.logger);
    Eigen::MatrixXd positions = std::move(start.positions);
    std::vector<Index> bad = std::move(start.bad);
    stats.start = start.choice;
    stats.start_iterations = start.iterations;
    stats.start_rejected = start.rejected;
    if (start.untangle) {
        StageRecord& r = result.stages.add(Stage::kStartUntangle, *start.untangle);
        r.newton_steps = start.untangle_iterations;
        r.seconds = start.untangle_seconds;
        if (*start.untangle == UntangleOutcome::kNotUntangled)
            r.figures = to_string(start.untangle_stop);
    }
    stats.start_bad = static_cast<Index>(bad.size());
    Index near_bound = 0;
    if (options.submesh_band > 0.0) {
        // The first round also solves around the simplices near their bound (the optimal-bound
        // rounds): with the bound as it is, the barrier lowers the largest distortion there.
        std::vector<unsigned char> marked(p.mesh.num_simplices(), 0);
        for (Index s : bad) marked[s] = 1;
        const std::vector<Mat<D>> A =
            linear_parts<D>(p.mesh, p.frames, (positions.rowwise() - p.map_center) * p.scale);
        for (const auto& energy : p.assembly.energies)
            energy->mark_near_bound(A, options.submesh_band, marked);
        bad.clear();
        for (Index s = 0; s < p.mesh.num_simplices(); ++s) {
            if (marked[s]) bad.push_back(s);
        }
        near_bound = Index(bad.size()) - stats.start_bad;
        stats.start_near_bound = near_bound;
    }
    stats.start_time = stage.lap();
    // A start without a bad simplex (a verified map within its bounds: the optimal bound's rounds)
    // has nothing to untangle: its regions, around the simplices near their bound, are solved in
    // vertex variables (the descent mode), where the barrier lowers the largest distortions and
    // keeps every region valid and within its bounds. Regions with bad simplices need the full
    // solve's disassembly.
    const SolveMode region_mode = stats.start_bad == 0 ? SolveMode::kDescent : SolveMode::kFull;
    std::vector<unsigned char> is_handle(input.mesh.num_vertices(), 0);
    for (Index h : input.handles) is_handle[h] = 1;
    // Vertices the solve moved: every one when the start came from Eq. 6, then those of the
    // solved regions.
    std::vector<unsigned char> repaired(input.mesh.num_vertices(), start.recovered ? 1 : 0);
    char line[320];
    std::snprintf(line, sizeof line,
                  "submesh mode: start from the %s, %ld bad simplices and %ld near the bound of "
                  "%ld (%d local/global iterations, %.2f s)",
                  stats.start.describe().c_str(), long(stats.start_bad), long(near_bound),
                  long(p.mesh.num_simplices()), stats.start_iterations, stats.start_time);
    log_line(observer.logger, line);

    for (int round = 0; !bad.empty() && round <= options.max_rounds && !stats.out_of_time;
         ++round) {
        Stopwatch round_watch;  // lapped into the stage times below
        const Stopwatch round_total;
        SubmeshRound record;
        record.round = round;
        record.bad_simplices = static_cast<Index>(bad.size());
        std::vector<Region> pending;
        for (auto& simplices : vertex_connected_regions(
                 input.mesh, p.topology,
                 fill_enclosed(p.topology,
                               grow_rings(input.mesh, p.topology, bad, options.rings)))) {
            pending.push_back({std::move(simplices), options.rings});
        }
        record.regions = static_cast<Index>(pending.size());
        stats.region_time += round_watch.lap();
        while (!pending.empty()) {
            // Regions conflict when they share a vertex.
            std::vector<std::vector<Index>> owners(input.mesh.num_vertices());
            for (std::size_t r = 0; r < pending.size(); ++r) {
                for (Index s : pending[r].simplices) {
                    for (int k = 0; k <= D; ++k) {
                        auto& list = owners[input.mesh.simplices(s, k)];
                        if (list.empty() || list.back() != Index(r)) list.push_back(Index(r));
                    }
                }
            }
            std::vector<std::vector<Index>> conflicts(pending.size());
            for (const auto& list : owners) {
                for (std::size_t a = 0; a < list.size(); ++a)
                    for (std::size_t b = 0; b < list.size(); ++b)
                        if (a != b) conflicts[list[a]].push_back(list[b]);
            }
            for (auto& c : conflicts) {
                std::sort(c.begin(), c.end());
                c.erase(std::unique(c.begin(), c.end()), c.end());
            }
            const std::vector<int> color = greedy_coloring(conflicts);
            const int colors =
                pending.empty() ? 0 : *std::max_element(color.begin(), color.end()) + 1;
            record.colors = std::max(record.colors, colors);
            stats.region_time += round_watch.lap();
            std::vector<Region> retry;
            for (int c = 0; c < colors; ++c) {
                if (budget.exhausted()) {
                    stats.out_of_time = true;
                    log_line(observer.logger, "  time limit reached: no further region is solved");
                    break;
                }
                std::vector<Index> members;
                for (std::size_t r = 0; r < pending.size(); ++r) {
                    if (color[r] == c) members.push_back(Index(r));
                }
                std::string sizes;
                for (Index m : members) {
                    sizes += (sizes.empty() ? "" : ", ") +
                             std::to_string(pending[m].simplices.size()) + " (" +
                             std::to_string(pending[m].rings) + " rings)";
                }
                log_line(observer.logger, "  solving " + std::to_string(members.size()) +
                                              " region" + (members.size() == 1 ? "" : "s") +
                                              " of " + sizes.substr(0, 200) + " simplices");
                std::vector<SimplexAssemblyResult> solved(members.size());
                std::vector<Submesh> subs(members.size());
                const int inner = members.size() == 1 ? threads : 1;
                arena.execute([&] {
                    tbb::parallel_for(std::size_t(0), members.size(), [&](std::size_t i) {
                        solved[i] = solve_region<D>(
                            input, p.topology, positions, is_handle, pending[members[i]],
                            region_mode, with_time_left(options, budget), inner,
                            members.size() == 1 ? observer.logger : Logger{}, subs[i]);
                    });
                });
                for (std::size_t i = 0; i < members.size(); ++i) {
                    const Region& region = pending[members[i]];
                    const SimplexAssemblyResult& r = solved[i];
                    ++stats.solves;
                    stats.iterations += r.newton.num_steps() + r.vertex_stage.num_steps();
                    stats.largest_submesh =
                        std::max(stats.largest_submesh, Index(region.simplices.size()));
                    stats.max_rings = std::max(stats.max_rings, region.rings);
                    const bool ok = r.success && r.verification.within_bound();
                    if (ok) {
                        ++record.solved;
                        for (Index v : subs[i].vertices) repaired[v] = 1;
                        for (std::size_t v = 0; v < subs[i].vertices.size(); ++v) {
                            if (!subs[i].on_region_boundary[v] && !is_handle[subs[i].vertices[v]]) {
                                positions.row(subs[i].vertices[v]) = r.positions.row(v);
                            }
                        }
                    } else {
                        std::snprintf(line, sizeof line,
                                      "  region of %ld simplices (%d rings) not repaired: %s",
                                      long(region.simplices.size()), region.rings,
                                      r.message.substr(0, 120).c_str());
                        log_line(observer.logger, line);
                    }
                    if (ok) continue;
                    // Two more rings, unless they add nothing (the region is its whole component):
                    // the same region from the same start would fail the same way.
                    std::vector<Index> grown =
                        region.rings + 2 <= options.max_rings
                            ? fill_enclosed(p.topology,
                                            grow_rings(input.mesh, p.topology, region.simplices, 2))
                            : std::vector<Index>{};
                    if (grown.size() > region.simplices.size()) {
                        retry.push_back({std::move(grown), region.rings + 2});
                    } else {
                        ++record.failed;
                    }
                }
            }
            stats.solve_time += round_watch.lap();
            if (stats.out_of_time) break;
            pending.swap(retry);
        }
        bad = bad_simplices_at<D>(p, positions, start.untangled);
        record.remaining = static_cast<Index>(bad.size());
        stats.region_time += round_watch.lap();
        record.time = round_total.seconds();
        std::snprintf(line, sizeof line,
                      "round %d: %ld bad simplices, %ld regions (%d colours), %ld solved, %ld "
                      "given up; %ld bad left",
                      round, long(record.bad_simplices), long(record.regions), record.colors,
                      long(record.solved), long(record.failed), long(record.remaining));
        log_line(observer.logger, line);
        stats.rounds.push_back(record);
        // Nothing repaired, nothing moved: another round would solve the same regions again.
        if (record.solved == 0) break;
    }
    result.assembled = bad.empty();
    // The repaired mesh is valid: finish with the vertex stage on the vertices the start and the
    // regions moved (region boundaries included; the rest of the mesh stays as it was, as in
    // section 4.4). It lowers the distortion there and never leaves the valid set.
    const bool any_repaired = std::find(repaired.begin(), repaired.end(), 1) != repaired.end();
    if (options.vertex_stage && !options.until_valid && bad.empty() && !any_repaired) {
        result.stages.add(Stage::kVertexStage, VertexStageOutcome::kSkippedNothingMoved);
    } else if (options.vertex_stage && !options.until_valid && bad.empty() && budget.exhausted()) {
        result.stages.add(Stage::kVertexStage, VertexStageOutcome::kSkippedTimeLimit);
    } else if (options.vertex_stage && !options.until_valid && bad.empty()) {
        Stopwatch vertex_watch;
        std::vector<unsigned char> fixed(p.mesh.num_vertices(), 0);
        for (Index v = 0; v < p.mesh.num_vertices(); ++v) fixed[v] = !repaired[v] || is_handle[v];
        for (Index s : p.assembly.anchored_simplices) {
            for (int k = 0; k <= D; ++k) fixed[p.mesh.simplices(s, k)] = 1;
        }
        // On the simplices with a free vertex only, as a mesh of their own: the same energy up
        // to the constant of the others, set up in proportion to what the regions moved.
        std::vector<Index> moving;
        for (Index s = 0; s < p.mesh.num_simplices(); ++s) {
            bool moves = false;
            for (int k = 0; k <= D; ++k) moves |= !fixed[p.mesh.simplices(s, k)];
            if (moves) moving.push_back(s);
        }
        const Submesh sub = extract_submesh(p.mesh, p.topology, moving);
        const Index nv = static_cast<Index>(sub.vertices.size());
        RestFrames<D> frames;
        for (Index s : sub.simplices) {
            frames.corners.push_back(p.frames.corners[s]);
            frames.edge_inverse.push_back(p.frames.edge_inverse[s]);
            frames.volume.push_back(p.frames.volume[s]);
            if (!p.frames.axes.empty()) frames.axes.push_back(p.frames.axes[s]);
        }
        std::vector<std::shared_ptr<const SimplexTerm<D>>> energies;
        for (const auto& energy : p.assembly.energies)
            energies.push_back(energy->restricted(sub.simplices));
        std::vector<Index> local(p.mesh.num_vertices(), -1);
        std::vector<unsigned char> local_fixed(nv, 0);
        Eigen::MatrixXd start(nv, D);
        for (Index i = 0; i < nv; ++i) {
            const Index v = sub.vertices[i];
            local[v] = i;
            local_fixed[i] = fixed[v];
            start.row(i) = (positions.row(v) - p.map_center) * p.scale;
        }
        std::vector<EdgeRow<D>> constraints;
        for (EdgeRow<D> c : p.assembly.constraints) {
            // An edge with a free end lies in the submesh; one with both ends fixed is constant.
            if (local[c.a] < 0 || local[c.b] < 0 || (fixed[c.a] && fixed[c.b])) continue;
            c.a = local[c.a];
            c.b = local[c.b];
            const auto it = std::lower_bound(sub.simplices.begin(), sub.simplices.end(), c.simplex);
            c.simplex = it != sub.simplices.end() && *it == c.simplex
                            ? Index(it - sub.simplices.begin())
                            : Index(-1);
            constraints.push_back(c);
        }
        VertexStage vertex = run_vertex_stage<D>(
            sub.mesh, frames, mesh_topology(sub.mesh, p.input->source), energies, start,
            local_fixed, with_time_left(options, budget), observer.logger,
            VertexStageTerms<D>{
                {}, constraints, {}, {}, exponent_continuation<D>(p, sub.simplices)});
        result.vertex_stage = vertex.newton;
        // The fixed vertices keep their positions exactly (no round trip through normalization).
        const Eigen::MatrixXd moved = p.to_original(vertex.positions);
        for (Index i = 0; i < nv; ++i)
            if (!local_fixed[i]) positions.row(sub.vertices[i]) = moved.row(i);
        const double seconds = vertex_watch.seconds();
        result.times.vertex_stage += seconds;
        record_vertex_stage(result.stages, vertex, seconds);
    }
    result.positions = positions;
}

template SolveMode choose_mode<2>(const PreparedProblem<2>&, const SimplexAssemblyOptions&);
template SolveMode choose_mode<3>(const PreparedProblem<3>&, const SimplexAssemblyOptions&);
template void solve_submeshes<2>(PreparedProblem<2>&, const SimplexAssemblyOptions&,
                                 const TimeBudget&, const SimplexAssemblyObserver&,
                                 SimplexAssemblyResult&);
template void solve_submeshes<3>(PreparedProblem<3>&, const SimplexAssemblyOptions&,
                                 const TimeBudget&, const SimplexAssemblyObserver&,
                                 SimplexAssemblyResult&);

}  // namespace sa
