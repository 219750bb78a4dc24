#include "optim/newton_options.h"

#include <cmath>
#include <sstream>

namespace sa {

namespace {

class Checker {
  public:
    explicit Checker(std::string* error) : error_(error) {}
    template <class T>
    void require(bool ok, const char* field, T value, const char* rule) {
        if (ok || failed_) return;
        failed_ = true;
        if (error_ != nullptr) {
            std::ostringstream msg;
            msg << "NewtonOptions." << field << " = " << value << ": " << rule;
            *error_ = msg.str();
        }
    }
    bool ok() const { return !failed_; }

  private:
    std::string* error_;
    bool failed_ = false;
};

bool non_negative(double v) {
    return v >= 0.0 && !std::isnan(v);
}

}  // namespace

bool NewtonOptions::is_valid(std::string* error) const {
    Checker c(error);
    c.require(max_iterations >= 0, "max_iterations", max_iterations, "must be >= 0");
    c.require(max_time_seconds > 0.0, "max_time_seconds", max_time_seconds, "must be > 0");
    c.require(non_negative(gradient_tolerance) && std::isfinite(gradient_tolerance),
              "gradient_tolerance", gradient_tolerance, "must be finite and >= 0");
    c.require(non_negative(decrement_tolerance) && std::isfinite(decrement_tolerance),
              "decrement_tolerance", decrement_tolerance, "must be finite and >= 0");
    c.require(non_negative(function_tolerance) && function_tolerance < 1.0, "function_tolerance",
              function_tolerance, "must be in [0, 1)");
    c.require(non_negative(projection_epsilon) && std::isfinite(projection_epsilon),
              "projection_epsilon", projection_epsilon, "must be finite and >= 0");
    const LineSearchOptions& ls = line_search;
    c.require(ls.initial_step > 0.0 && std::isfinite(ls.initial_step), "line_search.initial_step",
              ls.initial_step, "must be finite and > 0");
    c.require(ls.max_step_fraction > 0.0 && ls.max_step_fraction < 1.0,
              "line_search.max_step_fraction", ls.max_step_fraction, "must be in (0, 1)");
    c.require(ls.backtracking_factor > 0.0 && ls.backtracking_factor < 1.0,
              "line_search.backtracking_factor", ls.backtracking_factor, "must be in (0, 1)");
    c.require(non_negative(ls.armijo) && ls.armijo < 1.0, "line_search.armijo", ls.armijo,
              "must be in [0, 1)");
    c.require(ls.max_trials >= 1, "line_search.max_trials", ls.max_trials, "must be >= 1");
    const RegularizationOptions& r = regularization;
    c.require(r.initial > 0.0 && std::isfinite(r.initial), "regularization.initial", r.initial,
              "must be finite and > 0");
    c.require(r.factor > 1.0 && std::isfinite(r.factor), "regularization.factor", r.factor,
              "must be finite and > 1");
    c.require(r.max >= r.initial && std::isfinite(r.max), "regularization.max", r.max,
              "must be finite and >= regularization.initial");
    c.require(num_threads >= 0, "num_threads", num_threads, "must be >= 0 (0 = all cores)");
    for (std::size_t i = 0; i < callbacks.size(); ++i) {
        c.require(static_cast<bool>(callbacks[i]), "callbacks", i, "callback is empty");
    }
    return c.ok();
}

}  // namespace sa
