#include "frontends/polycube/polycube_labeling.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "optim/errors.h"

namespace sa {

Eigen::Vector3d label_direction(int label) {
    Eigen::Vector3d d = Eigen::Vector3d::Zero();
    d[label_axis(label)] = label_sign(label);
    return d;
}

std::string label_name(int label) {
    if (label < 0 || label > 5) return "none";
    return std::string(label_sign(label) > 0 ? "+" : "-") + "XYZ"[label_axis(label)];
}

std::string describe_boundary_triangle(const TetBoundary& boundary, Index b) {
    return "tetrahedron " + std::to_string(boundary.tet(b)) + " facet " +
           std::to_string(boundary.facet(b));
}

namespace {

/// Connected components of the boundary triangles over edges whose two triangles have equal
/// `key`. Returns the component of each triangle and the count.
std::vector<int> components(const TetBoundary& boundary, const std::vector<int>& key, int* count) {
    const Index nb = boundary.size();
    std::vector<int> component(nb, -1);
    std::vector<Index> stack;
    int n = 0;
    for (Index seed = 0; seed < nb; ++seed) {
        if (component[seed] >= 0) continue;
        component[seed] = n;
        stack.assign(1, seed);
        while (!stack.empty()) {
            const Index b = stack.back();
            stack.pop_back();
            for (const Index c : boundary.adjacent[b]) {
                if (c >= 0 && component[c] < 0 && key[c] == key[b]) {
                    component[c] = n;
                    stack.push_back(c);
                }
            }
        }
        ++n;
    }
    *count = n;
    return component;
}

}  // namespace

PolycubeCharts polycube_charts(const TetBoundary& boundary, const Eigen::MatrixXd& positions,
                               const std::vector<int>& labels) {
    return polycube_charts_of_areas(boundary, boundary_area_vectors(boundary, positions), labels);
}

PolycubeCharts polycube_charts_of_areas(const TetBoundary& boundary,
                                        const Eigen::MatrixXd& area_vectors,
                                        const std::vector<int>& labels) {
    const Index nb = boundary.size();
    if (static_cast<Index>(labels.size()) != nb || area_vectors.rows() != nb) {
        throw InvalidArgumentError("polycube_charts: " + std::to_string(labels.size()) +
                                   " labels and " + std::to_string(area_vectors.rows()) +
                                   " area vectors for " + std::to_string(nb) +
                                   " boundary triangles");
    }
    for (Index b = 0; b < nb; ++b) {
        if (labels[b] < 0 || labels[b] > 5) {
            throw InvalidArgumentError("polycube_charts: boundary triangle " + std::to_string(b) +
                                       " (" + describe_boundary_triangle(boundary, b) +
                                       ") has label " + std::to_string(labels[b]) +
                                       ", outside 0..5");
        }
    }
    PolycubeCharts charts;
    int count = 0;
    charts.chart_of = components(boundary, labels, &count);
    charts.label.assign(count, kNoLabel);
    charts.members.assign(count, {});
    charts.neighbours.assign(count, {});
    charts.area.assign(count, 0.0);
    charts.aligned_area.assign(count, 0.0);
    for (Index b = 0; b < nb; ++b) {
        const int c = charts.chart_of[b];
        charts.label[c] = labels[b];
        charts.members[c].push_back(b);
        charts.area[c] += area_vectors.row(b).norm();
        charts.aligned_area[c] += label_sign(labels[b]) * area_vectors(b, label_axis(labels[b]));
        for (const Index other : boundary.adjacent[b]) {
            if (other >= 0 && charts.chart_of[other] != c) {
                charts.neighbours[c].push_back(charts.chart_of[other]);
            }
        }
    }
    for (auto& n : charts.neighbours) {
        std::sort(n.begin(), n.end());
        n.erase(std::unique(n.begin(), n.end()), n.end());
    }
    return charts;
}

std::vector<int> closest_axis_labels(const TetBoundary& boundary,
                                     const Eigen::MatrixXd& positions) {
    const Eigen::MatrixXd area_vectors = boundary_area_vectors(boundary, positions);
    std::vector<int> labels(boundary.size());
    for (Index b = 0; b < boundary.size(); ++b) {
        int best = 0;
        double best_dot = -kInfinity;
        for (int label = 0; label < 6; ++label) {
            const double dot = label_sign(label) * area_vectors(b, label_axis(label));
            if (dot > best_dot) {
                best_dot = dot;
                best = label;
            }
        }
        labels[b] = best;
    }
    return labels;
}

std::string LabelConvention::describe() const {
    std::ostringstream out;
    if (inward == 0 && outward == 0) {
        out << "no labelled triangle";
    } else if (inward == 0) {
        out << "even labels point along the outward normal (0..5 = +X, -X, +Y, -Y, +Z, -Z)";
    } else if (outward == 0) {
        out << "even labels point along the inward normal (0..5 = -X, +X, -Y, +Y, -Z, +Z), the "
               "opposite of 0..5 = +X, -X, ...";
    } else {
        out << "mixed: " << outward << " boundary triangles have even labels along the outward "
            << "normal, " << inward << " along the inward normal";
    }
    if (tets > 0 && negative_tets == tets) {
        out << "; every rest tetrahedron is negatively oriented, so ultimaille's facet winding "
               "points inwards";
    } else if (negative_tets > 0) {
        out << "; " << negative_tets << " of " << tets
            << " rest tetrahedra are negatively oriented";
    }
    return out.str();
}

std::vector<int> labels_from_file_axes(const SimplicialMesh& mesh, const TetBoundary& boundary,
                                       const std::vector<int>& file_labels,
                                       const std::string& source, LabelConvention* convention) {
    const Index nb = boundary.size();
    if (static_cast<Index>(file_labels.size()) != nb) {
        throw InputError(source + ": " + std::to_string(file_labels.size()) +
                         " boundary labels for " + std::to_string(nb) + " boundary triangles");
    }
    for (Index b = 0; b < nb; ++b) {
        if (file_labels[b] < 0 || file_labels[b] > 5) {
            throw InputError(source + ": " + describe_boundary_triangle(boundary, b) +
                             " has label " + std::to_string(file_labels[b]) + ", outside 0..5");
        }
    }
    int count = 0;
    const std::vector<int> chart = components(boundary, file_labels, &count);
    const Eigen::MatrixXd area_vectors = boundary_area_vectors(boundary, mesh.vertices);
    std::vector<double> along(count, 0.0), area(count, 0.0);
    std::vector<Index> first(count, -1), size(count, 0);
    for (Index b = 0; b < nb; ++b) {
        const int c = chart[b];
        along[c] += area_vectors(b, label_axis(file_labels[b]));
        area[c] += area_vectors.row(b).norm();
        if (first[c] < 0) first[c] = b;
        ++size[c];
    }
    std::vector<int> labels(nb);
    LabelConvention found;
    for (Index b = 0; b < nb; ++b) {
        const int c = chart[b];
        if (!(std::abs(along[c]) > 1e-9 * area[c])) {
            const int axis = label_axis(file_labels[b]);
            throw InputError(source + ": the chart of " + std::to_string(size[c]) +
                             " boundary triangles labelled " + std::to_string(file_labels[b]) +
                             " (axis " + "XYZ"[axis] + ") at " +
                             describe_boundary_triangle(boundary, first[c]) +
                             " faces neither side of its axis: it cannot be planar");
        }
        const int sign = along[c] > 0.0 ? 1 : -1;
        labels[b] = make_label(label_axis(file_labels[b]), sign);
        if ((file_labels[b] % 2 == 0) == (sign > 0)) {
            ++found.outward;
        } else {
            ++found.inward;
        }
    }
    found.tets = mesh.num_simplices();
    for (Index t = 0; t < mesh.num_simplices(); ++t) {
        if (tet_orientation(mesh, t) < 0) ++found.negative_tets;
    }
    if (convention != nullptr) *convention = found;
    return labels;
}

std::vector<int> boundary_labels_from_flags(const TetBoundary& boundary, Index num_tets,
                                            const std::vector<int>& flags,
                                            const std::string& source) {
    if (flags.size() != 4 * std::size_t(num_tets)) {
        throw InputError(source + ": " + std::to_string(flags.size()) + " labels, expected " +
                         std::to_string(4 * std::size_t(num_tets)) + " (4 per tetrahedron for " +
                         std::to_string(num_tets) + " tetrahedra)");
    }
    std::vector<int> labels(boundary.size());
    for (std::size_t f = 0; f < flags.size(); ++f) {
        const Index b = boundary.of_tet_facet[f];
        const std::string where =
            source + ": tetrahedron " + std::to_string(f / 4) + " facet " + std::to_string(f % 4);
        if (flags[f] < -1 || flags[f] > 5) {
            throw InputError(where + " has label " + std::to_string(flags[f]) +
                             ", outside [-1, 5]");
        }
        if (b < 0 && flags[f] != kNoLabel) {
            throw InputError(where + " is an interior facet but has label " +
                             std::to_string(flags[f]) + " (interior facets take -1)");
        }
        if (b >= 0) {
            if (flags[f] == kNoLabel) {
                throw InputError(where + " is a boundary facet without a label (-1)");
            }
            labels[b] = flags[f];
        }
    }
    return labels;
}

std::vector<int> facet_flags(const TetBoundary& boundary, Index num_tets,
                             const std::vector<int>& labels, FlagSign sign) {
    if (static_cast<Index>(labels.size()) != boundary.size()) {
        throw InvalidArgumentError("facet_flags: " + std::to_string(labels.size()) +
                                   " labels for " + std::to_string(boundary.size()) +
                                   " boundary triangles");
    }
    std::vector<int> flags(4 * std::size_t(num_tets), kNoLabel);
    for (Index b = 0; b < boundary.size(); ++b) {
        const int label = labels[b];
        flags[boundary.tet_facet[b]] = sign == FlagSign::kOutward ? label : (label ^ 1);
    }
    return flags;
}

void validate_polycube_labels(const SimplicialMesh& mesh, const TetBoundary& boundary,
                              const std::vector<int>& labels, const std::string& source) {
    PolycubeCharts charts;
    try {
        charts = polycube_charts(boundary, mesh.vertices, labels);
    } catch (const InvalidArgumentError& e) {
        throw InputError(source + ": " + e.what());
    }
    auto describe = [&](int c) {
        return "the chart of " + std::to_string(charts.members[c].size()) +
               " boundary triangles labelled " + label_name(charts.label[c]) + " at " +
               describe_boundary_triangle(boundary, charts.members[c].front());
    };
    for (int c = 0; c < charts.size(); ++c) {
        if (!(charts.aligned_area[c] > 1e-9 * charts.area[c])) {
            throw InputError(source + ": " + describe(c) +
                             " faces away from its direction (area-weighted normal . " +
                             label_name(charts.label[c]) + " <= 0): it cannot be planar");
        }
        for (const int other : charts.neighbours[c]) {
            if (other > c && charts.label[other] == (charts.label[c] ^ 1)) {
                throw InputError(source + ": " + describe(c) + " touches " + describe(other) +
                                 ": opposite sides of one axis cannot share an edge");
            }
        }
    }
}

}  // namespace sa
