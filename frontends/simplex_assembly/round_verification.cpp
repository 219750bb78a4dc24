#include "frontends/simplex_assembly/detail/round_verification.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "energies/distortion.h"
#include "geometry/mesh/submesh.h"
#include "geometry/quality/local_injectivity.h"
#include "optim/errors.h"

namespace sa {

template <int D>
void verify_changes(const PreparedProblem<D>& p, const SimplexAssemblyOptions& options,
                    SimplexAssemblyResult& result, VerifiedMap& state) {
    if constexpr (D != 2) {
        throw InvalidArgumentError("verify_changes: triangle meshes only");
    } else {
        const MappingProblem& input = *p.input;
        const SimplicialMesh& original = input.mesh;
        const MeshTopology& topology = p.topology;
        const Index n = original.num_simplices(), nv = original.num_vertices();
        const Eigen::MatrixXd& x = result.positions;
        std::vector<const SimplexTerm<D>*> own;
        for (const auto& base : input.energies) {
            const auto& energy = static_cast<const SimplexTerm<D>&>(*base);
            if (energy.bounds_a_distortion()) own.push_back(&energy);
        }
        const bool whole = state.positions.rows() != nv || state.bounds.size() != own.size();
        if (whole) {
            // As verify_result(): both sides scaled by the power of two nearest the rest
            // diagonal's inverse.
            state.unit = std::ldexp(1.0, -scale_exponent(original.vertices));
            SimplicialMesh scaled = original;
            scaled.vertices *= state.unit;
            state.frames = rest_frames<D>(scaled);
            state.det.assign(n, 0.0);
            state.distortion.assign(n, 0.0);
            state.bounds.assign(own.size(), std::vector<double>(n, 0.0));
            state.branched.assign(nv, 0);
        }
        // The simplices with a vertex that moved, and the vertices of those simplices.
        std::vector<Index> touched;
        std::vector<Index> vertices;
        if (whole) {
            touched.resize(n);
            for (Index s = 0; s < n; ++s) touched[s] = s;
        } else {
            std::vector<unsigned char> moved(nv, 0), mark(n, 0);
            for (Index v = 0; v < nv; ++v) {
                if (!topology.used_vertex[v] || x.row(v) == state.positions.row(v)) continue;
                moved[v] = 1;
                for (Index i = topology.vertex_begin[v]; i < topology.vertex_begin[v + 1]; ++i)
                    mark[topology.simplices_of_vertex[i]] = 1;
            }
            for (Index s = 0; s < n; ++s)
                if (mark[s]) touched.push_back(s);
        }
        const Eigen::MatrixXd scaled_x = x.leftCols(D) * state.unit;
        tbb::parallel_for(Index(0), Index(touched.size()), [&](Index i) {
            const Index s = touched[i];
            Eigen::Matrix<double, D, D + 1> corners;
            for (int k = 0; k <= D; ++k)
                corners.col(k) = scaled_x.row(original.simplices(s, k)).transpose();
            const Mat<D> A = linear_part<D>(state.frames, s, corners);
            state.det[s] = A.determinant();
            const MatrixInvariants<double> m = matrix_invariants<D>(A, false);
            state.distortion[s] =
                m.J > 0.0 ? distortion<D>(options.distortion, m, options.gamma) : kInfinity;
            for (std::size_t k = 0; k < own.size(); ++k)
                state.bounds[k][s] = own[k]->max_distortion(std::vector<Mat<D>>{A});
        });
        // Branch points: every vertex whose star changed is a vertex of a touched simplex, and
        // its whole star lies within one ring of them.
        if (whole) {
            for (Index v : branched_vertices(original, topology, x)) state.branched[v] = 1;
        } else if (!touched.empty()) {
            const Submesh ring =
                extract_submesh(original, topology, grow_rings(original, topology, touched, 1));
            const MeshTopology ring_topology = mesh_topology(ring.mesh, input.source);
            Eigen::MatrixXd ring_x(ring.vertices.size(), x.cols());
            for (std::size_t i = 0; i < ring.vertices.size(); ++i)
                ring_x.row(i) = x.row(ring.vertices[i]);
            std::vector<unsigned char> in_touched(nv, 0);
            for (Index s : touched)
                for (int k = 0; k <= D; ++k) in_touched[original.simplices(s, k)] = 1;
            std::vector<unsigned char> branched(ring.vertices.size(), 0);
            for (Index i : branched_vertices(ring.mesh, ring_topology, ring_x)) branched[i] = 1;
            for (std::size_t i = 0; i < ring.vertices.size(); ++i) {
                const Index v = ring.vertices[i];
                if (in_touched[v]) state.branched[v] = branched[i];
            }
        }
        state.positions = x;

        Verification& v = result.verification;
        v = Verification{};
        v.simplices = n;
        // map_quality()'s rule: degenerate when det is not finite or |det| vol is at most 1e-14
        // of the largest.
        double largest = 0.0;
        for (Index s = 0; s < n; ++s) {
            if (std::isfinite(state.det[s]))
                largest = std::max(largest, std::abs(state.det[s]) * state.frames.volume[s]);
        }
        for (Index s = 0; s < n; ++s) {
            const double det = state.det[s];
            const bool degenerate =
                !std::isfinite(det) || std::abs(det) * state.frames.volume[s] <= 1e-14 * largest;
            v.degenerate += degenerate;
            v.inverted += std::isfinite(det) && det < 0.0;
            v.max_distortion = std::max(v.max_distortion, state.distortion[s]);
        }
        if (v.inverted == 0 && v.degenerate == 0) {
            for (Index u = 0; u < nv; ++u) v.branched += state.branched[u];
        }
        verify_handles<D>(input, options, x, v);
        v.bound = options.builtin_energy ? options.bound : kInfinity;
        for (std::size_t k = 0; k < own.size(); ++k) {
            v.bounds.push_back({own[k]->name(), own[k]->bound(),
                                *std::max_element(state.bounds[k].begin(), state.bounds[k].end())});
        }
        v.constraints = static_cast<Index>(input.constraints.size());
        v.constraint_tolerance = v.handle_tolerance;
        for (const EdgeConstraint& c : input.constraints) {
            const double length = c.normal.norm();
            const Eigen::VectorXd edge = (x.row(c.b) - x.row(c.a)).head(D).transpose();
            v.constraint_error = std::max(v.constraint_error,
                                          std::abs(c.normal.dot(edge) / length - c.value / length));
        }
        result.final_quality = MapQuality{};
        result.success = v.passed();
    }
}

template void verify_changes<2>(const PreparedProblem<2>&, const SimplexAssemblyOptions&,
                                SimplexAssemblyResult&, VerifiedMap&);
template void verify_changes<3>(const PreparedProblem<3>&, const SimplexAssemblyOptions&,
                                SimplexAssemblyResult&, VerifiedMap&);

}  // namespace sa
