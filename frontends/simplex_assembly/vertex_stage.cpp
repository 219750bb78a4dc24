#include "frontends/simplex_assembly/detail/vertex_stage.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "energies/boundary_angle_energy.h"
#include "frontends/simplex_assembly/engine.h"
#include "geometry/quality/local_injectivity.h"
#include "geometry/quality/map_quality.h"
#include "optim/time_budget.h"

namespace sa {

namespace {

/// One run of the engine on `energies` from `start`.
template <int D>
VertexStage run_once(const SimplicialMesh& mesh, const RestFrames<D>& frames,
                     const MeshTopology& topology,
                     const std::vector<std::shared_ptr<const SimplexTerm<D>>>& energies,
                     const Eigen::MatrixXd& start, const std::vector<unsigned char>& fixed,
                     const SimplexAssemblyOptions& options, const Logger& logger,
                     const VertexStageTerms<D>& terms) {
    VertexStage result;
    result.positions = start;
    const Index nv = mesh.num_vertices();
    PluginStage<D> stage = terms.plugin_stage;
    stage.kind = PluginStage<D>::Kind::kVertex;
    stage.fixed = &fixed;
    for (const auto& plugin : terms.plugins) {
        // The plugin's constraint set first (PolyCube: every chart on its plane).
        if (!plugin->project(result.positions, stage)) {
            result.positions = start;
            result.outcome = VertexStageOutcome::kSkippedPluginCannotProject;
            result.figures = plugin->name() + " cannot project the start";
            return result;
        }
    }
    // A wrap is a fold the barrier keeps: no motion that keeps every simplex positive unwraps it
    // (local_injectivity.h). Starting from one would only polish a map that cannot verify.
    const Index wrapped = static_cast<Index>(
        wrapped_simplices<D>(mesh, topology, frames,
                             linear_parts<D>(mesh, frames, result.positions.leftCols(D)))
            .size());
    if (wrapped > 0) {
        result.positions = start;
        result.outcome = VertexStageOutcome::kSkippedWrappedStart;
        result.figures = std::to_string(wrapped) + " simplices around wrapped edges or vertices";
        return result;
    }
    std::vector<std::array<Index, D + 1>> simplices(mesh.num_simplices());
    for (Index s = 0; s < mesh.num_simplices(); ++s)
        for (int k = 0; k <= D; ++k) simplices[s][k] = mesh.simplices(s, k);
    std::vector<Index> shared;
    for (const auto& plugin : terms.plugins) {
        std::vector<Index> mine = plugin->shared_coordinates(result.positions, stage);
        if (mine.empty()) continue;
        if (!shared.empty()) {
            throw InvalidArgumentError("vertex stage: two plugins share coordinates (" +
                                       plugin->name() + " is the second)");
        }
        shared = std::move(mine);
    }
    SimplexAssemblyEngine<D> engine = SimplexAssemblyEngine<D>::vertex_positions(
        result.positions.leftCols(D), std::move(simplices), frames.corners, frames.edge_inverse,
        std::move(shared));
    // Simplices whose vertices are all fixed keep a constant energy: they are left out.
    std::vector<Index> moving;
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        bool moves = false;
        for (int k = 0; k <= D; ++k) moves |= !fixed[mesh.simplices(s, k)];
        if (moves) moving.push_back(s);
    }
    for (const auto& energy : energies) energy->add_to(engine, moving);
    if constexpr (D == 2) {
        // E_theta on the positions of each boundary vertex and its fan neighbours.
        RaggedElements angle_elements;
        for (const BoundaryFan& fan : terms.fans) {
            std::vector<Index> e;
            const auto center = engine.vertex_variables(fan.vertex);
            e.insert(e.end(), center.begin(), center.end());
            for (const Index neighbour : fan.neighbours) {
                const auto p = engine.vertex_variables(neighbour);
                e.insert(e.end(), p.begin(), p.end());
            }
            angle_elements.push_back(e);
        }
        if (!angle_elements.empty()) {
            engine.add_barrier("boundary angle", BoundaryAngleVertexEnergy{},
                               std::move(angle_elements));
        }
    }
    if (!terms.constraints.empty()) {
        // n . (x_b - x_a) = value on the two vertices' positions.
        std::vector<LinearConstraint<2 * D, 1>> rows;
        rows.reserve(terms.constraints.size());
        for (const EdgeRow<D>& c : terms.constraints) {
            LinearConstraint<2 * D, 1> row;
            const auto a = engine.vertex_variables(c.a), b = engine.vertex_variables(c.b);
            std::copy(a.begin(), a.end(), row.variables.begin());
            std::copy(b.begin(), b.end(), row.variables.begin() + D);
            row.rows.coefficients << -c.normal.transpose(), c.normal.transpose();
            row.rows.rhs[0] = c.value;
            rows.push_back(row);
        }
        engine.template add_linear_constraints<2 * D, 1>("edge constraints", rows);
    }
    for (const auto& plugin : terms.plugins) plugin->add_vertex_terms(engine, stage);
    for (Index v = 0; v < nv; ++v)
        if (fixed[v]) engine.fix_vertex(v);
    if (!std::isfinite(engine.problem().value())) {
        result.positions = start;
        result.outcome = VertexStageOutcome::kSkippedInfeasibleStart;
        return result;
    }
    // A simplex whose e^{s d} is beyond the barrier's exponent cap (barrier.h; e^500) makes every
    // other simplex's energy vanish below the sum's rounding: Newton cannot lower the distortion
    // elsewhere, and on tlc/armadillo-598, where the fixed boundary forces such simplices, its
    // factorizations failed at every tau. The start is kept.
    Index beyond_cap = 0;
    for (Index s : moving) {
        Eigen::Matrix<double, D, D + 1> corners;
        for (int k = 0; k <= D; ++k)
            corners.col(k) = result.positions.row(mesh.simplices(s, k)).transpose();
        const Mat<D> A = linear_part<D>(frames, s, corners);
        for (const auto& energy : energies) {
            if (energy->beyond_exponent_cap(A)) {
                ++beyond_cap;
                break;
            }
        }
    }
    if (beyond_cap > 0) {
        result.outcome = VertexStageOutcome::kSkippedBeyondExponentCap;
        result.figures = std::to_string(beyond_cap) + " simplices beyond the exponent cap";
        result.positions = start;
        return result;
    }
    AssemblyRun run = engine.run(options, {.logger = logger, .after_iteration = {}});
    result.newton = std::move(run.newton);
    char line[160];
    std::snprintf(line, sizeof line, "vertex stage: %s after %d steps, %.2f s (",
                  to_string(run.stop).c_str(), result.newton.num_steps(),
                  result.newton.times.total);
    log_line(logger, line + result.newton.phase_times() + ")");
    result.stop = run.stop;
    result.outcome = VertexStageOutcome::kRan;
    result.positions.leftCols(D) = engine.positions(engine.problem().variables());
    return result;
}

}  // namespace

template <int D>
ExponentContinuation<D> exponent_continuation(const PreparedProblem<D>& prepared,
                                              const std::vector<Index>& simplices,
                                              std::optional<double> bound) {
    ExponentContinuation<D> c;
    if (prepared.energy == nullptr) return c;
    const std::shared_ptr<const SimplexEnergy<D>> energy = prepared.energy;
    c.s = energy->options().barrier.s;
    // The problem's own energies follow the built-in one (set_energies); its exponential barriers
    // (a deformation's volumetric bound) are continued with E_C, at the same share of their own
    // exponent, and measured in E_C's units: an untangled map whose squashed simplices sit far up
    // such a barrier spans as many orders of magnitude as one far up E_C.
    std::vector<std::shared_ptr<const SimplexTerm<D>>> own, barriers;
    for (std::size_t k = 1; k < prepared.assembly.energies.size(); ++k) {
        own.push_back(prepared.assembly.energies[k]);
        if (own.back()->exponent() > 0.0) barriers.push_back(own.back());
    }
    c.distortion = [energy, barriers, s = c.s](const Mat<D>& A) {
        double d = energy->barrier_distortion(A);
        for (const auto& barrier : barriers)
            d = std::max(d, barrier->exponent() / s * barrier->distortion(A));
        return d;
    };
    const PreparedProblem<D>* p = &prepared;
    c.energies = [p, energy, own, simplices, bound, s0 = c.s](double s) {
        SimplexEnergyOptions o = energy->options();
        o.barrier.s = s;
        if (bound) o.barrier.bound = *bound;
        const bool difference = o.mapping_distortion == DistortionType::kDifference;
        std::vector<std::shared_ptr<const SimplexTerm<D>>> terms;
        terms.push_back(std::make_shared<SimplexTermOf<D, SimplexEnergy<D>>>(
            "simplex energy",
            std::make_shared<const SimplexEnergy<D>>(
                o, p->frames.volume,
                difference ? p->assembly.reference_linear : std::vector<Mat<D>>{})));
        for (const auto& term : own)
            terms.push_back(term->exponent() > 0.0 ? term->with_exponent(term->exponent() * s / s0)
                                                   : term);
        if (!simplices.empty())
            for (auto& term : terms) term = term->restricted(simplices);
        return terms;
    };
    return c;
}

template <int D>
VertexStage run_vertex_stage(const SimplicialMesh& mesh, const RestFrames<D>& frames,
                             const MeshTopology& topology,
                             const std::vector<std::shared_ptr<const SimplexTerm<D>>>& energies,
                             const Eigen::MatrixXd& start, const std::vector<unsigned char>& fixed,
                             const SimplexAssemblyOptions& options, const Logger& logger,
                             const VertexStageTerms<D>& terms) {
    const ExponentContinuation<D>& c = terms.exponent;
    // The smallest and largest barrier distortion of a simplex with a free vertex (the others
    // are constant): the per-simplex Hessians span about e^{s (largest - smallest)}.
    std::vector<Index> moving;
    for (Index s = 0; s < mesh.num_simplices(); ++s) {
        bool moves = false;
        for (int k = 0; k <= D; ++k) moves |= !fixed[mesh.simplices(s, k)];
        if (moves) moving.push_back(s);
    }
    struct Range {
        double smallest = kInfinity, largest = 0.0;
        double spread() const { return largest - smallest; }
    };
    // E_C's distortion of simplex s in the positions x (#V x D or more columns).
    auto distortion = [&](const Eigen::MatrixXd& x, Index s) {
        Eigen::Matrix<double, D, D + 1> corners;
        for (int k = 0; k <= D; ++k)
            corners.col(k) = x.row(mesh.simplices(s, k)).leftCols(D).transpose();
        return c.distortion(linear_part<D>(frames, s, corners));
    };
    auto distortion_range = [&](const Eigen::MatrixXd& x) {
        Range r;
        if (!c.distortion) return r;
        for (Index s : moving) {
            const double d = distortion(x, s);
            r.smallest = std::min(r.smallest, d);
            r.largest = std::max(r.largest, d);
        }
        return r;
    };
    auto degenerate = [&](const Eigen::MatrixXd& x) {
        return count_degenerate<D>(linear_parts<D>(mesh, frames, x.leftCols(D)), frames.volume);
    };
    // One run of Newton from x, undone when it leaves degenerate simplices where x had none.
    auto run = [&](const std::vector<std::shared_ptr<const SimplexTerm<D>>>& at, double s,
                   const Eigen::MatrixXd& x, const SimplexAssemblyOptions& o) {
        VertexStage v = run_once<D>(mesh, frames, topology, at, x, fixed, o, logger, terms);
        ContinuationRound round;
        round.s = s;
        round.bound = o.bound;
        round.max_distortion_before = distortion_range(x).largest;
        round.outcome = v.outcome;
        if (v.ran()) {
            round.iterations = v.newton.num_steps();
            round.termination = v.newton.termination;
            const Index after = degenerate(x) == 0 ? degenerate(v.positions) : 0;
            if (after > 0) {
                v.positions = x;
                v.outcome = round.outcome = VertexStageOutcome::kRanUndone;
                round.undone_degenerate = after;
                log_line(logger, "vertex stage: undone: it left " + std::to_string(after) +
                                     " degenerate simplices, its start none");
            }
        }
        round.max_distortion_after = distortion_range(v.positions).largest;
        v.rounds.push_back(round);
        return v;
    };
    Range d = distortion_range(start);
    // Within the range a factorization handles: one run. So too when the start is not valid, or
    // when a simplex beyond the barrier's exponent cap at s has a fixed vertex (run_once skips
    // the stage and says why): fixed vertices can force its distortion (the handles of
    // tlc/armadillo-598's fixed boundary, where untangle_prepared() stops below the cap
    // otherwise), and no exponent makes the barrier lower such a simplex. Nothing forces one
    // whose vertices are all free (an assembly that recovered a mesh with one very distorted
    // tetrahedron, as PolyCube's on robustPolycube/cup; a Tutte start's slivers away from the
    // anchored simplex of detail/vertex_descent.h): the rounds at a lower s, below the cap, lower
    // it.
    auto beyond_cap_at_fixed_vertex = [&] {
        for (Index s : moving) {
            bool at_fixed = false;
            for (int k = 0; k <= D; ++k) at_fixed |= fixed[mesh.simplices(s, k)] != 0;
            if (at_fixed && !(c.s * distortion(start, s) <= kBarrierExponentCap)) return true;
        }
        return false;
    };
    if (!c.energies || !std::isfinite(d.largest) || !(c.s * d.spread() > kExponentRange) ||
        (!(c.s * d.largest <= kBarrierExponentCap) && beyond_cap_at_fixed_vertex()))
        return run(energies, c.energies ? c.s : options.s, start, options);

    // The energy asked for, on the whole mesh: what the best iterate is judged by.
    auto energy_at_s = [&](const Eigen::MatrixXd& x) {
        const std::vector<Mat<D>> A = linear_parts<D>(mesh, frames, x.leftCols(D));
        double sum = 0.0;
        for (const auto& energy : energies) sum += energy->sum(A);
        return sum;
    };
    const TimeBudget budget(options.max_time_seconds);
    VertexStage result;
    // Until a round runs: only the time limit can stop the first.
    result.outcome = VertexStageOutcome::kSkippedTimeLimit;
    result.positions = start;
    double best = energy_at_s(start);
    Eigen::MatrixXd x = start;
    const double d_start = d.largest;
    double s_first = -1.0, s_last = -1.0;
    int rounds = 0;
    bool last_round = false, improved = false;
    // Each round runs to convergence or to the iteration limit; the rounds share the time limit.
    while (!budget.exhausted()) {
        const double s = last_round ? c.s : continuation_exponent(c.s, d.spread());
        char line[160];
        std::snprintf(line, sizeof line,
                      "vertex stage: exponent continuation round %d, s = %.4g (asked %.4g), "
                      "distortion %.4g to %.4g",
                      rounds, s, c.s, d.smallest, d.largest);
        log_line(logger, line);
        SimplexAssemblyOptions o = with_time_left(options, budget);
        o.s = s;
        // e^{s d} = 1 + s d + ...: for s << 1 the part of E that moves is s times smaller, and so
        // must be the relative change that ends the round.
        o.energy_tolerance = options.energy_tolerance * std::min(1.0, s);
        VertexStage v = run(c.energies(s), s, x, o);
        result.rounds.push_back(v.rounds.back());
        ++rounds;
        if (s_first < 0.0) s_first = s;
        s_last = s;
        if (v.outcome == VertexStageOutcome::kRanUndone) {
            // The round's result is dropped: the best iterate so far stays, at the s it had.
            if (result.newton.iterations.empty()) result.newton = v.newton;
            result.outcome = improved ? VertexStageOutcome::kRan : VertexStageOutcome::kRanUndone;
            result.figures = "round " + std::to_string(rounds - 1) + " undone (" +
                             std::to_string(v.rounds.back().undone_degenerate) +
                             " degenerate simplices)";
            break;
        }
        if (v.ran()) {
            result.outcome = VertexStageOutcome::kRan;
            result.stop = v.stop;
            // One summary for the stage: every round's steps, the first round's start.
            if (result.newton.iterations.empty()) {
                result.newton = v.newton;
            } else {
                const PhaseTimes times = result.newton.times;
                std::vector<IterationRecord> records = std::move(result.newton.iterations);
                const double initial = result.newton.initial_energy;
                records.insert(records.end(),
                               v.newton.iterations.begin() +
                                   std::min<std::size_t>(1, v.newton.iterations.size()),
                               v.newton.iterations.end());
                result.newton = std::move(v.newton);
                result.newton.iterations = std::move(records);
                result.newton.initial_energy = initial;
                result.newton.times += times;
            }
            x = v.positions;
            const double e = energy_at_s(x);
            if (e < best) {
                best = e;
                result.positions = x;
                improved = true;
            }
        } else if (!result.ran()) {
            result.outcome = v.outcome;
            result.figures = v.figures;
        }
        if (last_round || !v.ran()) break;
        const Range after = distortion_range(x);
        const bool stalled = !(after.spread() < (1.0 - kContinuationStall) * d.spread());
        d = after;
        if (s >= c.s) break;
        // The last round takes the exponent asked for, from the best iterate so far (the start
        // when the largest distortion is one the handles force: then this is the single run).
        if (stalled || rounds + 1 >= kContinuationRounds) {
            last_round = true;
            x = result.positions;
        }
    }
    if (rounds == 0) {
        ContinuationRound none;
        none.outcome = VertexStageOutcome::kSkippedTimeLimit;
        none.max_distortion_before = none.max_distortion_after = d_start;
        result.rounds.push_back(none);
    } else {
        char line[200];
        std::snprintf(line, sizeof line,
                      "exponent continuation: %d round%s, s %.3g to %.3g, largest distortion "
                      "%.4g to %.4g",
                      rounds, rounds == 1 ? "" : "s", s_first, s_last, d_start,
                      distortion_range(result.positions).largest);
        result.continuation_rounds = rounds;
        result.figures = result.figures.empty() ? line : result.figures + "; " + line;
        if (result.outcome == VertexStageOutcome::kRan && !improved)
            result.outcome = VertexStageOutcome::kRanStartKept;
    }
    return result;
}

void record_vertex_stage(StageTrace& trace, const VertexStage& stage, double seconds) {
    StageRecord& r = trace.add(Stage::kVertexStage, stage.outcome);
    if (stage.ran()) {
        r.newton_steps = stage.newton.num_steps();
        r.termination = stage.newton.termination;
    }
    r.seconds = seconds;
    r.figures = stage.figures;
}

template ExponentContinuation<2> exponent_continuation<2>(const PreparedProblem<2>&,
                                                          const std::vector<Index>&,
                                                          std::optional<double>);
template ExponentContinuation<3> exponent_continuation<3>(const PreparedProblem<3>&,
                                                          const std::vector<Index>&,
                                                          std::optional<double>);

template VertexStage run_vertex_stage<2>(const SimplicialMesh&, const RestFrames<2>&,
                                         const MeshTopology&,
                                         const std::vector<std::shared_ptr<const SimplexTerm<2>>>&,
                                         const Eigen::MatrixXd&, const std::vector<unsigned char>&,
                                         const SimplexAssemblyOptions&, const Logger&,
                                         const VertexStageTerms<2>&);
template VertexStage run_vertex_stage<3>(const SimplicialMesh&, const RestFrames<3>&,
                                         const MeshTopology&,
                                         const std::vector<std::shared_ptr<const SimplexTerm<3>>>&,
                                         const Eigen::MatrixXd&, const std::vector<unsigned char>&,
                                         const SimplexAssemblyOptions&, const Logger&,
                                         const VertexStageTerms<3>&);

}  // namespace sa
