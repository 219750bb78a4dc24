#include "frontends/output/iteration_recorder.h"

#include <Eigen/SVD>
#include <cstdio>
#include <filesystem>
#include <utility>

#include "frontends/output/map_output.h"
#include "geometry/io/atomic_file.h"
#include "geometry/io/vtk_io.h"
#include "optim/errors.h"

namespace sa {

namespace {

constexpr const char* kSeries = "assembly.pvd";

// det and the ratio of the largest to the smallest singular value of a D x D matrix (D = 2, 3).
template <int D>
std::pair<double, double> determinant_and_conformal(const Eigen::MatrixXd& dynamic) {
    const Eigen::Matrix<double, D, D> m = dynamic;
    const Eigen::Vector<double, D> sigma =
        Eigen::JacobiSVD<Eigen::Matrix<double, D, D>>(m).singularValues();
    return {m.determinant(), sigma(0) / sigma(D - 1)};
}

}  // namespace

IterationRecorder::IterationRecorder(std::string folder, const SimplicialMesh& mesh, bool overwrite)
    : folder_(std::move(folder)), mesh_(mesh) {
    std::error_code error;
    std::filesystem::create_directories(folder_, error);
    if (error || !std::filesystem::is_directory(folder_)) {
        throw InputError(folder_ + ": cannot create the recording folder (" + error.message() +
                         ")");
    }
    const auto series = std::filesystem::path(folder_) / kSeries;
    if (!overwrite && std::filesystem::exists(series)) {
        throw InputError(
            series.string() +
            " exists (an earlier recording); choose another folder or allow overwriting");
    }
}

void IterationRecorder::record(int iteration, const Eigen::MatrixXd& corners) {
    const int k = mesh_.simplex_dimension() + 1;
    const int d = static_cast<int>(corners.cols());
    const Index n = mesh_.num_simplices();
    Eigen::MatrixXi cells(n, k);
    for (Index s = 0; s < n; ++s) {
        for (int a = 0; a < k; ++a) cells(s, a) = static_cast<int>(k * s + a);
    }
    // Mean image of every vertex over its simplices, for the gap.
    Eigen::MatrixXd mean = Eigen::MatrixXd::Zero(mesh_.num_vertices(), d);
    Eigen::VectorXd count = Eigen::VectorXd::Zero(mesh_.num_vertices());
    for (Index s = 0; s < n; ++s) {
        for (int a = 0; a < k; ++a) {
            mean.row(mesh_.simplices(s, a)) += corners.row(k * s + a);
            count(mesh_.simplices(s, a)) += 1.0;
        }
    }
    for (Index v = 0; v < mesh_.num_vertices(); ++v) {
        if (count(v) > 0) mean.row(v) /= count(v);
    }
    DataArray det{"det_J", Eigen::MatrixXd(n, 1)}, conformal{"conformal", Eigen::MatrixXd(n, 1)},
        gap{"gap", Eigen::MatrixXd(n, 1)};
    for (Index s = 0; s < n; ++s) {
        Eigen::MatrixXd rest(d, d), image(d, d);
        for (int a = 0; a < d; ++a) {
            image.col(a) = (corners.row(k * s + a + 1) - corners.row(k * s)).transpose();
        }
        const auto [determinant, ratio] =
            d == 2 ? determinant_and_conformal<2>(image) : determinant_and_conformal<3>(image);
        det.values(s) = determinant;
        conformal.values(s) = ratio;
        double g = 0.0;
        for (int a = 0; a < k; ++a)
            g = std::max(g, (corners.row(k * s + a) - mean.row(mesh_.simplices(s, a))).norm());
        gap.values(s) = g;
    }
    char name[64];
    std::snprintf(name, sizeof name, "iteration_%04d.vtu", iteration);
    write_vtu((std::filesystem::path(folder_) / name).string(), corners, cells, {},
              {det, conformal, gap});
    files_.push_back(name);
}

std::string IterationRecorder::finish() {
    const std::string path = (std::filesystem::path(folder_) / kSeries).string();
    AtomicFile file(path);
    std::ostream& out = file.stream();
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  "
           "<Collection>\n";
    for (std::size_t i = 0; i < files_.size(); ++i) {
        out << "    <DataSet timestep=\"" << i << "\" group=\"\" part=\"0\" file=\"" << files_[i]
            << "\"/>\n";
    }
    out << "  </Collection>\n</VTKFile>\n";
    file.commit();
    return path;
}

}  // namespace sa
