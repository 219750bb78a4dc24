#include "frontends/simplex_assembly/map_rank.h"

#include <gtest/gtest.h>

namespace sa {
namespace {

TEST(MapRank, FewerFailingSimplicesWinWhateverTheDistortion) {
    EXPECT_TRUE((MapRank{2, 50.0}).better_than(MapRank{3, 1.5}));
    EXPECT_FALSE((MapRank{3, 1.5}).better_than(MapRank{2, 50.0}));
    EXPECT_TRUE((MapRank{0, 50.0}).better_than(MapRank{1, 1.5}));
}

TEST(MapRank, AnEqualCountKeepsTheIncumbentUnlessBothAreValid) {
    EXPECT_FALSE((MapRank{4, 1.5}).better_than(MapRank{4, 9.0}));  // failing maps: no ranking
    EXPECT_TRUE((MapRank{0, 1.5}).better_than(MapRank{0, 9.0}));
    EXPECT_FALSE((MapRank{0, 9.0}).better_than(MapRank{0, 9.0}));
}

TEST(MapRank, AnUnverifiedCandidateReplacesNothing) {
    const MapRank unverified = MapRank::of_verdict(false, 1.0);
    EXPECT_FALSE(unverified.better_than(MapRank::of_verdict(false, 100.0)));
    EXPECT_FALSE(unverified.better_than(MapRank::of_verdict(true, 100.0)));
    EXPECT_TRUE(MapRank::of_verdict(true, 100.0).better_than(unverified));
}

}  // namespace
}  // namespace sa
