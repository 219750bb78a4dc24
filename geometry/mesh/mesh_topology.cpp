#include "geometry/mesh/mesh_topology.h"

#include <algorithm>
#include <numeric>
#include <sstream>

#include "optim/errors.h"

namespace sa {

namespace {
struct FacetKey {
    std::array<Index, 3> vertices;
    Index simplex;
    int opposite;
    bool operator<(const FacetKey& o) const {
        return vertices != o.vertices ? vertices < o.vertices : simplex < o.simplex;
    }
};
}  // namespace

MeshTopology mesh_topology(const SimplicialMesh& mesh, const std::string& source) {
    MeshTopology t;
    const int d = mesh.simplex_dimension();
    const int k = d + 1;
    const Index n = mesh.num_simplices();
    const Index nv = mesh.num_vertices();
    t.dimension = d;

    std::vector<FacetKey> facets;
    facets.reserve(std::size_t(n) * k);
    for (Index s = 0; s < n; ++s) {
        for (int o = 0; o < k; ++o) {
            FacetKey f{{-1, -1, -1}, s, o};
            int m = 0;
            for (int a = 0; a < k; ++a) {
                if (a != o) f.vertices[m++] = mesh.simplices(s, a);
            }
            auto order = [&](int a, int b) {
                if (f.vertices[b] < f.vertices[a]) std::swap(f.vertices[a], f.vertices[b]);
            };
            // The first d vertices in increasing order.
            if (d >= 2) order(0, 1);
            if (d >= 3) order(1, 2), order(0, 1);
            facets.push_back(f);
        }
    }
    // Bucketed by their smallest vertex, each bucket sorted: the order of one global sort of the
    // keys (several times faster on a million simplices, where a comparison sort of the keys was
    // most of this function).
    {
        std::vector<Index> begin(std::size_t(nv) + 1, 0);
        for (const FacetKey& f : facets) ++begin[f.vertices[0] + 1];
        std::partial_sum(begin.begin(), begin.end(), begin.begin());
        std::vector<FacetKey> bucketed(facets.size());
        std::vector<Index> cursor(begin.begin(), begin.end() - 1);
        for (const FacetKey& f : facets) bucketed[cursor[f.vertices[0]]++] = f;
        facets = {};
        for (Index v = 0; v < nv; ++v) {  // a few keys each: insertion sort
            for (Index i = begin[v] + 1; i < begin[v + 1]; ++i) {
                const FacetKey key = bucketed[i];
                Index j = i;
                for (; j > begin[v] && key < bucketed[j - 1]; --j) bucketed[j] = bucketed[j - 1];
                bucketed[j] = key;
            }
        }
        facets.swap(bucketed);
    }
    t.neighbour.assign(std::size_t(n) * k, -1);
    for (std::size_t i = 0; i < facets.size();) {
        std::size_t j = i + 1;
        while (j < facets.size() && facets[j].vertices == facets[i].vertices) ++j;
        if (j - i == 1) {
            t.boundary_facets.push_back(
                {facets[i].simplex, facets[i].opposite, facets[i].vertices});
        } else if (j - i == 2) {
            const FacetKey &a = facets[i], &b = facets[i + 1];
            t.interior_facets.push_back(
                {{a.simplex, b.simplex}, {a.opposite, b.opposite}, a.vertices});
            t.neighbour[std::size_t(a.simplex) * k + a.opposite] = b.simplex;
            t.neighbour[std::size_t(b.simplex) * k + b.opposite] = a.simplex;
        } else {
            std::ostringstream msg;
            msg << source << ": the mesh is not manifold: " << (d == 2 ? "edge (" : "triangle (");
            for (int a = 0; a < d; ++a) msg << (a ? ", " : "") << facets[i].vertices[a];
            msg << ") is shared by " << (j - i) << " simplices (";
            for (std::size_t m = i; m < j; ++m) msg << (m > i ? ", " : "") << facets[m].simplex;
            msg << ")";
            throw InputError(msg.str());
        }
        i = j;
    }

    if (d == 2 && mesh.ambient_dimension() == 3) {
        // Consistent orientation: a shared edge runs in opposite directions in its two triangles.
        auto runs_forward = [&](Index s, Index a, Index b) {
            for (int c = 0; c < 3; ++c) {
                if (mesh.simplices(s, c) == a && mesh.simplices(s, (c + 1) % 3) == b) return true;
            }
            return false;
        };
        for (const InteriorFacet& f : t.interior_facets) {
            const Index a = f.vertices[0], b = f.vertices[1];
            if (runs_forward(f.simplex[0], a, b) == runs_forward(f.simplex[1], a, b)) {
                std::ostringstream msg;
                msg << source << ": triangles " << f.simplex[0] << " and " << f.simplex[1]
                    << " are oriented inconsistently across edge (" << a << ", " << b << ")";
                throw InputError(msg.str());
            }
        }
    }

    t.boundary_vertex.assign(nv, 0);
    for (const BoundaryFacet& f : t.boundary_facets) {
        for (int a = 0; a < d; ++a) t.boundary_vertex[f.vertices[a]] = 1;
    }
    t.used_vertex.assign(nv, 0);
    t.vertex_begin.assign(nv + 1, 0);
    for (Index s = 0; s < n; ++s) {
        for (int a = 0; a < k; ++a) {
            t.used_vertex[mesh.simplices(s, a)] = 1;
            ++t.vertex_begin[mesh.simplices(s, a) + 1];
        }
    }
    std::partial_sum(t.vertex_begin.begin(), t.vertex_begin.end(), t.vertex_begin.begin());
    t.simplices_of_vertex.resize(t.vertex_begin[nv]);
    std::vector<Index> cursor(t.vertex_begin.begin(), t.vertex_begin.end() - 1);
    for (Index s = 0; s < n; ++s) {
        for (int a = 0; a < k; ++a) t.simplices_of_vertex[cursor[mesh.simplices(s, a)]++] = s;
    }

    // Edges: the larger ends of each vertex's edges to larger vertices, bucketed by the smaller
    // end (the simplices around each vertex), each bucket sorted and made unique.
    std::vector<Index> larger;
    for (Index u = 0; u < nv; ++u) {
        larger.clear();
        for (Index i = t.vertex_begin[u]; i < t.vertex_begin[u + 1]; ++i) {
            const Index s = t.simplices_of_vertex[i];
            for (int a = 0; a < k; ++a) {
                if (mesh.simplices(s, a) > u) larger.push_back(mesh.simplices(s, a));
            }
        }
        std::sort(larger.begin(), larger.end());
        larger.erase(std::unique(larger.begin(), larger.end()), larger.end());
        for (Index v : larger) t.edges.push_back({u, v});
    }
    return t;
}

std::vector<Index> MeshTopology::simplex_components(Index* count) const {
    const Index n = static_cast<Index>(neighbour.size() / (dimension + 1));
    std::vector<Index> component(n, -1);
    Index c = 0;
    std::vector<Index> stack;
    for (Index seed = 0; seed < n; ++seed) {
        if (component[seed] >= 0) continue;
        component[seed] = c;
        stack.push_back(seed);
        while (!stack.empty()) {
            const Index s = stack.back();
            stack.pop_back();
            for (int k = 0; k <= dimension; ++k) {
                const Index t = neighbour_of(s, k);
                if (t >= 0 && component[t] < 0) {
                    component[t] = c;
                    stack.push_back(t);
                }
            }
        }
        ++c;
    }
    if (count != nullptr) *count = c;
    return component;
}

namespace {

/// The number of pieces the simplices around `v` form through the facets that contain `v`.
/// `reached` (one flag per simplex, all 0) is left all 0 again.
int star_pieces(const SimplicialMesh& mesh, const MeshTopology& topology, Index v,
                std::vector<unsigned char>& reached) {
    const Index begin = topology.vertex_begin[v], end = topology.vertex_begin[v + 1];
    std::vector<Index> stack;
    int pieces = 0;
    for (Index i = begin; i < end; ++i) {
        const Index seed = topology.simplices_of_vertex[i];
        if (reached[seed]) continue;
        ++pieces;
        reached[seed] = 1;
        stack.push_back(seed);
        while (!stack.empty()) {
            const Index s = stack.back();
            stack.pop_back();
            for (int k = 0; k <= topology.dimension; ++k) {
                if (mesh.simplices(s, k) == v) continue;  // the facet opposite v: not through v
                const Index t = topology.neighbour_of(s, k);
                if (t >= 0 && !reached[t]) {
                    reached[t] = 1;
                    stack.push_back(t);
                }
            }
        }
    }
    for (Index i = begin; i < end; ++i) reached[topology.simplices_of_vertex[i]] = 0;
    return pieces;
}

}  // namespace

std::vector<Index> pinched_vertices(const SimplicialMesh& mesh, const MeshTopology& topology,
                                    int* first_pieces) {
    std::vector<Index> pinched;
    std::vector<unsigned char> reached(mesh.num_simplices(), 0);
    for (Index v = 0; v + 1 < Index(topology.vertex_begin.size()); ++v) {
        if (topology.vertex_begin[v + 1] - topology.vertex_begin[v] < 2) continue;
        const int pieces = star_pieces(mesh, topology, v, reached);
        if (pieces < 2) continue;
        if (pinched.empty() && first_pieces != nullptr) *first_pieces = pieces;
        pinched.push_back(v);
    }
    return pinched;
}

void require_no_pinched_vertex(const SimplicialMesh& mesh, const MeshTopology& topology,
                               const std::string& source, const std::string& needs) {
    int pieces = 0;
    const std::vector<Index> pinched = pinched_vertices(mesh, topology, &pieces);
    if (pinched.empty()) return;
    const bool triangles = topology.dimension == 2;
    const std::string others = pinched.size() == 1
                                   ? "the only one"
                                   : std::to_string(pinched.size() - 1) + " more such vertices";
    throw InputError(source + ": pinched at vertex " + std::to_string(pinched.front()) + ": its " +
                     (triangles ? "triangles" : "tetrahedra") + " form " + std::to_string(pieces) +
                     " pieces that share no " + (triangles ? "edge" : "face") + " through it (" +
                     others + "); " + needs);
}

}  // namespace sa
