#pragma once
// Options of the mesh driver (map_solve.h), with the paper's constants as defaults (section 4.4).

#include <cstdint>
#include <optional>
#include <string>

#include "energies/distortion.h"
#include "energies/simplex_energy.h"
#include "frontends/simplex_assembly/disassembly.h"
#include "frontends/simplex_assembly/engine_options.h"
#include "optim/hessian_projection.h"
#include "optim/linear_solver.h"
#include "optim/time_budget.h"

namespace sa {

/// How the driver solves (map_solve.h):
///   kFull     the whole mesh at once: disassembly, assembly, recovery, the vertex stage;
///   kSubmesh  submeshes around the bad simplices (section 4.4, "Speedup");
///   kDescent  from a start without inverted simplices, the vertex stage alone, its bound
///             continued in rounds (detail/vertex_descent.h); never chosen by kAuto.
enum class SolveMode { kAuto, kFull, kSubmesh, kDescent };
std::string to_string(SolveMode mode);
/// "auto", "full", "submesh" or "descent"; throws InvalidArgumentError otherwise.
SolveMode parse_solve_mode(const std::string& name);

/// Which variables carry the translations (section 5.1, "Variants of simplex assembly").
enum class Variant {
    /// r-SA: A_i for every simplex, T_p only on the simplices of the Steiner tree through the
    /// handles and of loops generating the mesh's first homology (default). Eq. 7 alone glues
    /// the mesh only where every loop is contractible; the loops' translations, agreeing at
    /// their vertices (Eq. 9), close the map around holes and handles too (docs/algorithm.md,
    /// "Departures from the paper").
    kReduced,
    kFull,    ///< f-SA: A_i and T_i for every simplex (Eqs. 2, 3)
    kVertex,  ///< v-SA: per-simplex copies of the vertex positions
};
std::string to_string(Variant variant);

struct SimplexAssemblyOptions;
/// "r", "f", "v" (or "reduced", "full", "vertex"); throws InvalidArgumentError otherwise.
Variant parse_variant(const std::string& name);

/// The mesh driver's options: the engine's schedule, Hessian modification and termination
/// (AssemblyEngineOptions: lambda_min, lambda_max, projection, projection_epsilon,
/// translation_shift, linear_solver, assembly_tolerance, energy_tolerance, max_iterations,
/// max_time_seconds, num_threads), and the energy, variant, stages and submeshes below.
struct SimplexAssemblyOptions : AssemblyEngineOptions {
    // The energy E = mu E_m + E_C + lambda E~_assembly (Eq. 10).
    /// Distortion inside the barrier E_C: conformal, volumetric or isometric.
    DistortionType distortion = DistortionType::kConformal;
    /// K: the bound on that distortion; +inf for none.
    double bound = kInfinity;
    /// s in e^{s d}.
    double s = 1.0;
    /// gamma of the isometric distortion.
    double gamma = 0.5;
    /// d_m of E_m = sum_i w_i d_m(A_i) (w_i the rest volume); none: E_m = 0.
    std::optional<DistortionType> mapping_distortion;
    /// mu, the weight of E_m.
    double mu = 1000.0;
    /// Whether the energy above (mu E_m + E_C of these options) is added; false leaves only the
    /// problem's own energies (MappingProblem::energies), which must then hold at least one.
    bool builtin_energy = true;

    Variant variant = Variant::kReduced;
    /// How the initial A_i are made feasible (section 4.2); by default the closest similarity for
    /// the conformal barrier and the closest rotation otherwise.
    std::optional<Initialization> initialization;
    std::uint64_t seed = 1;  ///< for random initial rotations

    /// Finish in vertex variables (vertex_stage.h): stop the assembly as soon as E~_assembly is
    /// below its tolerance, recover the mesh, and minimize mu E_m + E_C over its vertex positions
    /// (handles fixed) until E changes by less than energy_tolerance. When false, the paper's
    /// schedule runs to its own termination at lambda_max.
    bool vertex_stage = true;
    /// The assembly hands over to the vertex stage once the mesh recovered from the current A_i
    /// (checked every iteration) has an energy mu E_m + E_C at most this many times that of the
    /// disassembled simplices: a valid but far more distorted mesh would leave the vertex stage
    /// with the slow start the paper avoids by disassembling.
    double handover_ratio = 1.5;
    /// Stop at the first map verified inversion-free and within the bound: the assembly stops at
    /// the first iteration whose recovered mesh is valid (whatever its energy), and no vertex
    /// stage lowers the distortion afterwards. Untangling only; the fastest path.
    bool until_valid = false;

    /// Verification: handles must end within this fraction of the bounding-box diagonal of the
    /// initial map from their targets.
    double handle_tolerance = 1e-6;

    // The submesh strategy (submesh_assembly.h), with the paper's m, m_max and l_max.
    SolveMode mode = SolveMode::kAuto;
    int rings = 4;       ///< m: rings of simplices around the bad ones
    int max_rings = 20;  ///< m_max: a failed region grows by 2 rings up to this, while it grows
    int max_rounds = 2;  ///< l_max: rounds after the first, while a round repairs a region
    /// The first round's regions also surround every simplex whose barrier distortion d is within
    /// this share of its finite bound K: d >= d_I + (1 - band)(K - d_I), d_I the distortion of the
    /// identity (each bounded barrier alike). Solved with the bound K, their barrier pushes the
    /// largest distortion down while the rest of the map stays fixed: the optimal-bound rounds in
    /// the submesh mode (optimal_bound.h). 0: only the bad simplices (the paper's step 3).
    double submesh_band = 0.0;
    /// Most local/global iterations after the paper's M^0 in the submesh mode's start:
    /// Anderson-accelerated ARAP (rotations) or ASAP (similarities) iterations, which spread
    /// large handle motions (frontends/simplex_assembly/detail/submesh_start.h); 0 = start from the
    /// initial map itself. The iterate with the fewest bad simplices is kept.
    int start_iterations = 500;
    /// kAuto takes the full solve for meshes of at most this many triangles or tetrahedra (a
    /// tetrahedron's 9 variables couple with its 4 neighbours: the full 3D system costs far more),
    /// and for meshes whose initial map has more than `auto_bad_share` inverted or degenerate
    /// simplices unless every boundary vertex is a handle (the submesh mode's start untangles a
    /// fixed boundary's interior in vertex variables); the submesh mode otherwise.
    /// A run that ends without a valid map, its handles in place and time left, is untangled in
    /// vertex variables and finished by the vertex stage (untangle_fallback.h). Front-ends with a
    /// last resort of their own (param's Tutte start, start_fallback.h) turn it off.
    bool untangle_fallback = true;
    Index auto_full_triangles = 20000;
    Index auto_full_tetrahedra = 1000;
    double auto_bad_share = 0.25;

    /// The initialization actually used: `initialization` or the default for `distortion`.
    Initialization effective_initialization() const;
    /// Throws InvalidArgumentError naming the first bad field and its value.
    void validate() const;
};

/// The per-simplex energy's options (barrier, E_m) that `options` describe.
SimplexEnergyOptions simplex_energy_options(const SimplexAssemblyOptions& options);

/// `options` with max_time_seconds set to what `budget` has left, for a stage or a submesh: at
/// least a millisecond, so a stage that starts takes one step (it starts only while time is left).
SimplexAssemblyOptions with_time_left(const SimplexAssemblyOptions& options,
                                      const TimeBudget& budget);

}  // namespace sa
