// Ray sets go where the sensor points' sets spread most: in proportion to the spread within
// each sensor set, never fewer than a point has, each set to its own total.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "montecarlo/set_allotment.h"

namespace radiant {
namespace {

int sum(const std::vector<int>& v, std::size_t first, std::size_t size) {
    return std::accumulate(v.begin() + static_cast<long>(first),
                           v.begin() + static_cast<long>(first + size), 0);
}

TEST(SetAllotment, PointsThatSpreadAlikeGetTheSameSets) {
    const std::vector<int> sets = allot_sets({16}, {8, 8, 8, 8}, {2, 2, 2, 2}, {4});
    EXPECT_EQ(sets, (std::vector<int>{16, 16, 16, 16}));
}

TEST(SetAllotment, SetsFollowTheSpread) {
    // σ 1 and 3: 32 sets split 8 / 24 (n ∝ σ), the least summed variance 1/n₁ + 9/n₂.
    const std::vector<int> sets = allot_sets({16}, {8, 8}, {1, 3}, {2});
    EXPECT_EQ(sets, (std::vector<int>{8, 24}));
    const std::vector<int> more = allot_sets({64}, {8, 24}, {1, 3}, {2});
    EXPECT_EQ(more, (std::vector<int>{32, 96}));
}

TEST(SetAllotment, NoPointLosesSetsAndTheTotalIsMet) {
    // The quiet point has more than its share already: it keeps them, the rest go to the others.
    const std::vector<int> sets = allot_sets({20}, {40, 8, 8}, {1, 2, 2}, {3});
    EXPECT_EQ(sets[0], 40);
    EXPECT_GE(sum(sets, 0, 3), 60);
    EXPECT_LE(sum(sets, 0, 3), 62);
    EXPECT_EQ(sets[1], sets[2]);
}

TEST(SetAllotment, APointWhoseSetsAgreedStillGetsAShare) {
    // Its sets may have missed a rare bright patch: it counts as a quarter of the set's RMS.
    const std::vector<int> sets = allot_sets({100}, {8, 8, 8, 8}, {0, 1, 1, 1}, {4});
    const double rms = std::sqrt(3.0 / 4);
    EXPECT_NEAR(sets[0] / static_cast<double>(sets[1]), kMinSpreadShare * rms, 0.02);
    EXPECT_GE(sum(sets, 0, 4), 400);
    EXPECT_LE(sum(sets, 0, 4), 404);
}

TEST(SetAllotment, EachSensorSetKeepsItsOwnTotal) {
    // A noisy set does not take the rays of a quiet one, and a set without spread (dark, or
    // lit by luminaires alone) gets the sets asked for at every point.
    const std::vector<int> sets =
        allot_sets({10, 10, 10}, {5, 5, 5, 5, 5, 5}, {1, 1, 100, 300, 0, 0}, {2, 2, 2});
    EXPECT_EQ(sets[0], 10);
    EXPECT_EQ(sets[1], 10);
    EXPECT_EQ(sets[2], 5);
    EXPECT_EQ(sets[3], 15);
    EXPECT_EQ(sets[4], 10);
    EXPECT_EQ(sets[5], 10);
}

TEST(SetAllotment, EachSensorSetGetsItsOwnMean) {
    // Without spreads (before any estimate), evenly within each set.
    EXPECT_EQ(allot_sets({4, 12}, {2, 2, 2}, {}, {1, 2}), (std::vector<int>{4, 12, 12}));
    // With them, each set's total is its own mean times its points.
    const std::vector<int> sets = allot_sets({4, 12}, {2, 2, 2}, {5, 1, 3}, {1, 2});
    EXPECT_EQ(sets[0], 4);
    EXPECT_EQ(sets[1] + sets[2], 24);
    EXPECT_EQ(sets[2], 3 * sets[1]);
}

TEST(SetAllotment, NonFiniteSpreadsFallBackToEvenSets) {
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<int> sets =
        allot_sets({12}, {4, 4, 4}, {1, inf, std::numeric_limits<double>::quiet_NaN()}, {3});
    EXPECT_EQ(sets, (std::vector<int>{12, 12, 12}));
}

}  // namespace
}  // namespace radiant
