#pragma once
// Planar parameterization of a disk-topology surface by Simplex Assembly (sections 5.1 and 5.2),
// or of one with holes (genus 0, several boundary loops: the starts are computed with the inner
// holes filled, hole_filling.h, and every loop stays free): an initial map (LSCM, Tutte, harmonic,
// or one given), then Simplex Assembly with a free boundary
// (no handles) and E_m = sum_i area_i |A_i - A_i^0|^2 (difference to the initial map) or the LSCM
// energy, under a bound K on the conformal or isometric distortion, or the optimal bound: rounds
// that each take the largest distortion of the previous result as the new bound, until it stops
// improving (section 5.1, "Optimal bound"; the mesh driver's loop, optimal_bound.h). With
// `free_boundary_injective` the boundary-angle barrier E_theta keeps every boundary angle sum below
// 2 pi.

#include <string>
#include <vector>

#include "frontends/param/start_fallback.h"
#include "frontends/simplex_assembly/map_solve.h"
#include "frontends/simplex_assembly/optimal_bound.h"

namespace sa {

enum class InitialMap { kLscm, kTutte, kTutteUniform, kHarmonic };
std::string to_string(InitialMap map);
/// "lscm", "tutte" (mean-value weights), "tutte-uniform", "harmonic"; throws otherwise.
InitialMap parse_initial_map(const std::string& name);

struct ParameterizationOptions {
    /// The distortion in the barrier (conformal or isometric), E_m and mu; bound, threads, mode.
    /// The driver sets no handles and takes E_m as configured here.
    SimplexAssemblyOptions solver;
    /// Rounds of the optimal bound: 0 keeps solver.bound; n > 0 runs up to n rounds, those after
    /// the first in the submesh mode unless solver.mode is kFull or free_boundary_injective is set.
    int optimal_bound_rounds = 0;
    /// The optimal bound stops when a round lowers the largest distortion K by less than this
    /// share of K - 1 (OptimalBoundOptions::tolerance; on the shared disk meshes 5e-3 runs the
    /// rounds a share 5e-4 of K ran where K - 1 is 0.1-0.2, and goes on where K is near 1).
    double optimal_bound_tolerance = 5e-3;
    /// The submesh mode's rounds solve regions around every simplex whose distortion is within
    /// this share of the bound (OptimalBoundOptions::submesh_band).
    double optimal_bound_band = 0.5;
    /// The boundary-angle barrier E_theta (full mode only).
    bool free_boundary_injective = false;
    /// When the first round's result does not verify (or is over the bound), start again from a
    /// map that cannot fold (start_fallback.h) and keep the better verified result.
    bool fallback = true;
};

struct ParameterizationResult {
    Eigen::MatrixXd uv;          ///< #V x 2 (the last verified round)
    Eigen::MatrixXd initial_uv;  ///< #V x 2
    MapQuality initial_quality;
    SimplexAssemblyResult solve;  ///< the last verified round (or the first, if none was)
    std::vector<BoundRound> rounds;
    double reached_bound = kInfinity;  ///< the largest distortion of `uv`, in the barrier's measure
    Index boundary_violations_before = 0;  ///< boundary vertices with angle sum >= 2 pi
    Index boundary_violations_after = 0;
    /// Inner boundary loops filled for the start (hole_filling.h; 0 for a disk).
    Index filled_holes = 0;
    /// Vertices of the mesh that belong to no triangle: left out of the map (start_disk.h).
    Index unused_vertices = 0;
    double initial_map_time = 0.0;
    double total_time = 0.0;
    /// The fallback, when the requested start's result was not kept (fallback.used).
    StartFallback fallback;
    bool success = false;
    std::string message;
};

/// `mesh` is the rest surface (#V x 3 or #V x 2, triangles); `initial_uv`, when not null, is the
/// initial map (#V x 2) and `initial` is ignored. Throws InputError when the mesh cannot lie in
/// the plane (require_planar_surface in boundary_loops.h: closed, genus > 0, not manifold).
ParameterizationResult parameterize(const SimplicialMesh& mesh, const std::string& source,
                                    const Eigen::MatrixXd* initial_uv, InitialMap initial,
                                    const ParameterizationOptions& options,
                                    const SimplexAssemblyObserver& observer = {});

}  // namespace sa
