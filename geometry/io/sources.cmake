# Sources of geometry/io, included by geometry/CMakeLists.txt.
set(SA_GEOMETRY_IO_SOURCES
    io/atomic_file.cpp
    io/dmat_io.cpp
    io/frame_field_io.cpp
    io/index_list_io.cpp
    io/medit_io.cpp
    io/mesh_file.cpp
    io/obj_io.cpp
    io/off_io.cpp
    io/openmesh_io.cpp
    io/problem_io.cpp
    io/tetgen_io.cpp
    io/text_reader.cpp
    io/vtk_capture.cpp
    io/vtk_io.cpp
    io/write_checks.cpp
)
