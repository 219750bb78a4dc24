#pragma once
// The Poisson step of seamless parameterization (the paper's 5.2, "Global seamless
// parameterizations"): given per face the target Jacobian A_f of the map (2 x 2, in the face's
// rest frame, rest_frames.h) — an integrable field after Simplex Assembly — find (u, v) per
// vertex of the cut mesh minimizing
//     sum_f area_f |J_f(u, v) - A_f|_F^2 + w^2 sum_{cut edges} |d_g - R_e d_f|^2,
// J_f the Jacobian of the piecewise linear map, d_f and d_g the images of the cut edge seen from
// its two faces (f = the facet's first simplex), R_e the rotation by -k quarter turns for the
// edge's matching k (cut_graph.h): across a seam the two charts differ by R_e and a free
// translation, so the map is seamless. The seams are a penalty (w = 1e4 relative to the faces'
// size); `max_seam_mismatch` reports how far from exact they end. One vertex per connected part
// of the cut mesh is fixed at the origin (the translations are free).
//
// Combing: the faces joined by uncut edges form one chart, so the targets are first turned by
// quarter turns, Rot(t_f) A_f, with t_f chosen breadth-first so that the matching of every uncut
// edge becomes 0 (a seam's becomes k + t_f - t_g). This is always possible when the cut passes
// through every singularity; otherwise InvalidArgumentError. The map's Jacobian on face f is then
// Rot(t_f) A_f: the same cross, its (u, v) axes possibly exchanged or reversed.

#include <vector>

#include "frontends/seamless/cut_graph.h"
#include "optim/types.h"

namespace sa {

struct SeamlessMap {
    CutMesh cut;                   ///< the mesh opened along the cut
    Eigen::MatrixXd uv;            ///< #cut vertices x 2
    std::vector<int> chart_turns;  ///< t_f per face, in {0, 1, 2, 3}
    double max_seam_mismatch =
        0.0;  ///< largest |d_g - R_e d_f| over the cut edges, over the mean edge length in (u, v)
};

SeamlessMap seamless_poisson(const SimplicialMesh& mesh, const MeshTopology& topology,
                             const std::vector<unsigned char>& cut,
                             const std::vector<int>& matching,
                             const std::vector<Mat<2>>& jacobians);

}  // namespace sa
