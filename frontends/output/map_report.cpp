#include "frontends/output/map_report.h"

#include "geometry/io/atomic_file.h"

namespace sa {

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(FixedBoundaryPart, dimension, simplices, first_simplex, volume,
                                   encloses_volume, turning_measured, turning, euler)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SubmeshRound, round, bad_simplices, regions, colors, solved,
                                   failed, remaining, time)
void to_json(nlohmann::json& out, const SubmeshStats& m) {
    out = {{"start", m.start.describe()},
           {"start_iterations", m.start_iterations},
           {"start_rejected", m.start_rejected},
           {"start_bad", m.start_bad},
           {"start_near_bound", m.start_near_bound},
           {"rounds", m.rounds},
           {"solves", m.solves},
           {"iterations", m.iterations},
           {"largest_submesh", m.largest_submesh},
           {"max_rings", m.max_rings},
           {"out_of_time", m.out_of_time}};
}
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(StageTimes, setup, disassembly, optimization, recovery,
                                   vertex_stage, verification, total)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(PhaseTimes, setup, evaluate, project, assemble, analyze,
                                   factorize, solve, line_search, callbacks, total)

namespace {
/// JSON has no infinity: write it as null.
nlohmann::json number(double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}
}  // namespace

nlohmann::json quality_json(const MapQuality& q) {
    auto stat = [](const QualityStat& s) {
        return nlohmann::json{{"max", number(s.max)}, {"mean", number(s.mean)}};
    };
    return {{"simplices", q.simplices},       {"inverted", q.inverted},
            {"degenerate", q.degenerate},     {"conformal", stat(q.conformal)},
            {"isometric", stat(q.isometric)}, {"volumetric", stat(q.volumetric)}};
}

nlohmann::json stages_json(const StageTrace& stages) {
    nlohmann::json out = nlohmann::json::array();
    for (const StageRecord& r : stages.records) {
        nlohmann::json record = {{"stage", to_string(r.stage)},
                                 {"outcome", to_string(r.outcome)},
                                 {"newton_steps", r.newton_steps},
                                 {"seconds", r.seconds}};
        if (r.termination) record["termination"] = to_string(*r.termination);
        if (!r.figures.empty()) record["figures"] = r.figures;
        out.push_back(std::move(record));
    }
    return out;
}

namespace {
nlohmann::json input_json(const MappingProblem& problem) {
    return {{"source", problem.source},
            {"vertices", problem.mesh.num_vertices()},
            {"simplices", problem.mesh.num_simplices()},
            {"simplex_dimension", problem.mesh.simplex_dimension()},
            {"rest_dimension", problem.mesh.ambient_dimension()},
            {"handles", problem.handles.size()}};
}
}  // namespace

nlohmann::json infeasible_report(const MappingProblem& problem,
                                 const InfeasibleProblemError& error) {
    const HandleFeasibility& f = error.diagnosis();
    nlohmann::json conflicts = nlohmann::json::array();
    for (const HandleConflict& c : f.conflicts) {
        conflicts.push_back(
            {{"vertex", c.vertex},
             {"first", std::vector<double>(c.first.data(), c.first.data() + c.first.size())},
             {"second", std::vector<double>(c.second.data(), c.second.data() + c.second.size())}});
    }
    nlohmann::json report;
    report["input"] = input_json(problem);
    report["message"] = error.what();
    report["success"] = false;
    report["infeasible"] = {{"description", f.describe()},
                            {"fixed_simplices", f.fixed_simplices},
                            {"inverted", f.inverted.size()},
                            {"flat", f.flat.size()},
                            {"conflicting_handles", f.conflicts.size()},
                            {"collapsed_edges", f.collapsed_edges.size()},
                            {"inverted_simplices", f.inverted},
                            {"flat_simplices", f.flat},
                            {"conflicts", conflicts},
                            {"collapsed_edge_list", f.collapsed_edges},
                            {"fixed_boundaries", f.enclosing}};
    return report;
}

nlohmann::json solve_times_json(const SimplexAssemblyResult& r) {
    nlohmann::json times = r.times;
    times["newton_phases"] = r.newton.times;
    return times;
}

nlohmann::json assembly_iterations_json(const SimplexAssemblyResult& r) {
    nlohmann::json iterations = nlohmann::json::array();
    for (std::size_t k = 0; k < r.iterations.size(); ++k) {
        const AssemblyRecord& a = r.iterations[k];
        nlohmann::json row = {{"iteration", a.iteration}, {"energy", a.energy},
                              {"assembly", a.assembly},   {"barrier", a.barrier},
                              {"lambda", a.lambda},       {"time", a.time}};
        if (k < r.newton.iterations.size() && a.iteration > 0) {
            const IterationRecord& n = r.newton.iterations[k];
            row["step"] = n.step_length;
            row["line_search_trials"] = n.line_search_trials;
            row["gradient_norm"] = n.gradient_norm;
            row["decrement"] = n.decrement;
            row["regularization"] = n.regularization;
            row["iteration_time"] = n.iteration_time;
            row["factorization_time"] = n.factorization_time;
        }
        iterations.push_back(row);
    }
    return iterations;
}

nlohmann::json continuation_round_json(const ContinuationRound& round) {
    return {{"s", round.s},
            {"bound", number(round.bound)},
            {"max_distortion_before", round.max_distortion_before},
            {"max_distortion_after", round.max_distortion_after},
            {"iterations", round.iterations},
            {"outcome", to_string(round.outcome)},
            {"termination", newton_ran(round.outcome) ? nlohmann::json(to_string(round.termination))
                                                      : nlohmann::json(nullptr)},
            {"undone_degenerate", round.undone_degenerate}};
}

nlohmann::json map_report(const MappingProblem& problem, const SimplexAssemblyOptions& o,
                          const SimplexAssemblyResult& r) {
    nlohmann::json report;
    report["input"] = input_json(problem);
    report["options"] = {
        {"distortion", to_string(o.distortion)},
        {"bound", number(o.bound)},
        {"s", o.s},
        {"gamma", o.gamma},
        {"mapping_distortion", o.mapping_distortion ? to_string(*o.mapping_distortion) : "none"},
        {"mu", o.mu},
        {"variant", to_string(o.variant)},
        {"initialization", to_string(o.effective_initialization())},
        {"lambda_min", o.lambda_min},
        {"lambda_max", o.lambda_max},
        {"projection", to_string(o.projection)},
        {"translation_shift", o.translation_shift},
        {"linear_solver", to_string(o.linear_solver)},
        {"vertex_stage", o.vertex_stage},
        {"handover_ratio", o.handover_ratio},
        {"until_valid", o.until_valid},
        {"mode", to_string(o.mode)},
        {"rings", o.rings},
        {"max_rings", o.max_rings},
        {"max_rounds", o.max_rounds},
        {"start_iterations", o.start_iterations},
        {"assembly_tolerance", o.assembly_tolerance},
        {"energy_tolerance", o.energy_tolerance},
        {"max_iterations", o.max_iterations},
        {"max_time_seconds", number(o.max_time_seconds)},
        {"handle_tolerance", o.handle_tolerance},
        {"threads", r.newton.num_threads}};
    const Verification& v = r.verification;
    report["verification"] = {{"success", r.success},
                              {"valid", r.valid},
                              {"description", v.describe()},
                              {"simplices", v.simplices},
                              {"inverted", v.inverted},
                              {"degenerate", v.degenerate},
                              {"branch_points", v.branched},
                              {"first_branch_point", v.first_branch},
                              {"handles", v.handles},
                              {"handle_error", v.handle_error},
                              {"handle_tolerance", v.handle_tolerance},
                              {"bound", number(v.bound)},
                              {"max_distortion", number(v.max_distortion)},
                              {"within_bound", v.within_bound()}};
    report["message"] = r.message;
    report["mode"] = to_string(r.mode);
    if (r.mode == SolveMode::kSubmesh) {
        const SubmeshStats& m = r.submesh;
        report["submesh"] = m;
        report["submesh"]["times"] = {
            {"start", m.start_time}, {"regions", m.region_time}, {"solves", m.solve_time}};
    }
    if (r.mode == SolveMode::kDescent) {
        report["descent_rounds"] = nlohmann::json::array();
        for (const ContinuationRound& round : r.descent_rounds)
            report["descent_rounds"].push_back(continuation_round_json(round));
    }
    report["initial_quality"] = quality_json(r.initial_quality);
    report["final_quality"] = quality_json(r.final_quality);
    report["assembly"] = {{"assembled", r.assembled},
                          {"final_assembly_energy", r.final_assembly},
                          {"final_lambda", r.final_lambda},
                          {"variables", r.num_variables},
                          {"translation_simplices", r.num_translation_simplices},
                          {"steiner_tree_edges", r.num_tree_edges},
                          {"homology_loops", r.num_loops},
                          {"anchored_simplices", r.num_anchored_simplices},
                          {"newton_termination", to_string(r.newton.termination)},
                          {"newton_message", r.newton.message}};
    report["stages"] = stages_json(r.stages);
    report["vertex_stage"] = {{"ran", r.stages.vertex_stage_ran()},
                              {"iterations", r.vertex_stage.num_steps()},
                              {"initial_energy", r.vertex_stage.initial_energy},
                              {"final_energy", r.vertex_stage.final_energy},
                              {"termination", to_string(r.vertex_stage.termination)}};
    report["iterations"] = assembly_iterations_json(r);
    report["times"] = solve_times_json(r);
    return report;
}

void write_json(const std::string& path, const nlohmann::json& report) {
    AtomicFile file(path);
    file.stream() << report.dump(2) << "\n";
    file.commit();
}

}  // namespace sa
