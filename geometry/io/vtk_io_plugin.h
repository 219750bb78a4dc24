#pragma once
// The table of VTK file functions that the plugin libsa_vtk_io.so exports
// (geometry/io/vtk_io_plugin.cpp, linked with VTK); geometry/io/vtk_io.cpp forwards the functions
// of vtk_io.h to it, loading the plugin on first use (geometry/io/plugin_library.h).

#include "geometry/io/vtk_io.h"

namespace sa {

/// Legacy .vtk files are read without VTK (geometry/io/legacy_vtk_reader.cpp), not through here.
struct VtkIoFunctions {
    decltype(&sa::read_vtu) read_vtu;
    decltype(&sa::write_vtk) write_vtk;
    decltype(&sa::write_vtu) write_vtu;
};

}  // namespace sa

/// The plugin's entry point: a table valid for the life of the process.
extern "C" const sa::VtkIoFunctions* sa_vtk_io_functions();
