#include "geometry/mesh_generators.h"

#include <Eigen/LU>
#include <algorithm>
#include <array>

namespace sa {

SimplicialMesh grid_triangles(int nx, int ny) {
    SimplicialMesh mesh;
    mesh.vertices.resize((nx + 1) * (ny + 1), 2);
    for (int j = 0; j <= ny; ++j) {
        for (int i = 0; i <= nx; ++i)
            mesh.vertices.row(j * (nx + 1) + i) << double(i) / nx, double(j) / ny;
    }
    mesh.simplices.resize(2 * nx * ny, 3);
    int t = 0;
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            const int v = j * (nx + 1) + i;
            mesh.simplices.row(t++) << v, v + 1, v + nx + 2;
            mesh.simplices.row(t++) << v, v + nx + 2, v + nx + 1;
        }
    }
    return mesh;
}

SimplicialMesh grid_tetrahedra(int nx, int ny, int nz) {
    SimplicialMesh mesh;
    const double h = 1.0 / std::max({nx, ny, nz});
    auto index = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
    mesh.vertices.resize((nx + 1) * (ny + 1) * (nz + 1), 3);
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) mesh.vertices.row(index(i, j, k)) << i * h, j * h, k * h;
    // Kuhn: the six paths from corner 000 to 111 through the cube's axes.
    const std::array<std::array<int, 3>, 6> orders = {
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    mesh.simplices.resize(6 * nx * ny * nz, 4);
    int t = 0;
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
                for (const auto& order : orders) {
                    std::array<int, 3> c = {i, j, k};
                    std::array<int, 4> tet;
                    tet[0] = index(c[0], c[1], c[2]);
                    for (int step = 0; step < 3; ++step) {
                        ++c[order[step]];
                        tet[step + 1] = index(c[0], c[1], c[2]);
                    }
                    Eigen::Matrix3d e;
                    for (int a = 0; a < 3; ++a)
                        e.col(a) =
                            (mesh.vertices.row(tet[a + 1]) - mesh.vertices.row(tet[0])).transpose();
                    if (e.determinant() < 0) std::swap(tet[1], tet[2]);
                    mesh.simplices.row(t++) << tet[0], tet[1], tet[2], tet[3];
                }
    return mesh;
}

}  // namespace sa
