#pragma once
// The files of a PolyCube map (issue 21), from the prepared input and the output positions:
//   OUT.mesh        the mapped tetrahedral mesh (Medit), one row per vertex of the rest mesh;
//   OUT.rest.mesh   beside it: the rest mesh, i.e. the input after the splits, with the same
//                   vertices and tetrahedra in the same order, so that any checker can compare
//                   the two (../shared/tools/check_map.py --rest OUT.rest.mesh --map OUT.mesh);
//   OUT.flags       one label per tet facet, in ultimaille's facet order (S1.flags' layout) and
//                   in the input file's sign convention (PreparedPolycube::output_sign), so that
//                   hex meshers that read S1.mesh with S1.flags read the output the same way;
//   a .vtu/.vtk     the mapped mesh with cell data det_J, conformal, isometric, volumetric
//                   (delta_con, delta_iso, delta_vol after scaling to the input's volume; -1 where
//                   undefined), inverted, and facet_labels (4 integers per tetrahedron, as in
//                   OUT.flags);
//   a .png          the PolyCube's surface coloured by the conformal distortion of the
//                   tetrahedron under each boundary triangle, from 1 to the 99th percentile
//                   (at least 2); inverted or degenerate ones in red.

#include <string>

#include "frontends/polycube/polycube_preparation.h"

namespace sa {

/// OUT.rest.mesh for OUT.mesh (the extension .mesh replaced by .rest.mesh).
std::string polycube_rest_path(const std::string& out);
/// OUT.flags for OUT.mesh.
std::string polycube_flags_path(const std::string& out);

/// Writes OUT.mesh alone: `positions` (#V x 3, a map of prepared.mesh, in its units) in the
/// input's units (PreparedPolycube::in_input_units).
void write_polycube_map(const std::string& out, const PreparedPolycube& prepared,
                        const Eigen::MatrixXd& positions);

/// Writes OUT.mesh, OUT.rest.mesh and OUT.flags, in the input's units. `positions` #V x 3, a map
/// of prepared.mesh in its units.
void write_polycube_meshes(const std::string& out, const PreparedPolycube& prepared,
                           const Eigen::MatrixXd& positions);

/// Writes the .vtu (or .vtk) described above, in the input's units; `verification` from
/// verify_polycube() on the same positions.
void write_polycube_vtu(const std::string& path, const PreparedPolycube& prepared,
                        const Eigen::MatrixXd& positions, const PolycubeVerification& verification);

/// Writes the picture described above, titled `title`.
void write_polycube_png(const std::string& path, const PreparedPolycube& prepared,
                        const Eigen::MatrixXd& positions, const PolycubeVerification& verification,
                        const std::string& title);

}  // namespace sa
