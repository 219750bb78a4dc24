#include "geometry/io/openmesh_io.h"

#include "geometry/io/openmesh_plugin.h"
#include "geometry/io/plugin_library.h"

namespace sa {

MeshFile read_stl(const std::string& path) {
    return plugin_table<OpenMeshFunctions>("sa_openmesh", "sa_openmesh_functions",
                                           "reading STL files")
        .read_stl(path);
}

}  // namespace sa
