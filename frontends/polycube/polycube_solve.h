#pragma once
// The PolyCube solve (issue 21; the paper's 5.3 with 5.1's barriers), a configuration of the mesh
// driver (frontends/simplex_assembly/map_solve.h) and its engine, with no schedule of its own:
//
//   1. the cube-cover start (frontends/polycube/cube_cover.h): planar, axis-aligned charts,
//   possibly folded;
//      when folded, untangled in vertex variables with every plane one variable
//      (PolycubePluginOptions), and the driver starts from that map when it untangles;
//   2. the driver's disassembly (closest similarity, 4.2), its assembly (Eq. 10, f-SA) and its
//      vertex stage, minimizing the conformal barrier E_C (bound K, or none) with the PolyCube
//      plugin (polycube_plugin()) adding, in the assembly stage,
//        - planarity a^T A_i e_k = 0 on two normalized edges of every labelled boundary facet of
//          tetrahedron i (frontends/polycube/polycube_constraints.h), in E~_assembly: with the edge
//          assembly of Eq. 7 every chart maps into one plane orthogonal to its axis;
//        - each boundary vertex on its planes at the start's offsets, a^T (A_i u + T_i) = c, in
//          E~_assembly (the paper's 5.3; it needs the translations of f-SA): every other term is
//          blind to the map's scale, and E~ falls as the map shrinks (polycube_solve.cpp);
//        - the 3D boundary-angle barriers E_e = 1 / (2 pi - theta_e) and E_v = 1 / (4 pi - theta_v)
//          in A-form, on every boundary edge and vertex (frontends/polycube/tet_angle_barriers.h);
//      and, in the vertex stage, the sliding boundary: the vertices of each plane (the charts of
//      one axis that share vertices) are projected onto their mean coordinate, which becomes one
//      variable shared by all of them (AssemblyPlugin::shared_coordinates): a chart vertex
//      slides in its plane, a vertex where two planes meet along their line, a corner moves
//      with its three planes, and each plane moves as a whole. One plane per axis stays (the
//      translation), and a second on the axis of largest extent (E_C does not see the scale).
//      The hand-over test projects the recovered mesh onto the planes and untangles the
//      tetrahedra this folds (PolycubePluginOptions); by default the first valid one is handed
//      over (handover_ratio).
//      The angle barriers are checked on the vertex stage's start (the hand-over) and need no
//      term there: with exact planes and no degenerate tetrahedron the angle sums cannot change
//      (polycube_solve.cpp says why); verification measures them on the output;
//   3. with `optimal_bound`, the rounds of optimal_bound.h (5.1, "Optimal bound");
//   4. verify_polycube() on the output positions: the run succeeds only when it passes (and the
//      driver's own verification: no inverted or degenerate tetrahedron, no branched edge).
//
// Units: positions (the start's and the result's) in prepared.mesh's, the input's times
// 2^-scale_exponent (PreparedPolycube::in_input_units() for the input's); distortion reported
// after scaling to the input volume.

#include <memory>
#include <string>
#include <vector>

#include "frontends/polycube/polycube_preparation.h"
#include "frontends/simplex_assembly/map_solve.h"
#include "frontends/simplex_assembly/optimal_bound.h"

namespace sa {

struct PolycubeSolveOptions {
    double bound = kInfinity;     ///< K on the conformal distortion; +inf: none
    bool optimal_bound = false;   ///< rounds of optimal_bound.h (bound must be +inf then)
    int rounds = 10;              ///< most rounds with optimal_bound
    double max_time = kInfinity;  ///< seconds, the whole solve
    int threads = 0;              ///< 0 = all cores
    /// Weight of the 3D boundary-angle barriers against E_C.
    double angle_weight = 1.0;
    /// Most Newton steps of the untangling on the planes (PolycubePluginOptions); 0: none.
    int untangle_iterations = 100;
    /// The driver's hand-over test (SimplexAssemblyOptions::handover_ratio). A mesh untangled on
    /// the planes is inversion-free but its conformal barrier is far above the disassembled
    /// simplices' (S3: 1.7e13 against 1.2e5), so the default hands over the first valid
    /// recovered mesh: each assembly iteration on a 30k-tetrahedron mesh costs tens of seconds
    /// and a vertex-stage iteration under one (docs/measurements.md, PolyCube).
    double handover_ratio = kInfinity;
};

struct PolycubeSolve {
    Eigen::MatrixXd start;     ///< the cube-cover map, #V x 3
    MapQuality start_quality;  ///< of the start
    /// The driver started from the start untangled on its planes (PolycubePluginOptions), not
    /// from the start itself.
    bool start_untangled = false;
    Eigen::MatrixXd positions;       ///< the output, #V x 3
    SimplexAssemblyResult solve;     ///< the driver's result (the kept round)
    std::vector<BoundRound> rounds;  ///< with optimal_bound (empty otherwise)
    /// The bound the kept result was solved with, and its largest conformal distortion.
    double bound = kInfinity;
    PolycubeVerification verification;
    bool success = false;  ///< the driver's and verify_polycube()'s checks both passed
    std::string message;   ///< the outcome in a sentence or two
    double cube_cover_seconds = 0.0, untangle_seconds = 0.0, solve_seconds = 0.0,
           verify_seconds = 0.0;
    SimplexAssemblyOptions options;  ///< what the driver was given (first round)
};

/// How the plugin's projection (the hand-over's and the vertex stage's start) finishes: after
/// moving each plane's vertices onto their mean coordinate, the tetrahedra this folds are
/// untangled in vertex variables (untangle.h, Garanzha et al.'s regularized barrier) with each
/// plane one variable, as in the vertex stage, and the two outermost planes of each axis fixed
/// (with fewer, the untangling energy at its first, large eps shrinks the map towards a point);
/// the result is kept once it is inversion-free with every angle sum below its limit. The driver
/// then hands over a mesh whose charts the assembly has made nearly, not exactly, planar, instead
/// of assembling on.
struct PolycubePluginOptions {
    int untangle_iterations = 100;  ///< most Newton steps per projection; 0: no untangling
    double max_time = kInfinity;    ///< seconds from the plugin's creation; none after
    int threads = 0;                ///< 0 = all cores
    Logger logger;                  ///< one line per untangling
    /// Per plane (polycube_planes() numbering): where it is held, in the map's units. Empty: the
    /// planes move (as described above). Given: every plane stays at its coordinate, in the
    /// assembly (the offsets' right-hand sides), the projection, the untangling and the vertex
    /// stage; the quantized PolyCube of a hex mesh (frontends/hex/plane_quantization.h).
    std::vector<double> plane_coordinates;
};

/// The plugin of `prepared`'s PolyCube terms (see above). It refers to `prepared`, which must
/// outlive it. `angle_weight` multiplies the angle barriers. The assembly stage takes the
/// linear-part layout only (r-SA, f-SA).
std::shared_ptr<const AssemblyPlugin<3>> polycube_plugin(const PreparedPolycube& prepared,
                                                         double angle_weight = 1.0,
                                                         const PolycubePluginOptions& options = {});

/// The solve described above. Progress rows go to `logger`. Bad options throw
/// InvalidArgumentError; a finite `bound` below what the labels force
/// (prepared.angle_bound) throws NoSolutionError before any work; numerical outcomes are in the
/// result.
PolycubeSolve solve_polycube(const PreparedPolycube& prepared, const PolycubeSolveOptions& options,
                             const Logger& logger = {});

/// The same solve (steps 2 and 4; `options.optimal_bound` must be false) with every plane held at
/// `plane_coordinates` (per plane, polycube_planes() numbering, in the map's units), from `start`
/// (#V x 3, a map of prepared.mesh: a PolyCube whose planes were moved there, e.g. by
/// quantization, folded or not): its boundary vertices are put on their planes and the folds
/// untangled on them first. PolycubeSolve::start is `start`; the cube-cover time is 0.
PolycubeSolve solve_polycube_on_planes(const PreparedPolycube& prepared,
                                       const Eigen::MatrixXd& start,
                                       const std::vector<double>& plane_coordinates,
                                       const PolycubeSolveOptions& options,
                                       const Logger& logger = {});

}  // namespace sa
