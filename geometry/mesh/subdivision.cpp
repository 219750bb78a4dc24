#include "geometry/mesh/subdivision.h"

#include "geometry/io/openmesh_plugin.h"
#include "geometry/io/plugin_library.h"

namespace sa {

SimplicialMesh loop_subdivide(const SimplicialMesh& mesh, int levels) {
    return plugin_table<OpenMeshFunctions>("sa_openmesh", "sa_openmesh_functions",
                                           "Loop subdivision")
        .loop_subdivide(mesh, levels);
}

}  // namespace sa
