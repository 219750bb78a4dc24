#pragma once
// A PNG of a pose, the picture users look at before anything else: the deformed surface of a tet
// mesh (its boundary triangles at the mapped positions), or a planar triangle mesh seen from
// above, each face coloured by the isometric distortion max(sigma_max, 1 / sigma_min) of its
// simplex (viridis, with a colour bar), inverted simplices in red. When tetrahedra are inverted,
// every face of each inverted one is drawn and the surface is translucent, so that they show
// through it (a folded tetrahedron is often behind the surface, even one with a boundary facet);
// the title gives their number and the distortion.
// Rendered by write_surface_value_png (frontends/output/surface_value_picture.h).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "geometry/mesh/simplicial_mesh.h"

namespace sa {

struct PosePicture {
    /// A line at the top; empty: "<n> inverted of <m> tetrahedra; isometric max <a> mean <b>".
    std::string title;
    int width = 1600;  ///< pixels, in [16, 8192]
    int height = 1200;
    /// The view (vtk_scene.h); planar meshes are always seen from above.
    double azimuth = 30.0;
    double elevation = 25.0;
    /// The colour range of the isometric distortion: low (1, an isometry) to high, beyond which
    /// colours saturate; high <= low takes the 99th percentile of the drawn faces' values (at
    /// least low + 0.5).
    double low = 1.0;
    double high = 0.0;
    /// Opacity of the surface of a tet mesh with inverted (or marked) tetrahedra.
    double see_through_opacity = 0.3;
    /// Simplices drawn like the inverted ones although they are not (every facet of a
    /// tetrahedron, in red), e.g. those the start of a pose inverted; the default title then
    /// names them with `marked_label`.
    std::vector<Index> marked;
    std::string marked_label = "marked";
};

/// Writes `path`. `rest` is the rest mesh (planar triangles or tetrahedra), `positions` #V x d
/// the pose. Throws InvalidArgumentError on a mesh of another kind or positions of the wrong
/// shape; otherwise as write_surface_value_png (no display and no Xvfb, an unwritable file).
void write_pose_png(const std::string& path, const SimplicialMesh& rest,
                    const Eigen::MatrixXd& positions, const PosePicture& picture = {});

}  // namespace sa
