#pragma once
// Splits that let a PolyCube labelling be planar without squashing tetrahedra (issue 21's
// preprocessing). Planarity puts every vertex of a chart on its chart's plane, so:
//   - a tetrahedron whose four vertices lie on one chart becomes flat;
//   - an interior edge whose two ends lie on one chart lies in that plane, and the tetrahedra
//     around it, which are on one side of the plane only, are flattened along it;
//   - a boundary edge whose two ends lie on a chart that does not contain it, and a boundary
//     triangle whose three vertices lie on another chart than its own, are squeezed to a point
//     or a segment (the intersection of two or three planes);
//   - any other tetrahedron whose vertices the planes hold so that it is flat for every position
//     of the planes and of the free coordinates (two vertices on each of two parallel lines where
//     two planes meet, three on one such line, ...): tested exactly, by its determinant at
//     random integer samples. Its split is the first of its facets (at the centroid) or interior
//     edges (at the midpoint) after which no child is flat.
// Each is split so that the offending element gets a vertex that is not on that chart: interior
// and boundary edges at their midpoints (every tetrahedron around the edge in two), boundary
// triangles and, for a tetrahedron, one of its interior facets at their centroids (the one or two
// tetrahedra on the facet in three). New vertices lie on the charts of the split element only
// (none for interior ones). Every child keeps its parent's orientation.
//
// Numbering: vertices are appended; a split tetrahedron keeps its index for its first child and
// the others are appended, so an unsplit tetrahedron keeps its index. Labels are per tet facet
// (4 per tetrahedron, -1 on interior facets, frontends/polycube/polycube_labeling.h's 0..5
// otherwise), and follow the splits: a child facet inside a parent facet takes its label, new
// facets are interior.

#include <vector>

#include "frontends/polycube/polycube_labeling.h"

namespace sa {

struct SquashedElements {
    Index tets = 0;                ///< tetrahedra with their four vertices on one chart
    Index interior_edges = 0;      ///< interior edges with both ends on one chart
    Index boundary_edges = 0;      ///< boundary edges with both ends on a chart not containing them
    Index boundary_triangles = 0;  ///< boundary triangles with their vertices on another chart
    /// Other tetrahedra that the planes flatten whatever the solve does (two vertices on each of
    /// two parallel PolyCube edges, three on one edge, ...; the planes: charts of one axis that
    /// share a vertex are one plane).
    Index flattened_tets = 0;
    Index total() const {
        return tets + interior_edges + boundary_edges + boundary_triangles + flattened_tets;
    }
};

/// Counts the elements above for `facet_labels` (4 #T entries: -1 or 0..5).
SquashedElements count_squashed_elements(const SimplicialMesh& mesh,
                                         const std::vector<int>& facet_labels);

struct PolycubeSplitReport {
    SquashedElements before;
    /// All zero on success; flattened tetrahedra that no split repairs stay here.
    SquashedElements after;
    /// Those tetrahedra (indices in the split mesh): flat in every map whose charts are planar,
    /// so the labels admit no valid PolyCube map of this mesh.
    std::vector<Index> flat_tets;
    Index edge_splits = 0;  ///< interior and boundary edges split
    Index face_splits = 0;  ///< boundary triangles and interior facets split
    Index vertices_added = 0;
    Index tets_added = 0;
};

/// Splits every squashed element of `mesh` (tetrahedra in 3D), updating `facet_labels` (4 #T
/// entries) to the new tetrahedra. Throws InputError `SOURCE: ...` for a squashed tetrahedron
/// without an interior facet (a tetrahedron on its own), which no split can repair.
PolycubeSplitReport split_squashed_elements(SimplicialMesh& mesh, std::vector<int>& facet_labels,
                                            const std::string& source);

}  // namespace sa
