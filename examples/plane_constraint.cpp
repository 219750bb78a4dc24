// A user's own linear assembly constraint: the bottom face of a cube slides on its plane while the
// top face is pushed down and sideways (the initial map folds the top layer). Each bottom edge
// (a, b) gets the row n . (f(b) - f(a)) = 0, n = (0, 0, 1); one bottom vertex is a handle, so the
// plane stays z = 0. The result is verified from its vertex positions.
#include <cmath>
#include <iostream>

#include "frontends/simplex_assembly/map_solve.h"
#include "geometry/mesh/mesh_generators.h"
#include "geometry/mesh/mesh_topology.h"

int main() {
    sa::MappingProblem problem;
    problem.mesh = sa::grid_tetrahedra(4, 4, 4);  // the unit cube
    const Eigen::MatrixXd& rest = problem.mesh.vertices;
    problem.initial = rest;
    problem.handles.push_back(0);  // the corner (0, 0, 0) stays
    for (sa::Index v = 0; v < rest.rows(); ++v) {
        if (rest(v, 2) == 1.0) {  // the top face goes down through the layer below it
            problem.handles.push_back(v);
            problem.initial.row(v) += Eigen::RowVector3d(0.3, 0.0, -0.4);
        }
    }
    for (const auto& [a, b] : sa::mesh_topology(problem.mesh, "cube").edges) {
        if (rest(a, 2) == 0.0 && rest(b, 2) == 0.0)
            problem.constraints.push_back({a, b, Eigen::Vector3d(0.0, 0.0, 1.0), 0.0});
    }

    const sa::SimplexAssemblyResult r =
        sa::run_simplex_assembly(problem, sa::SimplexAssemblyOptions{});
    double off_plane = 0.0;
    for (sa::Index v = 0; v < rest.rows(); ++v)
        if (rest(v, 2) == 0.0) off_plane = std::max(off_plane, std::abs(r.positions(v, 2)));
    std::cout << r.message << "\nbottom vertices: largest |z| " << off_plane << "\n";
    return r.initial_quality.inverted > 0 && r.success && off_plane <= 1e-12 ? 0 : 1;
}
