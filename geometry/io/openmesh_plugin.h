#pragma once
// The table of OpenMesh-backed functions that the plugin libsa_openmesh.so exports
// (geometry/io/openmesh_plugin.cpp and geometry/mesh/subdivision_plugin.cpp, linked with OpenMesh);
// geometry/io/openmesh_io.cpp and geometry/mesh/subdivision.cpp forward to it, loading the plugin
// on first use (geometry/io/plugin_library.h): linked into every program, libOpenMeshCore.so's
// relocations and static initializers cost each start (docs/measurements.md).

#include "geometry/io/openmesh_io.h"
#include "geometry/mesh/subdivision.h"

namespace sa {

struct OpenMeshFunctions {
    decltype(&sa::read_stl) read_stl;
    decltype(&sa::loop_subdivide) loop_subdivide;
};

/// loop_subdivide() of geometry/mesh/subdivision.h, in the plugin.
SimplicialMesh loop_subdivide_with_openmesh(const SimplicialMesh& mesh, int levels);

}  // namespace sa

/// The plugin's entry point: a table valid for the life of the process.
extern "C" const sa::OpenMeshFunctions* sa_openmesh_functions();
