#pragma once
// Integrable frame fields by Simplex Assembly (the paper's 4.5 and "Global seamless
// parameterizations" in 5.2). Given per face a frame phi_f as a 2 x 2 matrix (frame_field.h) and
// the fixed matchings k_e of the interior edges (cut_graph.h), find matrices A_f minimizing
//     mu sum_f w_f |A_f - phi_f|_F^2  +  sum_f E_C(A_f)  +  lambda sum_e |A_f e_f - R_e A_g e_g|^2
// (Eq. 10 with Eq. 11 as the assembly term: R_e = Rot(k_e quarter turns), e_f and e_g the edge's
// unit vectors in each face's frame; E_m = |phi' - phi|^2, the paper's choice; E_C the conformal
// barrier e^{d_conf} with K = +inf, which keeps every det A_f > 0, so the Poisson map of the
// result has no foldovers; w_f = area_f / mean area). It is the Simplex Assembly engine
// (frontends/simplex_assembly/engine.h) in its linear-part layout without translations: A_f per
// face in the face's rest frame, the frame energy as its per-simplex energy, Eq. 11 as its
// assembly term; the engine's schedule (4.4) and termination end it (sum_e curl_e^2 <
// assembly_tolerance and E changing by less than energy_tolerance, relative, in a step; or E
// converged at lambda_max; or the limits). The matchings stay fixed, so the singularities do too.
// A field that is integrable already (sum curl^2 below the tolerance) is returned unchanged
// without an iteration: E_C would otherwise pull an integrable but anisotropic field towards
// conformal frames.
//
// phi is first scaled by 1 / (its mean row norm), so the curl tolerances are relative to the
// field's size; the result is scaled back. The whole mesh is solved at once (no submeshes: 4
// variables per face, e.g. 160k for 40k faces, one CHOLMOD factorization per iteration).

#include <vector>

#include "frontends/simplex_assembly/engine_options.h"
#include "geometry/mesh/mesh_topology.h"
#include "geometry/mesh/rest_frames.h"
#include "optim/logger.h"
#include "optim/newton_summary.h"

namespace sa {

/// The engine's schedule and termination (engine_options.h: lambda_min 1e3, lambda_max 1e16,
/// assembly_tolerance 1e-12 on sum_e curl_e^2 of the field scaled to mean row norm 1,
/// energy_tolerance 1e-8, 200 iterations, ...) and the weight of E_m.
struct IntegrableFieldOptions : AssemblyEngineOptions {
    double mu = 1000.0;  ///< the weight of E_m
};

struct IntegrableField {
    std::vector<Mat<2>> matrices;  ///< A_f per face, in the units of phi
    double assembly = 0.0;         ///< sum_e curl_e^2 at the end (scaled field)
    bool assembled = false;        ///< assembly < assembly_tolerance
    NewtonSummary newton;
    AssemblyStop stop = AssemblyStop::kAssembled;  ///< why the engine stopped
};

/// Progress rows go to `logger` (iteration, energy, E~, lambda, step, time).
IntegrableField integrable_field(const SimplicialMesh& mesh, const MeshTopology& topology,
                                 const RestFrames<2>& frames, const std::vector<Mat<2>>& phi,
                                 const std::vector<int>& matching,
                                 const IntegrableFieldOptions& options = {},
                                 const Logger& logger = {});

}  // namespace sa
