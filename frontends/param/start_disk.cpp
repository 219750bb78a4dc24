#include "frontends/param/start_disk.h"

#include "geometry/mesh/boundary_loops.h"
#include "geometry/mesh/hole_filling.h"

namespace sa {

StartDisk start_disk(const SimplicialMesh& surface, const MeshTopology& topology,
                     const std::string& source) {
    StartDisk disk;
    disk.surface_vertices = surface.num_vertices();
    // The used vertices, in their order.
    std::vector<Index> index(surface.num_vertices(), -1);
    for (Index v = 0; v < surface.num_vertices(); ++v) {
        if (!topology.used_vertex[v]) {
            ++disk.unused_vertices;
            continue;
        }
        index[v] = Index(disk.surface_vertex.size());
        disk.surface_vertex.push_back(v);
    }
    SimplicialMesh used;
    used.vertices.resize(Index(disk.surface_vertex.size()), surface.vertices.cols());
    for (std::size_t k = 0; k < disk.surface_vertex.size(); ++k)
        used.vertices.row(Index(k)) = surface.vertices.row(disk.surface_vertex[k]);
    used.simplices = surface.simplices;
    for (Index f = 0; f < used.num_simplices(); ++f)
        for (int c = 0; c < 3; ++c) used.simplices(f, c) = int(index[surface.simplices(f, c)]);
    MeshTopology used_topology = disk.unused_vertices > 0 ? mesh_topology(used, source) : topology;
    if (boundary_loops(used, used_topology).size() > 1) {
        FilledHoles filled = fill_inner_holes(used, used_topology);
        disk.filled_holes = filled.holes;
        disk.mesh = std::move(filled.mesh);
        disk.topology = mesh_topology(disk.mesh, source);
        disk.surface_vertex.resize(disk.mesh.num_vertices(), -1);
    } else {
        disk.mesh = std::move(used);
        disk.topology = std::move(used_topology);
    }
    return disk;
}

Eigen::MatrixXd StartDisk::to_surface(const Eigen::MatrixXd& uv) const {
    Eigen::MatrixXd out(surface_vertices, uv.cols());
    Eigen::RowVectorXd sum = Eigen::RowVectorXd::Zero(uv.cols());
    Index used = 0;
    for (std::size_t k = 0; k < surface_vertex.size(); ++k) {
        if (surface_vertex[k] < 0) continue;
        out.row(surface_vertex[k]) = uv.row(Index(k));
        sum += uv.row(Index(k));
        ++used;
    }
    if (unused_vertices > 0) {
        std::vector<unsigned char> set(surface_vertices, 0);
        for (Index v : surface_vertex)
            if (v >= 0) set[v] = 1;
        for (Index v = 0; v < surface_vertices; ++v)
            if (!set[v]) out.row(v) = sum / double(std::max<Index>(used, 1));
    }
    return out;
}

}  // namespace sa
