#include "frontends/simplex_assembly/bound_rounds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "optim/errors.h"

namespace sa {
namespace {

constexpr double kInf = INFINITY;

// A round that records its bounds and returns the next of `reached` (one largest distortion per
// bound), or nothing once they run out.
struct ScriptedRounds {
    explicit ScriptedRounds(std::vector<std::vector<double>> script = {})
        : reached(std::move(script)) {}
    std::vector<std::vector<double>> reached;
    std::vector<std::vector<double>> asked;
    BoundRoundSolve solve() {
        return [this](const std::vector<double>& bounds) -> std::optional<std::vector<double>> {
            asked.push_back(bounds);
            if (asked.size() > reached.size()) return std::nullopt;
            return reached[asked.size() - 1];
        };
    }
};

TEST(BoundRounds, AStartOverItsTargetIsLoweredWithHeadroomThenSolvedAtTheTarget) {
    const BoundRule rule{.max_rounds = 30, .headroom = 0.1, .tolerance = 0.01};
    ScriptedRounds rounds({{5.0}, {2.5}, {2.4}});
    const TimeBudget budget(kInf);
    const BoundRoundsEnd end = run_bound_rounds(rule, {{.target = 3.0, .identity = 1.0}}, {kInf},
                                                {9.0}, budget, rounds.solve());
    ASSERT_EQ(rounds.asked.size(), 3u);
    EXPECT_DOUBLE_EQ(rounds.asked[0][0], 9.0 + 0.1 * 8.0);
    EXPECT_DOUBLE_EQ(rounds.asked[1][0], 5.0 + 0.1 * 4.0);
    EXPECT_DOUBLE_EQ(rounds.asked[2][0], 3.0);  // reached: a round at the target itself
    EXPECT_EQ(end, BoundRoundsEnd::kAtTarget);
}

TEST(BoundRounds, AStalledRoundBelowTheTargetStillGetsTheRoundAtTheTarget) {
    const BoundRule rule{.max_rounds = 30, .headroom = 0.1, .tolerance = 0.5};
    ScriptedRounds rounds({{2.9}, {2.85}});
    const TimeBudget budget(kInf);
    const BoundRoundsEnd end = run_bound_rounds(rule, {{.target = 3.0, .identity = 1.0}}, {kInf},
                                                {3.1}, budget, rounds.solve());
    ASSERT_EQ(rounds.asked.size(), 2u);
    EXPECT_DOUBLE_EQ(rounds.asked[1][0], 3.0);
    EXPECT_EQ(end, BoundRoundsEnd::kAtTarget);
}

TEST(BoundRounds, ProgressIsMeasuredFromTheIdentitysDistortion) {
    // Near the identity a share of d itself would stop rounds that still halve d - 1.
    const BoundRule rule{.max_rounds = 10, .tolerance = 1e-3};
    ScriptedRounds rounds({{1.0 + 2e-4}, {1.0 + 1e-4}, {1.0 + 0.9999e-4}});
    const TimeBudget budget(kInf);
    const BoundRoundsEnd end = run_bound_rounds(rule, {{.target = 1.0, .identity = 1.0}}, {kInf},
                                                {1.0 + 4e-4}, budget, rounds.solve());
    EXPECT_EQ(rounds.asked.size(), 3u);
    EXPECT_DOUBLE_EQ(rounds.asked[0][0], 1.0 + 4e-4);  // margin 0: the largest distortion itself
    EXPECT_EQ(end, BoundRoundsEnd::kNoProgress);
}

TEST(BoundRounds, ABoundAtTheIdentitysDistortionIsKeptWhileTheOthersAreLowered) {
    const BoundRule rule{.max_rounds = 10, .margin = 1e-6, .tolerance = 1e-3};
    ScriptedRounds rounds({{1.0, 1.5}});
    const TimeBudget budget(kInf);
    const std::vector<RoundedBound> rounded = {{.target = 1.0, .identity = 1.0},
                                               {.target = 1.0, .identity = 1.0}};
    const BoundRoundsEnd end =
        run_bound_rounds(rule, rounded, {4.0, 4.0}, {1.0, 2.0}, budget, rounds.solve());
    ASSERT_GE(rounds.asked.size(), 1u);
    EXPECT_EQ(rounds.asked[0][0], 4.0);
    EXPECT_DOUBLE_EQ(rounds.asked[0][1], 2.0 * (1.0 + 1e-6));
    ASSERT_EQ(rounds.asked.size(), 2u);
    EXPECT_EQ(end, BoundRoundsEnd::kRoundFailed);  // the script has no second result
}

TEST(BoundRounds, EveryBoundAtTheIdentityRunsNoRound) {
    ScriptedRounds rounds;
    const TimeBudget budget(kInf);
    const BoundRoundsEnd end = run_bound_rounds(BoundRule{}, {{.target = 1.0, .identity = 1.0}},
                                                {kInf}, {1.0 + 1e-12}, budget, rounds.solve());
    EXPECT_TRUE(rounds.asked.empty());
    EXPECT_EQ(end, BoundRoundsEnd::kAtTarget);
}

TEST(BoundRounds, TheRoundLimitAndTheTimeLimitEndTheRounds) {
    const BoundRule two{.max_rounds = 2, .tolerance = 1e-3};
    ScriptedRounds rounds({{3.0}, {2.0}, {1.5}});
    const TimeBudget unlimited(kInf);
    EXPECT_EQ(run_bound_rounds(two, {{.target = 1.0, .identity = 1.0}}, {kInf}, {4.0}, unlimited,
                               rounds.solve()),
              BoundRoundsEnd::kRoundLimit);
    EXPECT_EQ(rounds.asked.size(), 2u);

    ScriptedRounds none(std::vector<std::vector<double>>{{3.0}});
    const TimeBudget spent(0.0);
    EXPECT_EQ(run_bound_rounds(two, {{.target = 1.0, .identity = 1.0}}, {kInf}, {4.0}, spent,
                               none.solve()),
              BoundRoundsEnd::kTimeLimit);
    EXPECT_TRUE(none.asked.empty());
}

TEST(BoundRounds, ARuleOutOfRangeIsRefusedByName) {
    BoundRule rule;
    rule.headroom = 1.5;
    try {
        rule.validate("optimal bound");
        FAIL() << "accepted headroom 1.5";
    } catch (const InvalidArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find("headroom"), std::string::npos) << e.what();
    }
    const TimeBudget budget(kInf);
    EXPECT_THROW(run_bound_rounds(BoundRule{}, {{}}, {}, {1.0}, budget, ScriptedRounds{}.solve()),
                 InvalidArgumentError);
}

}  // namespace
}  // namespace sa
