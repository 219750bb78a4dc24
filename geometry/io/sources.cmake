# Sources of geometry/io, included by geometry/CMakeLists.txt.
set(SA_GEOMETRY_IO_SOURCES
    io/dmat_io.cpp
    io/frame_field_io.cpp
    io/index_list_io.cpp
    io/indexed_positions_io.cpp
    io/legacy_vtk_reader.cpp
    io/medit_io.cpp
    io/mesh_file.cpp
    io/obj_io.cpp
    io/off_io.cpp
    io/openmesh_io.cpp
    io/plugin_library.cpp
    io/ply_reader.cpp
    io/polycube_labels_io.cpp
    io/problem_io.cpp
    io/rawfield_io.cpp
    io/tetgen_io.cpp
    io/vtk_io.cpp
)
# Files written atomically, text parsing with file and line, write-side checks: shared by
# sa_geometry and the plugins.
set(SA_FILE_SUPPORT_SOURCES
    io/atomic_file.cpp
    io/byte_cursor.cpp
    io/text_reader.cpp
    io/vtk_cells.cpp
    io/write_checks.cpp
)
