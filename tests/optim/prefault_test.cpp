#include "optim/detail/prefault.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace sa {
namespace {

TEST(Prefault, AssignGivesTheValuesForLargeAndSmallVectors) {
    for (std::size_t n : {std::size_t(0), std::size_t(10), std::size_t(1) << 20}) {
        std::vector<std::int64_t> v{1, 2, 3};
        assign_prefaulted(v, n, std::int64_t{-7});
        ASSERT_EQ(v.size(), n);
        for (std::int64_t x : v) ASSERT_EQ(x, -7);
    }
}

TEST(Prefault, KeepsTheBufferWhenItIsLargeEnough) {
    std::vector<double> v(std::size_t(1) << 18, 1.0);
    const double* data = v.data();
    assign_prefaulted(v, std::size_t(1) << 17, 2.0);
    EXPECT_EQ(v.data(), data);
    EXPECT_EQ(v.size(), std::size_t(1) << 17);
    EXPECT_EQ(v.back(), 2.0);
}

TEST(Prefault, LeavesTheContentsOfMappedMemory) {
    std::vector<double> v(std::size_t(1) << 20, 3.5);
    prefault(v.data(), v.size() * sizeof(double));
    prefault(v.data() + 1, 100);  // below the threshold: nothing
    prefault(nullptr, 1 << 20);
    for (double x : v) ASSERT_EQ(x, 3.5);
}

}  // namespace
}  // namespace sa
