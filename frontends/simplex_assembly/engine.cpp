#include "frontends/simplex_assembly/engine.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "optim/enum_names.h"
#include "optim/newton_solver.h"
#include "optim/stopwatch.h"

namespace sa {

constexpr EnumName<AssemblyStop> kAssemblyStopNames[] = {
    {AssemblyStop::kAssembled, "assembled"},
    {AssemblyStop::kConvergedAtLambdaMax, "converged at lambda_max"},
    {AssemblyStop::kConverged, "converged"},
    {AssemblyStop::kHook, "stopped by the front-end"},
    {AssemblyStop::kNoFreeVariables, "no free variables"},
    {AssemblyStop::kMaxIterations, "max iterations"},
    {AssemblyStop::kMaxTime, "time limit"},
    {AssemblyStop::kLineSearchFailed, "line search failed"},
    {AssemblyStop::kFactorizationFailed, "factorization failed"},
    {AssemblyStop::kInfeasibleStart, "infeasible start"},
    {AssemblyStop::kNonFinite, "non-finite"}};

std::string to_string(AssemblyStop stop) {
    return enum_name(kAssemblyStopNames, stop);
}

void AssemblyEngineOptions::validate() const {
    auto fail = [](const char* field, double value, const char* rule) {
        std::ostringstream msg;
        msg << field << " = " << value << ": " << rule;
        throw InvalidArgumentError(msg.str());
    };
    if (!(lambda_min > 0.0) || !std::isfinite(lambda_min))
        fail("lambda_min", lambda_min, "must be finite and > 0");
    if (!(lambda_max >= lambda_min) || !std::isfinite(lambda_max))
        fail("lambda_max", lambda_max, "must be finite and >= lambda_min");
    if (!(assembly_tolerance > 0.0)) fail("assembly_tolerance", assembly_tolerance, "must be > 0");
    if (!(energy_tolerance >= 0.0)) fail("energy_tolerance", energy_tolerance, "must be >= 0");
    if (max_iterations < 1) fail("max_iterations", max_iterations, "must be >= 1");
    if (!(max_time_seconds > 0.0)) fail("max_time_seconds", max_time_seconds, "must be > 0");
    if (!(projection_epsilon >= 0.0))
        fail("projection_epsilon", projection_epsilon, "must be >= 0");
    if (!(translation_shift >= 0.0) || !std::isfinite(translation_shift * lambda_max))
        fail("translation_shift", translation_shift,
             "must be >= 0 and finite times lambda_max (the shift is translation_shift * lambda)");
    if (num_threads < 0) fail("num_threads", num_threads, "must be >= 0 (0 = all cores)");
}

namespace {

Eigen::VectorXd stack_linear_parts(const auto& linear, const auto& translations) {
    constexpr int D = std::decay_t<decltype(linear.front())>::RowsAtCompileTime;
    const Index n = static_cast<Index>(linear.size());
    Eigen::VectorXd x(Index(D * D) * n + Index(D) * Index(translations.size()));
    for (Index s = 0; s < n; ++s)
        x.template segment<D * D>(Index(D * D) * s) =
            Eigen::Map<const Vec<D * D>>(linear[s].data());
    for (std::size_t k = 0; k < translations.size(); ++k)
        x.template segment<D>(Index(D * D) * n + Index(D) * Index(k)) = translations[k].second;
    return x;
}

template <int N>
std::array<Index, N> consecutive(Index first) {
    std::array<Index, N> a;
    for (int k = 0; k < N; ++k) a[k] = first + k;
    return a;
}

}  // namespace

template <int D>
SimplexAssemblyEngine<D>::SimplexAssemblyEngine(
    const std::vector<Mat<D>>& linear, const std::vector<std::pair<Index, Vec<D>>>& translations)
    : layout_(Layout::kLinearParts),
      num_simplices_(static_cast<Index>(linear.size())),
      problem_(stack_linear_parts(linear, translations)) {
    translation_offset_.assign(num_simplices_, -1);
    for (std::size_t k = 0; k < translations.size(); ++k) {
        const Index s = translations[k].first;
        check_simplex(s);
        if (translation_offset_[s] >= 0) {
            throw InvalidArgumentError("SimplexAssemblyEngine: simplex " + std::to_string(s) +
                                       " is given two translations");
        }
        translation_offset_[s] = Index(kLinear) * num_simplices_ + Index(D) * Index(k);
        translated_.push_back(s);
    }
}

template <int D>
SimplexAssemblyEngine<D>::SimplexAssemblyEngine(LayoutTag, Layout layout, Eigen::VectorXd x,
                                                Index n)
    : layout_(layout), num_simplices_(n), problem_(std::move(x)) {
    translation_offset_.assign(n, -1);
}

template <int D>
SimplexAssemblyEngine<D> SimplexAssemblyEngine<D>::corner_copies(
    const std::vector<Corners>& corners, std::vector<Corners> rest_corners,
    std::vector<Mat<D>> rest_edge_inverse) {
    const Index n = static_cast<Index>(corners.size());
    if (Index(rest_corners.size()) != n || Index(rest_edge_inverse.size()) != n) {
        throw InvalidArgumentError(
            "SimplexAssemblyEngine::corner_copies: one set of rest corners and one rest edge "
            "inverse per simplex");
    }
    Eigen::VectorXd x(Index(kAffine) * n);
    for (Index s = 0; s < n; ++s) {
        for (int k = 0; k <= D; ++k) x.template segment<D>(kAffine * s + D * k) = corners[s].col(k);
    }
    SimplexAssemblyEngine engine(LayoutTag{}, Layout::kCornerCopies, std::move(x), n);
    engine.rest_corners_ = std::move(rest_corners);
    engine.rest_inverse_ = std::move(rest_edge_inverse);
    return engine;
}

template <int D>
SimplexAssemblyEngine<D> SimplexAssemblyEngine<D>::vertex_positions(
    const Eigen::MatrixXd& positions, std::vector<std::array<Index, D + 1>> simplices,
    std::vector<Corners> rest_corners, std::vector<Mat<D>> rest_edge_inverse,
    std::vector<Index> shared) {
    const Index n = static_cast<Index>(simplices.size());
    if (Index(rest_corners.size()) != n || Index(rest_edge_inverse.size()) != n) {
        throw InvalidArgumentError(
            "SimplexAssemblyEngine::vertex_positions: one set of rest corners and one rest edge "
            "inverse per simplex");
    }
    if (positions.cols() != D) {
        throw InvalidArgumentError("SimplexAssemblyEngine::vertex_positions: positions have " +
                                   std::to_string(positions.cols()) + " columns, expected " +
                                   std::to_string(D));
    }
    const Index nv = positions.rows();
    for (Index s = 0; s < n; ++s) {
        for (Index v : simplices[s]) {
            if (v < 0 || v >= nv) {
                throw InvalidArgumentError("SimplexAssemblyEngine::vertex_positions: simplex " +
                                           std::to_string(s) + " has vertex " + std::to_string(v) +
                                           ", outside [0, " + std::to_string(nv) + ")");
            }
        }
    }
    // Vertex-major coordinates, x[D v + c].
    Eigen::VectorXd x(static_cast<Index>(D) * nv);
    for (Index v = 0; v < nv; ++v) x.template segment<D>(D * v) = positions.row(v).transpose();
    if (!shared.empty()) {
        if (Index(shared.size()) != x.size()) {
            throw InvalidArgumentError("SimplexAssemblyEngine::vertex_positions: shared has " +
                                       std::to_string(shared.size()) + " entries for " +
                                       std::to_string(x.size()) + " coordinates");
        }
        Eigen::VectorXd sum = Eigen::VectorXd::Zero(x.size());
        Eigen::VectorXd count = Eigen::VectorXd::Zero(x.size());
        for (Index i = 0; i < x.size(); ++i) {
            const Index j = shared[i];
            if (j < 0 || j >= x.size() || shared[j] != j) {
                throw InvalidArgumentError("SimplexAssemblyEngine::vertex_positions: coordinate " +
                                           std::to_string(i) + " shares coordinate " +
                                           std::to_string(j) +
                                           ", which is out of range or shares another");
            }
            sum[j] += x[i];
            count[j] += 1.0;
        }
        for (Index i = 0; i < x.size(); ++i)
            if (shared[i] == i) x[i] = sum[i] / count[i];
    }
    SimplexAssemblyEngine engine(LayoutTag{}, Layout::kVertexPositions, std::move(x), n);
    engine.shared_ = std::move(shared);
    engine.simplices_ = std::move(simplices);
    engine.rest_corners_ = std::move(rest_corners);
    engine.rest_inverse_ = std::move(rest_edge_inverse);
    return engine;
}

template <int D>
Index SimplexAssemblyEngine<D>::corner_variable(Index s, int k, int c) const {
    if (layout_ == Layout::kVertexPositions)
        return coordinate_variable(Index(D) * simplices_[s][k] + c);
    return Index(kAffine) * s + D * k + c;
}

template <int D>
Vec<D> SimplexAssemblyEngine<D>::corner(const Eigen::VectorXd& x, Index s, int k) const {
    Vec<D> p;
    for (int c = 0; c < D; ++c) p[c] = x[corner_variable(s, k, c)];
    return p;
}

template <int D>
void SimplexAssemblyEngine<D>::check_simplex(Index s) const {
    if (s < 0 || s >= num_simplices_) {
        throw InvalidArgumentError("SimplexAssemblyEngine: simplex " + std::to_string(s) +
                                   " outside [0, " + std::to_string(num_simplices_) + ")");
    }
}

template <int D>
std::array<Index, SimplexAssemblyEngine<D>::kLinear> SimplexAssemblyEngine<D>::linear_variables(
    Index s) const {
    check_simplex(s);
    if (layout_ != Layout::kLinearParts) {
        throw InvalidArgumentError(
            "SimplexAssemblyEngine: the corner layout has no linear-part variables (use "
            "affine_variables and linear_part_map)");
    }
    return consecutive<kLinear>(Index(kLinear) * s);
}

template <int D>
bool SimplexAssemblyEngine<D>::has_translation(Index s) const {
    check_simplex(s);
    return layout_ != Layout::kLinearParts || translation_offset_[s] >= 0;
}

template <int D>
std::array<Index, D> SimplexAssemblyEngine<D>::translation_variables(Index s) const {
    check_simplex(s);
    if (layout_ != Layout::kLinearParts || translation_offset_[s] < 0) {
        throw InvalidArgumentError("SimplexAssemblyEngine: simplex " + std::to_string(s) +
                                   " has no translation variables");
    }
    return consecutive<D>(translation_offset_[s]);
}

template <int D>
std::array<Index, SimplexAssemblyEngine<D>::kAffine> SimplexAssemblyEngine<D>::affine_variables(
    Index s) const {
    check_simplex(s);
    if (layout_ != Layout::kLinearParts) {
        std::array<Index, kAffine> corners;
        for (int k = 0; k <= D; ++k)
            for (int c = 0; c < D; ++c) corners[D * k + c] = corner_variable(s, k, c);
        return corners;
    }
    const std::array<Index, kLinear> a = linear_variables(s);
    const std::array<Index, D> t = translation_variables(s);
    std::array<Index, kAffine> both;
    std::copy(a.begin(), a.end(), both.begin());
    std::copy(t.begin(), t.end(), both.begin() + kLinear);
    return both;
}

template <int D>
std::array<Index, D> SimplexAssemblyEngine<D>::vertex_variables(Index v) const {
    if (layout_ != Layout::kVertexPositions) {
        throw InvalidArgumentError(
            "SimplexAssemblyEngine: only the vertex layout has vertex variables");
    }
    if (v < 0 || Index(D) * v >= problem_.num_variables()) {
        throw InvalidArgumentError("SimplexAssemblyEngine: vertex " + std::to_string(v) +
                                   " outside [0, " + std::to_string(problem_.num_variables() / D) +
                                   ")");
    }
    std::array<Index, D> out;
    for (int c = 0; c < D; ++c) out[c] = coordinate_variable(Index(D) * v + c);
    return out;
}

template <int D>
typename SimplexAssemblyEngine<D>::ImageMap SimplexAssemblyEngine<D>::image_coefficients(
    Index s, const Vec<D>& u) const {
    check_simplex(s);
    ImageMap G = ImageMap::Zero();
    if (layout_ == Layout::kLinearParts) {
        // A u + T: column c of A times u_c, then T.
        for (int c = 0; c < D; ++c) G.template block<D, D>(0, D * c) = u[c] * Mat<D>::Identity();
        G.template rightCols<D>() = Mat<D>::Identity();
        return G;
    }
    // Barycentric coordinates of u in the rest corners: the image is sum_k beta_k x_k.
    const Vec<D> b = rest_inverse_[s] * (u - rest_corners_[s].col(0));
    G.template block<D, D>(0, 0) = (1.0 - b.sum()) * Mat<D>::Identity();
    for (int k = 0; k < D; ++k) G.template block<D, D>(0, D * (k + 1)) = b[k] * Mat<D>::Identity();
    return G;
}

template <int D>
typename SimplexAssemblyEngine<D>::LinearPartMap SimplexAssemblyEngine<D>::linear_part_map(
    Index s) const {
    check_simplex(s);
    LinearPartMap L = LinearPartMap::Zero();
    if (layout_ == Layout::kLinearParts) {
        L.template leftCols<kLinear>().setIdentity();
        return L;
    }
    // vec(P E^-1) with column c of P = x_{c+1} - x_0 (VertexSimplexEnergy::map).
    const Mat<D>& Rinv = rest_inverse_[s];
    for (int c = 0; c < D; ++c) {
        for (int k = 0; k < D; ++k) {
            L.template block<D, D>(D * c, D * (k + 1)) += Rinv(k, c) * Mat<D>::Identity();
            L.template block<D, D>(D * c, 0) -= Rinv(k, c) * Mat<D>::Identity();
        }
    }
    return L;
}

template <int D>
void SimplexAssemblyEngine<D>::fix_simplex(Index s) {
    check_simplex(s);
    if (layout_ != Layout::kLinearParts) {
        for (Index v : affine_variables(s)) problem_.set_fixed(v);
        return;
    }
    for (Index v : linear_variables(s)) problem_.set_fixed(v);
    if (translation_offset_[s] >= 0) {
        for (Index v : translation_variables(s)) problem_.set_fixed(v);
    }
}

template <int D>
void SimplexAssemblyEngine<D>::fix_vertex(Index v) {
    for (Index i : vertex_variables(v)) problem_.set_fixed(i);
}

template <int D>
Mat<D> SimplexAssemblyEngine<D>::linear_part(const Eigen::VectorXd& x, Index s) const {
    if (layout_ != Layout::kLinearParts) {
        Mat<D> edges;
        for (int k = 0; k < D; ++k) {
            edges.col(k) = corner(x, s, k + 1) - corner(x, s, 0);
        }
        return edges * rest_inverse_[s];
    }
    return Eigen::Map<const Mat<D>>(x.data() + Index(kLinear) * s);
}

template <int D>
std::vector<Mat<D>> SimplexAssemblyEngine<D>::linear_parts(const Eigen::VectorXd& x) const {
    std::vector<Mat<D>> A(num_simplices_);
    for (Index s = 0; s < num_simplices_; ++s) A[s] = linear_part(x, s);
    return A;
}

template <int D>
std::vector<std::pair<Index, Vec<D>>> SimplexAssemblyEngine<D>::known_translations(
    const Eigen::VectorXd& x) const {
    std::vector<std::pair<Index, Vec<D>>> known;
    if (layout_ != Layout::kLinearParts) {
        for (Index s = 0; s < num_simplices_; ++s) {
            // T maps the frame's origin: mean of the copies minus A times the mean rest corner.
            Vec<D> mean = Vec<D>::Zero();
            for (int k = 0; k <= D; ++k) mean += corner(x, s, k);
            mean /= double(D + 1);
            const Vec<D> rest_mean = rest_corners_[s].rowwise().mean();
            known.emplace_back(s, mean - linear_part(x, s) * rest_mean);
        }
        return known;
    }
    for (Index s : translated_)
        known.emplace_back(s, x.template segment<D>(translation_offset_[s]));
    return known;
}

template <int D>
Eigen::MatrixXd SimplexAssemblyEngine<D>::positions(const Eigen::VectorXd& x) const {
    if (layout_ != Layout::kVertexPositions) {
        throw InvalidArgumentError("SimplexAssemblyEngine: only the vertex layout has positions");
    }
    const Index nv = x.size() / D;
    Eigen::MatrixXd p(nv, D);
    for (Index v = 0; v < nv; ++v)
        for (int c = 0; c < D; ++c) p(v, c) = x[coordinate_variable(D * v + c)];
    return p;
}

template <int D>
double SimplexAssemblyEngine<D>::assembly_energy() const {
    std::vector<double> values;
    problem_.value(problem_.variables(), &values);
    double sum = 0.0;
    for (TermId t : assembly_terms_) sum += values[t];
    return sum;
}

template <int D>
void SimplexAssemblyEngine<D>::declare_blocks() {
    if (blocks_declared_) return;
    blocks_declared_ = true;
    if (layout_ != Layout::kLinearParts) {
        problem_.add_variable_block(
            layout_ == Layout::kCornerCopies ? "vertex copies" : "vertex positions", 0,
            problem_.num_variables());
        return;
    }
    const Index linear_end = Index(kLinear) * num_simplices_;
    problem_.add_variable_block("linear parts", 0, linear_end);
    if (!translated_.empty()) {
        translation_block_ =
            problem_.add_variable_block("translations", linear_end, problem_.num_variables());
    }
}

template <int D>
AssemblyRun SimplexAssemblyEngine<D>::run(const AssemblyEngineOptions& options,
                                          const AssemblyHooks& hooks) {
    options.validate();
    Stopwatch watch;
    declare_blocks();
    AssemblyRun result;
    // Without assembly terms there is nothing to schedule: Newton's own relative-change and
    // decrement tests end it (the gradient test is scale-dependent and left out).
    const bool schedule = !assembly_terms_.empty();
    bool stopped = false;  // by the schedule's own test or the hook
    double lambda = options.lambda_min;
    auto set_lambda = [&](double value) {
        lambda = value;
        for (TermId t : assembly_terms_) problem_.set_weight(t, lambda);
        if (translation_block_ >= 0)
            problem_.set_hessian_shift(translation_block_, options.translation_shift * lambda);
    };
    set_lambda(lambda);
    if (schedule)
        log_line(hooks.logger, "iter      energy   assembly     lambda      step  ls     time");
    NewtonOptions newton;
    newton.max_iterations = options.max_iterations;
    newton.max_time_seconds = options.max_time_seconds;
    newton.gradient_tolerance = 0.0;
    if (schedule) {
        // The schedule decides convergence (below); Newton's tests would stop it at any lambda.
        newton.decrement_tolerance = newton.function_tolerance = 0.0;
    } else if (options.stop_when_converged) {
        newton.function_tolerance = options.energy_tolerance;
        // A fixed energy minimized to convergence: steps longer than Newton's where its model
        // is too curved (LineSearchOptions::expand; not in the schedule, whose lambda moves).
        newton.line_search.expand = true;
    } else {
        newton.decrement_tolerance = newton.function_tolerance = 0.0;
    }
    newton.projection = options.projection;
    newton.projection_epsilon = options.projection_epsilon;
    newton.linear_solver = options.linear_solver;
    newton.num_threads = options.num_threads;
    double last_assembly = schedule ? kInfinity : 0.0;
    newton.callbacks.push_back([&](const IterationContext& c) {
        double assembly_value = 0.0;
        for (TermId t : assembly_terms_) assembly_value += c.term_values[t];
        double barrier_value = 0.0;
        for (TermId t : barrier_terms_) barrier_value += c.problem.weight(t) * c.term_values[t];
        last_assembly = assembly_value;
        AssemblyRecord row;
        row.iteration = c.record.iteration;
        row.energy = c.record.energy;
        row.energy_change = c.record.iteration > 0 ? c.record.energy_change : 0.0;
        row.assembly = assembly_value;
        row.barrier = barrier_value;
        row.lambda = schedule ? lambda : 0.0;
        row.step = c.record.step_length;
        row.line_search_trials = c.record.line_search_trials;
        row.time = c.record.cumulative_time;
        result.records.push_back(row);
        char line[160];
        if (schedule) {
            std::snprintf(line, sizeof line, "%4d  %10.4e  %9.3e  %9.3e  %8.2e  %2d  %6.2fs",
                          row.iteration, row.energy, row.assembly, row.lambda,
                          std::max(row.step, 0.0), std::max(row.line_search_trials, 0), row.time);
            log_line(hooks.logger, line);
        } else if (row.iteration > 0) {
            std::snprintf(line, sizeof line, "P%3d  %10.4e  %9s  %9s  %8.2e  %2d  %6.2fs",
                          row.iteration, row.energy, "-", "-", row.step, row.line_search_trials,
                          row.time);
            log_line(hooks.logger, line);
        }
        if (hooks.after_iteration) {
            if (hooks.after_iteration(row, c.problem.variables())) {
                result.stop = AssemblyStop::kHook;
                stopped = true;
                return CallbackResult::kStopSuccess;
            }
        }
        if (!schedule) return CallbackResult::kContinue;
        // Converged: assembled, or at lambda_max, where the weights no longer change and the
        // schedule can do nothing more (the paper runs on to its 200 iterations; on tlc/stgc-3d
        // that was 100 iterations of steps changing E by 1e-15 of itself).
        const bool assembled = assembly_value < options.assembly_tolerance;
        if (row.iteration > 0 && (assembled || lambda >= options.lambda_max)) {
            const double before = c.record.energy + c.record.energy_change;
            if (c.record.energy_change <= options.energy_tolerance * std::abs(before)) {
                result.stop =
                    assembled ? AssemblyStop::kAssembled : AssemblyStop::kConvergedAtLambdaMax;
                stopped = true;
                return CallbackResult::kStopSuccess;
            }
        }
        const double ratio = assembly_value > 0.0 ? barrier_value / assembly_value : kInfinity;
        set_lambda(std::min(options.lambda_min * std::max(ratio, 1.0), options.lambda_max));
        return CallbackResult::kContinue;
    });
    result.newton = NewtonSolver(newton).solve(problem_);
    if (!stopped) {
        switch (result.newton.termination) {
            case TerminationType::kConverged:
                // With the schedule's zero tolerances only "no free variables" converges.
                result.stop = !schedule ? AssemblyStop::kConverged : AssemblyStop::kNoFreeVariables;
                if (problem_.num_free_variables() == 0)
                    result.stop = AssemblyStop::kNoFreeVariables;
                break;
            case TerminationType::kMaxIterations:
                result.stop = AssemblyStop::kMaxIterations;
                break;
            case TerminationType::kMaxTime:
                result.stop = AssemblyStop::kMaxTime;
                break;
            case TerminationType::kLineSearchFailed:
                result.stop = AssemblyStop::kLineSearchFailed;
                break;
            case TerminationType::kFactorizationFailed:
                result.stop = AssemblyStop::kFactorizationFailed;
                break;
            case TerminationType::kInfeasibleStart:
                result.stop = AssemblyStop::kInfeasibleStart;
                break;
            case TerminationType::kNonFinite:
            case TerminationType::kUserSuccess:
            case TerminationType::kUserAbort:
                result.stop = AssemblyStop::kNonFinite;
                break;
        }
    }
    result.final_lambda = schedule ? lambda : 0.0;
    result.final_assembly = last_assembly;
    result.assembled = last_assembly < options.assembly_tolerance;
    result.time = watch.seconds();
    return result;
}

template class SimplexAssemblyEngine<2>;
template class SimplexAssemblyEngine<3>;

}  // namespace sa
