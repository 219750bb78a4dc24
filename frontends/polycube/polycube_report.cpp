#include "frontends/polycube/polycube_report.h"

#include <cmath>

#include "frontends/output/map_report.h"

namespace sa {

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LabelCleanupReport, charts_before, charts_after, merged_small,
                                   merged_few_neighbours, merged_opposite, teeth, triangles_changed,
                                   rounds, clean)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LabelRepairReport, turning_before, turning_after,
                                   backward_before, backward_after, moves, triangles_changed,
                                   trials)

namespace {

/// JSON has no infinity: null instead.
nlohmann::json finite(double x) {
    return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json();
}

nlohmann::json squashed_json(const SquashedElements& s) {
    return {{"tets", s.tets},
            {"interior_edges", s.interior_edges},
            {"boundary_edges", s.boundary_edges},
            {"boundary_triangles", s.boundary_triangles},
            {"flattened_tets", s.flattened_tets}};
}

}  // namespace

nlohmann::json polycube_preparation_json(const PreparedPolycube& p) {
    nlohmann::json j;
    j["input"] = {{"vertices", p.input.num_vertices()},
                  {"tets", p.input.num_simplices()},
                  {"volume", std::ldexp(p.input_volume, 3 * p.scale_exponent)}};
    nlohmann::json labels = {{"source", p.label_source},
                             {"boundary_triangles", p.boundary.size()},
                             {"charts", p.charts.size()},
                             {"output_flags", p.output_sign == FlagSign::kOutward
                                                  ? "even = +axis along the outward normal"
                                                  : "even = +axis along the inward normal"}};
    if (p.convention) {
        labels["convention"] = {{"description", p.convention->describe()},
                                {"outward", p.convention->outward},
                                {"inward", p.convention->inward},
                                {"negative_tets", p.convention->negative_tets}};
    }
    if (p.cleanup) labels["cleanup"] = *p.cleanup;
    if (p.repair) labels["repair"] = *p.repair;
    if (p.orientation) {
        const Eigen::Matrix3d& r = p.orientation->rotation;
        labels["orientation"] = {{"rotation",
                                  {{r(0, 0), r(0, 1), r(0, 2)},
                                   {r(1, 0), r(1, 1), r(1, 2)},
                                   {r(2, 0), r(2, 1), r(2, 2)}}},
                                 {"angle_degrees", p.orientation->angle_degrees},
                                 {"l1_alignment", p.orientation->energy},
                                 {"l1_alignment_as_given", p.orientation->energy_identity}};
    }
    nlohmann::json turning = nlohmann::json::array();
    const double unit = std::ldexp(1.0, p.scale_exponent);  // lengths in the input's units
    for (const NonMonotoneBoundary& b : p.non_monotone) {
        turning.push_back({{"labels", {label_name(b.label_a), label_name(b.label_b)}},
                           {"edges", b.edges},
                           {"strongly_backward_edges", b.strongly_backward},
                           {"length", unit * b.length},
                           {"backward_travel", unit * b.backward_travel},
                           {"vertex", b.vertex}});
    }
    labels["non_monotone_boundaries"] = turning;
    auto finite_or_inf = [](double x) {
        return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json("inf");
    };
    nlohmann::json wedges = nlohmann::json::array();
    for (const WedgeAngleBound& w : p.angle_bound.worst) {
        wedges.push_back({{"vertex", w.vertex},
                          {"label", label_name(w.label)},
                          {"wedges_at_vertex", w.wedges},
                          {"triangles", w.triangles},
                          {"rest_angle_degrees", w.rest_angle * 180.0 / M_PI},
                          {"polycube_angle_degrees", w.image_angle * 180.0 / M_PI},
                          {"bound", finite_or_inf(w.bound)}});
    }
    labels["distortion_lower_bound"] = {{"bound", finite_or_inf(p.angle_bound.bound)},
                                        {"worst_wedges", wedges}};
    j["labels"] = labels;
    j["splits"] = {{"squashed_before", squashed_json(p.splits.before)},
                   {"squashed_after", squashed_json(p.splits.after)},
                   {"edge_splits", p.splits.edge_splits},
                   {"face_splits", p.splits.face_splits},
                   {"vertices", p.mesh.num_vertices()},
                   {"tets", p.mesh.num_simplices()}};
    j["seconds"] = {{"labels", p.read_labels_seconds}, {"splits", p.splits_seconds}};
    return j;
}

nlohmann::json polycube_verification_json(const PolycubeVerification& v) {
    return {{"passed", v.passed},
            {"failures", v.failures},
            {"quality", quality_json(v.quality)},
            {"volume_scale", v.volume_scale},
            {"planarity",
             {{"max_spread", v.max_planarity},
              {"nonplanar_charts", v.nonplanar_charts},
              {"wrong_side_charts", v.wrong_side_charts}}},
            {"polycube_edges",
             {{"count", v.polycube_edges},
              {"zero_length", v.zero_length_edges},
              {"shortest", finite(v.shortest_edge)}}},
            {"angle_sums",
             {{"edge_violations", v.edge_angle_violations},
              {"vertex_violations", v.vertex_angle_violations},
              {"max_edge_over_pi", finite(v.max_edge_angle_sum / M_PI)},
              {"max_vertex_over_pi", finite(v.max_vertex_angle_sum / M_PI)}}}};
}

}  // namespace sa
