#include "geometry/io/vtk_io.h"

#include "geometry/io/plugin_library.h"
#include "geometry/io/vtk_io_plugin.h"

namespace sa {

namespace {

const VtkIoFunctions& vtk_io() {
    return plugin_table<VtkIoFunctions>("sa_vtk_io", "sa_vtk_io_functions",
                                        "reading and writing VTK files (.vtk, .vtu)");
}

}  // namespace

void require_vtk_io() {
    vtk_io();
}

MeshFile read_vtu(const std::string& path) {
    return vtk_io().read_vtu(path);
}

void write_vtk(const std::string& path, const Eigen::MatrixXd& positions,
               const Eigen::MatrixXi& simplices, const std::vector<DataArray>& point_data,
               const std::vector<DataArray>& cell_data) {
    vtk_io().write_vtk(path, positions, simplices, point_data, cell_data);
}

void write_vtu(const std::string& path, const Eigen::MatrixXd& positions,
               const Eigen::MatrixXi& simplices, const std::vector<DataArray>& point_data,
               const std::vector<DataArray>& cell_data) {
    vtk_io().write_vtu(path, positions, simplices, point_data, cell_data);
}

}  // namespace sa
