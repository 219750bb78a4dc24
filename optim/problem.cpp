#include "optim/problem.h"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace sa {

namespace {
std::atomic<std::uint64_t> next_problem_id{1};
}

Problem::Problem(Eigen::VectorXd variables)
    : variables_(std::move(variables)), fixed_(variables_.size(), 0), id_(next_problem_id++) {}

void Problem::set_variables(const Eigen::VectorXd& variables) {
    if (variables.size() != variables_.size()) {
        std::ostringstream msg;
        msg << "set_variables: expected " << variables_.size() << " values, got "
            << variables.size();
        throw InvalidArgumentError(msg.str());
    }
    variables_ = variables;
}

void Problem::check_element_index(const std::string& term, std::size_t element, Index v) const {
    if (v < 0 || v >= num_variables()) {
        std::ostringstream msg;
        msg << "term '" << term << "': element " << element << " names variable " << v
            << ", outside [0, " << num_variables() << ")";
        throw InvalidArgumentError(msg.str());
    }
}

void Problem::check_element_arity(const std::string& term, Index element, int arity, int expected,
                                  int block) {
    if (arity > 0 && arity == expected && (block == 0 || arity % block == 0)) return;
    std::ostringstream msg;
    msg << "term '" << term << "': element " << element << " names " << arity << " variables";
    if (arity == 0) {
        msg << "; an element names at least one";
    } else if (arity != expected) {
        msg << ", its energy's data expects " << expected;
    } else {
        msg << ", not a multiple of the energy's Hessian block " << block;
    }
    throw InvalidArgumentError(msg.str());
}

void Problem::check_element_data(const std::string& term, std::size_t elements,
                                 const std::vector<std::size_t>& sizes, const char* what) {
    for (std::size_t k = 0; k < sizes.size(); ++k) {
        if (sizes[k] == elements) continue;
        std::ostringstream msg;
        msg << "term '" << term << "': " << what;
        if (sizes.size() > 1) msg << " (array " << k + 1 << " of " << sizes.size() << ")";
        msg << " has " << sizes[k] << " entries for " << elements << " elements";
        throw InvalidArgumentError(msg.str());
    }
}

void Problem::set_fixed(Index variable, bool fixed) {
    if (variable < 0 || variable >= num_variables()) {
        std::ostringstream msg;
        msg << "set_fixed: variable " << variable << " outside [0, " << num_variables() << ")";
        throw InvalidArgumentError(msg.str());
    }
    if ((fixed_[variable] != 0) != fixed) {
        fixed_[variable] = fixed ? 1 : 0;
        ++structure_version_;
    }
}

Index Problem::num_free_variables() const {
    return static_cast<Index>(std::count(fixed_.begin(), fixed_.end(), 0));
}

BlockId Problem::add_variable_block(std::string name, Index begin, Index end) {
    if (begin < 0 || end > num_variables() || begin >= end) {
        std::ostringstream msg;
        msg << "variable block '" << name << "': range [" << begin << ", " << end
            << ") is empty or outside [0, " << num_variables() << ")";
        throw InvalidArgumentError(msg.str());
    }
    for (const VariableBlock& b : blocks_) {
        if (begin < b.end && b.begin < end) {
            std::ostringstream msg;
            msg << "variable block '" << name << "' [" << begin << ", " << end
                << ") overlaps block '" << b.name << "' [" << b.begin << ", " << b.end << ")";
            throw InvalidArgumentError(msg.str());
        }
    }
    blocks_.push_back(VariableBlock{std::move(name), begin, end});
    return static_cast<BlockId>(blocks_.size() - 1);
}

void Problem::set_hessian_shift(BlockId id, double shift) {
    if (!std::isfinite(shift) || shift < 0.0) {
        std::ostringstream msg;
        msg << "variable block '" << blocks_.at(id).name
            << "': Hessian shift must be finite and >= 0, got " << shift;
        throw InvalidArgumentError(msg.str());
    }
    blocks_.at(id).hessian_shift = shift;
}

void Problem::set_regularize_on_failure(BlockId id, bool regularize) {
    blocks_.at(id).regularize_on_failure = regularize;
}

double Problem::value(const Eigen::VectorXd& x, std::vector<double>* term_values) const {
    if (term_values != nullptr) term_values->assign(terms_.size(), 0.0);
    double total = 0.0;
    for (std::size_t t = 0; t < terms_.size(); ++t) {
        const double v = terms_[t]->value(x);
        if (term_values != nullptr) (*term_values)[t] = v;
        if (!(v < kInfinity)) return v;  // +inf (infeasible) or NaN
        total += terms_[t]->weight() * v;
    }
    return total;
}

double Problem::max_step(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) const {
    double step = kInfinity;
    for (const auto& term : terms_) step = std::min(step, term->max_step(x, dx));
    return step;
}

}  // namespace sa
