#pragma once
// The planes and edges of a PolyCube labelling (issue 21; the paper's 5.3).
//
// Planes: charts of one axis that share a vertex lie in one plane (their common vertex has one
// coordinate along that axis), so a plane is a class of such charts. A boundary vertex lies on
// at most one plane per axis: on one (inside a chart), two (on a PolyCube edge) or three (at a
// corner).
//
// Edges: a PolyCube edge is a chain of boundary mesh edges between two planes of axes a != b; it
// runs along the third axis d and ends at two corners, vertices that lie on a plane of axis d.
// For the PolyCube to be valid, the chain must keep a positive length with its corners in their
// rest order along d: when the planes of its two corners swap or meet, the chain's tetrahedra
// fold whatever its vertices do (a vertex of the chain ends up beyond its corner). The cube-cover
// start (cube_cover.h) enforces these orders, which a least-squares fit alone does not.

#include <Eigen/Core>
#include <array>
#include <vector>

#include "frontends/polycube/polycube_labeling.h"

namespace sa {

struct PolycubePlanes {
    std::vector<int> plane_of_chart;  ///< per chart (PolycubeCharts numbering)
    std::vector<int> axis;            ///< per plane: 0, 1 or 2
    /// Per vertex, per axis: the plane of that axis through it, or -1 (#V entries).
    std::vector<std::array<int, 3>> plane_of_vertex;
    int size() const { return static_cast<int>(axis.size()); }
};

/// The planes of `charts` (a labelling of `boundary`, the boundary of a mesh of `num_vertices`
/// vertices). Throws InvalidArgumentError when `charts` does not belong to `boundary`.
PolycubePlanes polycube_planes(const TetBoundary& boundary, const PolycubeCharts& charts,
                               Index num_vertices);

/// One PolyCube edge with its corners in rest order: `from` comes first along `axis`.
struct PolycubeEdgeOrder {
    int axis = -1;                       ///< d, the axis the edge runs along
    Index from = -1, to = -1;            ///< its corner vertices
    int from_plane = -1, to_plane = -1;  ///< their planes of axis d (equal: the edge cannot exist)
    double rest_extent = 0.0;            ///< rest(to)_d - rest(from)_d, >= 0, in rest units
    Index mesh_edges = 0;                ///< boundary mesh edges in the chain
    /// The chain's vertices from `from` to `to` (mesh_edges + 1 of them).
    std::vector<Index> vertices;
};

/// Every PolyCube edge of `planes` that runs between two corners, with its rest order from
/// `rest` (#V x 3). A chain that closes on itself, or that branches or ends without reaching a
/// plane of its axis, has no corners to order and is left out.
std::vector<PolycubeEdgeOrder> polycube_edge_orders(const TetBoundary& boundary,
                                                    const PolycubeCharts& charts,
                                                    const PolycubePlanes& planes,
                                                    const Eigen::MatrixXd& rest);

}  // namespace sa
