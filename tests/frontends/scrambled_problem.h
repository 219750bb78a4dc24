#pragma once
// Fixed-boundary test problems with many inverted simplices: generated from any mesh, or from
// tests/fixtures/generated_problems.h.

#include <random>

#include "frontends/simplex_assembly/map_solve.h"
#include "geometry/mesh/mesh_topology.h"
#include "tests/fixtures/generated_problems.h"

namespace sa {

/// `mesh` with its boundary vertices as handles at their rest positions and every interior
/// vertex moved by a uniform offset in [-amount, amount] per coordinate (seeded): a feasible
/// problem whose initial map inverts many simplices.
inline MappingProblem scrambled(const SimplicialMesh& mesh, double amount, unsigned seed) {
    MappingProblem p;
    p.mesh = mesh;
    p.initial = mesh.vertices;
    const MeshTopology t = mesh_topology(mesh, "generated");
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-amount, amount);
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        if (t.boundary_vertex[v]) {
            p.handles.push_back(v);
        } else {
            for (int c = 0; c < mesh.vertices.cols(); ++c) p.initial(v, c) += u(rng);
        }
    }
    return p;
}

/// A generated problem (rest, initial map, handles) as the driver's input.
inline MappingProblem mapping_problem(const GeneratedProblem& g) {
    MappingProblem p;
    p.mesh = g.rest;
    p.initial = g.initial;
    p.handles = g.handles;
    p.source = "generated";
    return p;
}

}  // namespace sa
