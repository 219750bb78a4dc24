#include "geometry/mesh/hole_filling.h"

#include <algorithm>

#include "geometry/mesh/boundary_loops.h"

namespace sa {

FilledHoles fill_inner_holes(const SimplicialMesh& mesh, const MeshTopology& topology) {
    FilledHoles filled;
    const std::vector<std::vector<Index>> loops = boundary_loops(mesh, topology);
    auto length = [&](const std::vector<Index>& loop) {
        double sum = 0.0;
        for (std::size_t k = 0; k < loop.size(); ++k)
            sum += (mesh.vertices.row(loop[(k + 1) % loop.size()]) - mesh.vertices.row(loop[k]))
                       .norm();
        return sum;
    };
    std::size_t outer = 0;
    for (std::size_t l = 1; l < loops.size(); ++l)
        if (length(loops[l]) > length(loops[outer])) outer = l;

    Index extra_vertices = 0, extra_triangles = 0;
    for (std::size_t l = 0; l < loops.size(); ++l) {
        if (l == outer) continue;
        ++extra_vertices;
        extra_triangles += Index(loops[l].size());
    }
    const Index nv = mesh.num_vertices(), nf = mesh.num_simplices();
    filled.mesh.vertices.resize(nv + extra_vertices, mesh.vertices.cols());
    filled.mesh.vertices.topRows(nv) = mesh.vertices;
    filled.mesh.simplices.resize(nf + extra_triangles, 3);
    filled.mesh.simplices.topRows(nf) = mesh.simplices;
    Index v = nv, f = nf;
    for (std::size_t l = 0; l < loops.size(); ++l) {
        if (l == outer) continue;
        const std::vector<Index>& loop = loops[l];
        Eigen::RowVectorXd centroid = Eigen::RowVectorXd::Zero(mesh.vertices.cols());
        for (Index u : loop) centroid += mesh.vertices.row(u);
        filled.mesh.vertices.row(v) = centroid / double(loop.size());
        // The loop follows its edges in the order of the triangles beside them: the fan takes
        // each edge the other way round, so that it is oriented like the surface.
        for (std::size_t k = 0; k < loop.size(); ++k)
            filled.mesh.simplices.row(f++) << loop[(k + 1) % loop.size()], loop[k], v;
        ++v;
        ++filled.holes;
    }
    return filled;
}

}  // namespace sa
