#include "combined_runs.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace radiant::bench {
namespace {

// Three runs at two points; the third run found a rare bright path at the second.
const std::vector<std::vector<double>> kRuns = {{1, 10}, {2, 11}, {3, 100}};

TEST(CombinedRuns, MeanAndItsStandardError) {
    const CombinedRuns c = combine_runs(kRuns, false);
    ASSERT_EQ(c.value.size(), 2u);
    EXPECT_DOUBLE_EQ(c.value[0], 2);
    EXPECT_DOUBLE_EQ(c.value[1], 121.0 / 3);
    EXPECT_DOUBLE_EQ(c.standard_error[0], std::sqrt(1.0 / 3));
}

TEST(CombinedRuns, MedianResistsOneRunsBrightPath) {
    const CombinedRuns c = combine_runs(kRuns, true);
    EXPECT_DOUBLE_EQ(c.value[0], 2);
    EXPECT_DOUBLE_EQ(c.value[1], 11);
    // Both points deviate from their median by 0, 1 and 1 or 89: the median deviation is 1.
    const double error = std::sqrt(std::numbers::pi / 2) * 1.4826 / std::sqrt(3.0);
    EXPECT_DOUBLE_EQ(c.standard_error[0], error);
    EXPECT_DOUBLE_EQ(c.standard_error[1], error);
    const CombinedRuns even = combine_runs({{1}, {2}, {4}, {100}}, true);
    EXPECT_DOUBLE_EQ(even.value[0], 3);
}

TEST(CombinedRuns, OneRunHasNoStandardError) {
    const CombinedRuns c = combine_runs({{5, 6}}, false);
    EXPECT_DOUBLE_EQ(c.value[1], 6);
    EXPECT_TRUE(std::isnan(c.standard_error[1]));
}

}  // namespace
}  // namespace radiant::bench
