#include "frontends/seamless/integrable_field.h"

#include <algorithm>
#include <cmath>

#include "energies/edge_assembly_energy.h"
#include "energies/simplex_energy.h"
#include "frontends/seamless/frame_field.h"
#include "frontends/simplex_assembly/engine.h"
#include "optim/errors.h"

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
    std::vector<Mat<2>> start(nf);
    for (Index f = 0; f < nf; ++f) {
        reference[f] = scale * phi[f];
        if (!(reference[f].determinant() > 0.0)) {
            throw InvalidArgumentError("integrable_field: the frame of face " + std::to_string(f) +
                                       " is not positively oriented");
        }
        weights[f] = frames.volume[f] * double(nf) / area;
        start[f] = reference[f];
    }
    // The engine in its linear-part layout, no translations (4.5): E_m = |A_f - phi_f|^2 with
    // the conformal barrier (kind 1), Eq. 11 per interior edge (kind 2).
    SimplexAssemblyEngine<2> engine(start);
    SimplexEnergyOptions energy_options;
    energy_options.barrier_distortion = DistortionType::kConformal;
    energy_options.mapping_distortion = DistortionType::kDifference;
    energy_options.mu = options.mu;
    engine.add_simplex_energy(
        "frame energy", SimplexEnergy<2>(energy_options, std::move(weights), std::move(reference)));

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
        const auto f = engine.linear_variables(facet.simplex[0]);
        const auto g = engine.linear_variables(facet.simplex[1]);
        std::array<Index, 8> element;
        std::copy(f.begin(), f.end(), element.begin());
        std::copy(g.begin(), g.end(), element.begin() + 4);
        edge_elements.push_back(element);
    }
    engine.add_assembly_term("edge curl (Eq. 11)", EdgeAssemblyEnergy<2>(std::move(edges)),
                             std::move(edge_elements));

    IntegrableField result;
    const double start_assembly = engine.assembly_energy();  // unweighted
    if (start_assembly < options.assembly_tolerance) {       // already integrable: keep phi
        result.matrices = phi;
        result.assembly = start_assembly;
        result.assembled = true;
        log_line(logger, "the field is integrable already (sum curl^2 " +
                             std::to_string(start_assembly) + "): kept as it is");
        return result;
    }
    AssemblyRun run = engine.run(options, {.logger = logger, .after_iteration = {}});
    result.newton = std::move(run.newton);
    result.stop = run.stop;
    result.assembly = run.final_assembly;
    result.assembled = run.assembled;
    const std::vector<Mat<2>> solved = engine.linear_parts(engine.problem().variables());
    result.matrices.resize(nf);
    for (Index f = 0; f < nf; ++f) {
        result.matrices[f] = solved[f] / scale;
    }
    return result;
}

}  // namespace sa
