#include <gtest/gtest.h>

#include "optim/optim.h"
#include "test_energies.h"

namespace sa {
namespace {

TEST(NewtonOptions, DefaultsAreValid) {
    std::string error;
    EXPECT_TRUE(NewtonOptions{}.is_valid(&error)) << error;
}

// Each case breaks one field; the message must name it.
TEST(NewtonOptions, InvalidFieldsAreNamed) {
    struct Case {
        const char* field;
        void (*breaks)(NewtonOptions&);
    };
    const Case cases[] = {
        {"max_iterations", [](NewtonOptions& o) { o.max_iterations = -1; }},
        {"max_time_seconds", [](NewtonOptions& o) { o.max_time_seconds = 0.0; }},
        {"gradient_tolerance", [](NewtonOptions& o) { o.gradient_tolerance = -1.0; }},
        {"decrement_tolerance", [](NewtonOptions& o) { o.decrement_tolerance = std::nan(""); }},
        {"function_tolerance", [](NewtonOptions& o) { o.function_tolerance = 1.5; }},
        {"projection_epsilon", [](NewtonOptions& o) { o.projection_epsilon = -1e-8; }},
        {"line_search.initial_step", [](NewtonOptions& o) { o.line_search.initial_step = 0.0; }},
        {"line_search.max_step_fraction",
         [](NewtonOptions& o) { o.line_search.max_step_fraction = 1.0; }},
        {"line_search.backtracking_factor",
         [](NewtonOptions& o) { o.line_search.backtracking_factor = 1.0; }},
        {"line_search.armijo", [](NewtonOptions& o) { o.line_search.armijo = -0.1; }},
        {"line_search.max_trials", [](NewtonOptions& o) { o.line_search.max_trials = 0; }},
        {"regularization.initial", [](NewtonOptions& o) { o.regularization.initial = 0.0; }},
        {"regularization.factor", [](NewtonOptions& o) { o.regularization.factor = 1.0; }},
        {"regularization.max", [](NewtonOptions& o) { o.regularization.max = 1e-9; }},
        {"num_threads", [](NewtonOptions& o) { o.num_threads = -2; }},
        {"callbacks", [](NewtonOptions& o) { o.callbacks.push_back(IterationCallback{}); }},
    };
    for (const Case& c : cases) {
        NewtonOptions options;
        c.breaks(options);
        std::string error;
        EXPECT_FALSE(options.is_valid(&error)) << c.field;
        EXPECT_NE(error.find(std::string("NewtonOptions.") + c.field + " = "), std::string::npos)
            << "message '" << error << "' does not name " << c.field;
    }
}

TEST(NewtonOptions, SolveRejectsInvalidOptionsWithTheMessage) {
    Problem problem(Eigen::Vector2d(0.0, 1.0));
    problem.add_term("spring", test::Spring{}, {{0, 1}});
    NewtonOptions options;
    options.line_search.backtracking_factor = 2.0;
    try {
        solve(problem, options);
        FAIL() << "expected InvalidArgumentError";
    } catch (const InvalidArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find("line_search.backtracking_factor = 2"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_EQ(problem.variables(), Eigen::Vector2d(0.0, 1.0));
}

}  // namespace
}  // namespace sa
