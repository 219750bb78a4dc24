#include "geometry/io/openmesh_plugin.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>

#include "geometry/io/openmesh_traits.h"
#include "optim/errors.h"

namespace sa {

namespace {
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<OpenMeshDoubleTraits>;
}  // namespace

SimplicialMesh loop_subdivide_with_openmesh(const SimplicialMesh& mesh, int levels) {
    if (mesh.simplex_dimension() != 2)
        throw InvalidArgumentError("loop_subdivide: needs a triangle mesh");
    if (levels < 0)
        throw InvalidArgumentError("loop_subdivide: levels = " + std::to_string(levels) +
                                   ", must be >= 0");
    if (levels == 0) return mesh;
    TriMesh om;
    std::vector<TriMesh::VertexHandle> handles;
    handles.reserve(mesh.num_vertices());
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        OpenMesh::Vec3d p(0.0, 0.0, 0.0);
        for (int c = 0; c < mesh.ambient_dimension(); ++c) p[c] = mesh.vertices(v, c);
        handles.push_back(om.add_vertex(p));
    }
    for (Index f = 0; f < mesh.num_simplices(); ++f) {
        const auto face = om.add_face(handles[mesh.simplices(f, 0)], handles[mesh.simplices(f, 1)],
                                      handles[mesh.simplices(f, 2)]);
        if (!face.is_valid()) {
            throw InputError("loop_subdivide: OpenMesh refused triangle " + std::to_string(f) +
                             " (non-manifold?)");
        }
    }
    OpenMesh::Subdivider::Uniform::LoopT<TriMesh> loop;
    loop.attach(om);
    loop(static_cast<std::size_t>(levels));
    loop.detach();
    SimplicialMesh out;
    out.vertices.resize(om.n_vertices(), mesh.ambient_dimension());
    for (const auto v : om.vertices()) {
        const OpenMesh::Vec3d p = om.point(v);
        for (int c = 0; c < mesh.ambient_dimension(); ++c) out.vertices(v.idx(), c) = p[c];
    }
    out.simplices.resize(om.n_faces(), 3);
    for (const auto f : om.faces()) {
        int k = 0;
        for (const auto v : om.fv_range(f)) out.simplices(f.idx(), k++) = v.idx();
    }
    return out;
}

}  // namespace sa
