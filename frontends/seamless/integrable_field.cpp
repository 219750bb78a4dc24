#include "frontends/seamless/integrable_field.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "energies/edge_assembly_energy.h"
#include "energies/simplex_energy.h"
#include "geometry/frame_field.h"
#include "optim/errors.h"
#include "optim/newton_solver.h"

namespace sa {

IntegrableField integrable_field(const SimplicialMesh& mesh, const MeshTopology& topology,
                                 const RestFrames<2>& frames, const std::vector<Mat<2>>& phi,
                                 const std::vector<int>& matching,
                                 const IntegrableFieldOptions& options, const Logger& logger) {
    const Index nf = mesh.num_simplices();
    if (Index(phi.size()) != nf || matching.size() != topology.interior_facets.size()) {
        throw InvalidArgumentError(
            "integrable_field: expected one frame per face and one matching per interior edge");
    }
    double area = 0.0;
    for (Index f = 0; f < nf; ++f) area += frames.volume[f];
    const double scale = 1.0 / mean_row_norm(phi);
    std::vector<Mat<2>> reference(nf);
    std::vector<double> weights(nf);
    Eigen::VectorXd x(4 * nf);
    for (Index f = 0; f < nf; ++f) {
        reference[f] = scale * phi[f];
        if (!(reference[f].determinant() > 0.0)) {
            throw InvalidArgumentError("integrable_field: the frame of face " + std::to_string(f) +
                                       " is not positively oriented");
        }
        weights[f] = frames.volume[f] * double(nf) / area;
        x.segment<4>(4 * f) = Eigen::Map<const Vec<4>>(reference[f].data());
    }
    Problem problem(std::move(x));
    SimplexEnergyOptions energy_options;
    energy_options.barrier_distortion = DistortionType::kConformal;
    energy_options.mapping_distortion = DistortionType::kDifference;
    energy_options.mu = options.mu;
    std::vector<std::array<Index, 4>> face_elements(nf);
    for (Index f = 0; f < nf; ++f) face_elements[f] = {4 * f, 4 * f + 1, 4 * f + 2, 4 * f + 3};
    const TermId simplex_term = problem.add_term(
        "frame energy", SimplexEnergy<2>(energy_options, std::move(weights), std::move(reference)),
        std::move(face_elements));

    // Eq. 11 per interior edge.
    std::vector<SharedFacetEdges<2>> edges;
    std::vector<std::array<Index, 8>> edge_elements;
    for (std::size_t i = 0; i < topology.interior_facets.size(); ++i) {
        const InteriorFacet& facet = topology.interior_facets[i];
        const auto [ef, eg] = facet_edge_in_frames(mesh, frames, facet);
        SharedFacetEdges<2> e;
        e.in_i = ef;
        e.in_j = eg;
        e.rotation = quarter_turns(matching[i]);
        edges.push_back(e);
        const Index f = 4 * facet.simplex[0], g = 4 * facet.simplex[1];
        edge_elements.push_back({f, f + 1, f + 2, f + 3, g, g + 1, g + 2, g + 3});
    }
    const TermId assembly_term = problem.add_term(
        "edge curl (Eq. 11)", EdgeAssemblyEnergy<2>(std::move(edges)), std::move(edge_elements));

    IntegrableField result;
    std::vector<double> start_terms;
    problem.value(problem.variables(), &start_terms);
    const double start_assembly = start_terms[assembly_term];  // unweighted
    if (start_assembly < options.assembly_tolerance) {         // already integrable: keep phi
        result.matrices = phi;
        result.assembly = start_assembly;
        result.assembled = true;
        log_line(logger, "the field is integrable already (sum curl^2 " +
                             std::to_string(start_assembly) + "): kept as it is");
        return result;
    }
    double lambda = options.lambda_min, last_assembly = kInfinity;
    problem.set_weight(assembly_term, lambda);
    NewtonOptions newton;
    newton.max_iterations = options.max_iterations;
    newton.max_time_seconds = options.max_time_seconds;
    newton.gradient_tolerance = newton.decrement_tolerance = newton.function_tolerance = 0.0;
    newton.num_threads = options.num_threads;
    log_line(logger, "iter      energy   sum curl^2     lambda      step     time");
    newton.callbacks.push_back([&](const IterationContext& c) {
        const double assembly = c.term_values[assembly_term];
        const double rest = c.term_values[simplex_term];
        last_assembly = assembly;
        char line[160];
        std::snprintf(line, sizeof line, "%4d  %10.4e  %11.3e  %9.3e  %8.2e  %6.2fs",
                      c.record.iteration, c.record.energy, assembly, lambda,
                      std::max(c.record.step_length, 0.0), c.record.cumulative_time);
        log_line(logger, line);
        if (c.record.iteration > 0 && assembly < options.assembly_tolerance) {
            const double before = c.record.energy + c.record.energy_change;
            if (c.record.energy_change <= options.energy_tolerance * std::abs(before))
                return CallbackResult::kStopSuccess;
        }
        const double ratio = assembly > 0.0 ? rest / assembly : kInfinity;
        lambda = std::min(options.lambda_min * std::max(ratio, 1.0), options.lambda_max);
        problem.set_weight(assembly_term, lambda);
        return CallbackResult::kContinue;
    });
    result.newton = solve(problem, newton);
    result.assembly = last_assembly;
    result.assembled = last_assembly < options.assembly_tolerance;
    result.matrices.resize(nf);
    for (Index f = 0; f < nf; ++f) {
        result.matrices[f] = Eigen::Map<const Mat<2>>(problem.variables().data() + 4 * f) / scale;
    }
    return result;
}

}  // namespace sa
