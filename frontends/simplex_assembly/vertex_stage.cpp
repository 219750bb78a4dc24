#include "frontends/simplex_assembly/detail/vertex_stage.h"

#include "energies/boundary_angle_energy.h"
#include "frontends/simplex_assembly/engine.h"

namespace sa {

template <int D>
VertexStage run_vertex_stage(const SimplicialMesh& mesh, const RestFrames<D>& frames,
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
            result.note = "skipped: " + plugin->name() + " cannot project the start";
            return result;
        }
    }
    std::vector<std::array<Index, D + 1>> simplices(mesh.num_simplices());
    for (Index s = 0; s < mesh.num_simplices(); ++s)
        for (int k = 0; k <= D; ++k) simplices[s][k] = mesh.simplices(s, k);
    SimplexAssemblyEngine<D> engine = SimplexAssemblyEngine<D>::vertex_positions(
        result.positions.leftCols(D), std::move(simplices), frames.corners, frames.edge_inverse);
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
        [&]<int... k>(std::integer_sequence<int, k...>) {
            (
                [&] {
                    constexpr int K = k + 1;
                    std::vector<std::array<Index, 2 * K + 4>> angle_elements;
                    for (const BoundaryFan& fan : terms.fans) {
                        if (int(fan.triangles.size()) != K) continue;
                        std::array<Index, 2 * K + 4> e;
                        const auto center = engine.vertex_variables(fan.vertex);
                        e[0] = center[0];
                        e[1] = center[1];
                        for (int m = 0; m <= K; ++m) {
                            const auto neighbour = engine.vertex_variables(fan.neighbours[m]);
                            e[2 + 2 * m] = neighbour[0];
                            e[3 + 2 * m] = neighbour[1];
                        }
                        angle_elements.push_back(e);
                    }
                    if (!angle_elements.empty()) {
                        engine.add_barrier("boundary angle " + std::to_string(K),
                                           BoundaryAngleVertexEnergy<K>{},
                                           std::move(angle_elements));
                    }
                }(),
                ...);
        }
        (std::make_integer_sequence<int, kMaxFan>{});
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
        result.note = terms.plugins.empty()
                          ? "skipped: the recovered mesh has an inverted simplex or one over the "
                            "bound"
                          : "skipped: the recovered mesh (projected by the plugins) has an "
                            "inverted simplex, one over the bound, or a plugin barrier at +inf";
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
        result.note = "skipped: " + std::to_string(beyond_cap) +
                      " simplices are so distorted that the barrier cannot rank the others";
        result.positions = start;
        return result;
    }
    AssemblyHooks hooks;
    hooks.logger = logger;
    AssemblyRun run = engine.run(engine_options(options), hooks);
    result.newton = std::move(run.newton);
    result.stop = run.stop;
    result.ran = true;
    result.note = to_string(result.newton.termination);
    result.positions.leftCols(D) = engine.positions(engine.problem().variables());
    return result;
}

template VertexStage run_vertex_stage<2>(const SimplicialMesh&, const RestFrames<2>&,
                                         const std::vector<std::shared_ptr<const SimplexTerm<2>>>&,
                                         const Eigen::MatrixXd&, const std::vector<unsigned char>&,
                                         const SimplexAssemblyOptions&, const Logger&,
                                         const VertexStageTerms<2>&);
template VertexStage run_vertex_stage<3>(const SimplicialMesh&, const RestFrames<3>&,
                                         const std::vector<std::shared_ptr<const SimplexTerm<3>>>&,
                                         const Eigen::MatrixXd&, const std::vector<unsigned char>&,
                                         const SimplexAssemblyOptions&, const Logger&,
                                         const VertexStageTerms<3>&);

}  // namespace sa
