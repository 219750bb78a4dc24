#include "frontends/output/map_output.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "geometry/io/mesh_file.h"

namespace sa {

std::vector<DataArray> quality_cell_data(const MapQuality& quality) {
    const Index n = static_cast<Index>(quality.per_simplex.size());
    DataArray det{"det_J", Eigen::MatrixXd(n, 1)}, conformal{"conformal", Eigen::MatrixXd(n, 1)},
        isometric{"isometric", Eigen::MatrixXd(n, 1)},
        volumetric{"volumetric", Eigen::MatrixXd(n, 1)},
        inverted{"inverted", Eigen::MatrixXd(n, 1), true};
    for (Index s = 0; s < n; ++s) {
        const SimplexQuality& q = quality.per_simplex[s];
        auto defined = [](double v) { return std::isfinite(v) ? v : -1.0; };
        det.values(s) = defined(q.det);
        conformal.values(s) = defined(q.conformal);
        isometric.values(s) = defined(q.isometric);
        volumetric.values(s) = defined(q.volumetric);
        inverted.values(s) = q.inverted ? 1.0 : 0.0;
    }
    return {det, conformal, isometric, volumetric, inverted};
}

void write_map_result(const std::string& path, const MappingProblem& problem,
                      const SimplexAssemblyResult& result) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (ext != ".vtu" && ext != ".vtk") {
        write_mesh_file(path, result.positions, problem.mesh.simplices);
        return;
    }
    const Index nv = problem.mesh.num_vertices();
    const Index d = result.positions.cols();
    auto padded = [&](const Eigen::MatrixXd& m) {
        Eigen::MatrixXd out = Eigen::MatrixXd::Zero(m.rows(), 3);
        out.leftCols(m.cols()) = m;
        return out;
    };
    std::vector<DataArray> point_data;
    if (problem.mesh.ambient_dimension() == d) {
        point_data.push_back({"displacement", padded(result.positions - problem.mesh.vertices)});
    }
    point_data.push_back({"change", padded(result.positions - problem.initial.leftCols(d))});
    DataArray handle{"handle", Eigen::MatrixXd::Zero(nv, 1), true};
    for (Index h : problem.handles) handle.values(h) = 1.0;
    point_data.push_back(handle);
    const std::vector<DataArray> cell_data = quality_cell_data(result.final_quality);
    if (ext == ".vtu") {
        write_vtu(path, result.positions, problem.mesh.simplices, point_data, cell_data);
    } else {
        write_vtk(path, result.positions, problem.mesh.simplices, point_data, cell_data);
    }
}

}  // namespace sa
