#pragma once
// The paper's Figure 2 as a ParaView time series: the disassembled simplices at every iteration,
// each on its own corners, one .vtu per iteration and a .pvd listing them (ParaView plays it).
//
//   IterationRecorder recorder(folder, mesh);       // creates the folder if needed
//   observer.snapshot = recorder.callback();         // SimplexAssemblyObserver
//   ... run ...
//   recorder.finish();                               // writes assembly.pvd
//
// Cell data per simplex: det_J (det A_i), conformal (delta_con), gap (the largest distance from
// one of its corners to the mean image of that vertex over all simplices: 0 once assembled).
// Files already in the folder with these names are replaced only when `overwrite` is set.

#include <functional>
#include <string>
#include <vector>

#include "geometry/mesh/simplicial_mesh.h"

namespace sa {

class IterationRecorder {
  public:
    /// Throws InputError when the folder cannot be created, or when it already holds a recording
    /// and `overwrite` is false.
    IterationRecorder(std::string folder, const SimplicialMesh& mesh, bool overwrite);

    void record(int iteration, const Eigen::MatrixXd& corners);
    std::function<void(int, const Eigen::MatrixXd&)> callback() {
        return
            [this](int iteration, const Eigen::MatrixXd& corners) { record(iteration, corners); };
    }
    /// Writes the .pvd; returns its path.
    std::string finish();
    int frames() const { return static_cast<int>(files_.size()); }

  private:
    std::string folder_;
    const SimplicialMesh& mesh_;
    std::vector<std::string> files_;
};

}  // namespace sa
