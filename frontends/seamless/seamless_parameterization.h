#pragma once
// Seamless parameterization from a frame field (the paper's 5.2, "Global seamless
// parameterizations", Figure 12): the whole pipeline behind `sa seamless`.
//
//   1. the field phi: the input frames (frame_field.h), or the smoothest cross field
//      (cross_field.h) — boundary-aligned, and aligned with the input's vectors on the faces an
//      input gives when it leaves other faces free;
//   2. its singularities and matchings, and a cut graph through the singularities (cut_graph.h);
//   3. for comparison, the plain Poisson map of phi (seamless_poisson.h) and its foldovers;
//   4. the integrable field phi' by Simplex Assembly (integrable_field.h, Eq. 11), matchings fixed;
//   5. the Poisson map of phi', verified from its (u, v): inverted and degenerate faces (the rule
//      of map_quality.h), the largest seam mismatch, and its cone points — per interior vertex,
//      1 - (sum of its corner angles in (u, v)) / 2 pi — compared with the singularities of phi.
// Before step 2, a configuration of singularities that no seamless parameterization can have
// (cone_obstruction.h) stops the pipeline with `infeasible` set.
// Success: phi' assembled (sum curl^2 below tolerance), no inverted or degenerate face, seam
// mismatch within tolerance, and cone points exactly at phi's singularities with their indices
// (angle sums within cone_tolerance of quarter turns).
//
// Scale: the Jacobians of (u, v) are phi' / (mean row norm of phi) / H, so with a unit field one
// unit of u or v spans H in the mesh's length units. Edge curls are reported relative to the mean
// row norm of phi.

#include <optional>
#include <string>
#include <vector>

#include "frontends/seamless/cross_field.h"
#include "frontends/seamless/integrable_field.h"
#include "frontends/seamless/local_field_repair.h"
#include "frontends/seamless/seamless_poisson.h"
#include "geometry/quality/map_quality.h"

namespace sa {

/// Per-face vectors from a file (geometry/io/frame_field_io.h), or none.
struct FrameFieldInput {
    Eigen::MatrixXd u;                 ///< #F x 3
    Eigen::MatrixXd v;                 ///< #F x 3, or empty: a cross field (v = n x u)
    std::vector<unsigned char> given;  ///< #F; empty = every face given
};

struct SeamlessOptions {
    /// H, the mesh length per unit of (u, v); 0: 1/30 of the bounding-box diagonal.
    double scale = 0.0;
    /// Largest accepted seam mismatch (seamless_poisson.h) of the verified map.
    double seam_tolerance = 1e-6;
    /// Largest accepted distance, in radians, of a vertex's (u, v) angle sum from a multiple of
    /// pi / 2.
    double cone_tolerance = 1e-6;
    /// The field's assembly; its max_time_seconds is the wall-clock limit of the whole run (the
    /// assembly and the local repairs take what is left).
    IntegrableFieldOptions integrable;
    /// When the result does not verify, smooth the field's geometry locally and run again
    /// (local_field_repair.h, the paper's repair); the output keeps the input positions.
    bool local_repair = true;
};

struct CurlStats {
    double max = 0.0;
    double mean = 0.0;
};

/// One Poisson map and what was measured from its (u, v).
struct VerifiedSeamlessMap {
    SeamlessMap map;
    MapQuality quality;  ///< of the (u, v) map per face: inverted, degenerate, distortion
};

struct SeamlessResult {
    SimplicialMesh surface;    ///< the input mesh in space (a planar one with z = 0 added)
    std::string field_source;  ///< "file", "smoothest cross field" or "constrained cross field"
    double scale = 0.0;        ///< H used
    std::vector<Mat<2>> field_before, field_after;  ///< phi and phi' per face (rest frames)
    std::vector<Singularity> singularities_before;  ///< of phi (cross_field.h)
    std::vector<Singularity> singularities_after;   ///< cone points of the result's (u, v)
    double cone_deviation = 0.0;  ///< largest distance of an angle sum from a quarter turn, rad
    bool singularities_kept = false;
    /// The nearest-cross matchings of phi' (cut_graph.h) equal phi's everywhere. Informational:
    /// phi' may turn by more than 45 degrees across an edge near a singularity while its fixed
    /// matchings keep the singularities.
    bool matchings_kept = false;
    std::vector<int> matching;
    std::vector<unsigned char> cut;  ///< per interior facet
    Index cut_edges = 0;
    /// Per face, the largest relative curl of its interior edges.
    Eigen::VectorXd face_curl_before, face_curl_after;
    CurlStats curl_stats_before, curl_stats_after;
    VerifiedSeamlessMap plain;   ///< Poisson of phi
    VerifiedSeamlessMap result;  ///< Poisson of phi'
    IntegrableField integrable;
    /// The local repair, when the first result did not verify (repair.ran).
    FieldRepair repair;
    /// Why no seamless parameterization can have the field's singularities
    /// (cone_obstruction.h), when that is so: then nothing was optimized, `result` is empty and
    /// success is false.
    std::string infeasible;
    struct Times {
        double field = 0.0, cut = 0.0, plain_poisson = 0.0, integrable = 0.0, poisson = 0.0,
               verification = 0.0, total = 0.0;
    } times;
    bool success = false;
    std::string message;  ///< what was verified, in a sentence or two
};

/// What a pinched surface is refused with (mesh_topology.h, require_no_pinched_vertex).
inline constexpr const char* kSeamlessSurface =
    "a seamless parameterization needs a manifold surface (one fan of triangles around each "
    "vertex)";

/// `mesh`: a triangle mesh in space (#V x 3; a planar one gets z = 0), manifold (no pinched
/// vertex) and oriented. Throws InputError for a mesh or field that cannot be used (naming the
/// face or vertex).
SeamlessResult seamless_parameterization(const SimplicialMesh& mesh,
                                         const std::optional<FrameFieldInput>& field,
                                         const SeamlessOptions& options = {},
                                         const Logger& logger = {});

}  // namespace sa
