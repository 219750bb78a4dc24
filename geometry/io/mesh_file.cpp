#include "geometry/io/mesh_file.h"

#include "geometry/io/medit_io.h"
#include "geometry/io/obj_io.h"
#include "geometry/io/off_io.h"
#include "geometry/io/openmesh_io.h"
#include "geometry/io/ply_io.h"
#include "geometry/io/problem_io.h"
#include "geometry/io/tetgen_io.h"
#include "geometry/io/text_reader.h"
#include "geometry/io/vtk_io.h"
#include "optim/errors.h"

namespace sa {

void check_input_file(const std::string& path) {
    io::check_readable(path);
}

MeshFile read_mesh_file(const std::string& path) {
    const std::string extension = io::lower_extension(path);
    if (extension == ".obj") return read_obj(path);
    if (extension == ".off") return read_off(path);
    if (extension == ".ply") return read_ply(path);
    if (extension == ".stl") return read_stl(path);
    if (extension == ".vtk") return read_vtk(path);
    if (extension == ".vtu") return read_vtu(path);
    if (extension == ".mesh") return read_medit(path);
    if (extension == ".node" || extension == ".ele") return read_tetgen(path);
    return read_problem(path);
}

void write_mesh_file(const std::string& path, const Eigen::MatrixXd& positions,
                     const Eigen::MatrixXi& simplices) {
    const std::string extension = io::lower_extension(path);
    if (extension == ".vtu") return write_vtu(path, positions, simplices);
    if (extension == ".vtk") return write_vtk(path, positions, simplices);
    if (extension == ".obj") return write_obj(path, positions, simplices);
    if (extension == ".off") return write_off(path, positions, simplices);
    if (extension == ".mesh") return write_medit(path, positions, simplices);
    if (extension == ".node" || extension == ".ele")
        return write_tetgen(path, positions, simplices);
    if (extension == ".ply" || extension == ".stl")
        throw InvalidArgumentError("write_mesh_file: " + path + ": cannot write " + extension +
                                   " files; write .vtu, .vtk, .obj, .off, .mesh or .node");
    write_result_records(path, positions);
}

}  // namespace sa
