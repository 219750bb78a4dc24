#include "geometry/subdivision.h"

#include "geometry/io/plugin_library.h"
#include "geometry/openmesh_plugin.h"

namespace sa {

SimplicialMesh loop_subdivide(const SimplicialMesh& mesh, int levels) {
    return plugin_table<OpenMeshFunctions>("sa_openmesh", "sa_openmesh_functions",
                                           "Loop subdivision")
        .loop_subdivide(mesh, levels);
}

}  // namespace sa
