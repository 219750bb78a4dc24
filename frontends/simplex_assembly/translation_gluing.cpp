#include "frontends/simplex_assembly/translation_gluing.h"

#include <queue>

namespace sa {

template <int D>
std::vector<Vec<D>> glue_translations(const SimplicialMesh& mesh, const MeshTopology& topology,
                                      const RestFrames<D>& frames, const std::vector<Mat<D>>& A,
                                      const std::vector<std::pair<Index, Vec<D>>>& known,
                                      const std::vector<Vec<D>>& fallback) {
    const Index n = mesh.num_simplices();
    std::vector<Vec<D>> T(n, Vec<D>::Zero());
    std::vector<unsigned char> placed(n, 0);
    std::queue<Index> queue;
    for (const auto& [s, t] : known) {
        if (placed[s]) continue;
        T[s] = t;
        placed[s] = 1;
        queue.push(s);
    }
    // The local index of vertex v in simplex s.
    auto local = [&](Index s, Index v) {
        for (int k = 0; k <= D; ++k) {
            if (mesh.simplices(s, k) == v) return k;
        }
        return -1;
    };
    auto spread = [&] {
        while (!queue.empty()) {
            const Index i = queue.front();
            queue.pop();
            for (int o = 0; o <= D; ++o) {
                const Index j = topology.neighbour_of(i, o);
                if (j < 0 || placed[j]) continue;
                Vec<D> sum = Vec<D>::Zero();
                for (int k = 0; k <= D; ++k) {
                    if (k == o) continue;
                    const Index v = mesh.simplices(i, k);
                    sum += A[i] * frames.corner(i, k) + T[i] - A[j] * frames.corner(j, local(j, v));
                }
                T[j] = sum / double(D);
                placed[j] = 1;
                queue.push(j);
            }
        }
    };
    spread();
    for (Index s = 0; s < n; ++s) {
        if (placed[s]) continue;
        T[s] = fallback[s];
        placed[s] = 1;
        queue.push(s);
        spread();
    }
    return T;
}

template std::vector<Vec<2>> glue_translations<2>(const SimplicialMesh&, const MeshTopology&,
                                                  const RestFrames<2>&, const std::vector<Mat<2>>&,
                                                  const std::vector<std::pair<Index, Vec<2>>>&,
                                                  const std::vector<Vec<2>>&);
template std::vector<Vec<3>> glue_translations<3>(const SimplicialMesh&, const MeshTopology&,
                                                  const RestFrames<3>&, const std::vector<Mat<3>>&,
                                                  const std::vector<std::pair<Index, Vec<3>>>&,
                                                  const std::vector<Vec<3>>&);

}  // namespace sa
