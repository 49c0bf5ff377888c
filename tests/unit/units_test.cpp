#include <gtest/gtest.h>

#include "radiant/scene.h"

TEST(Units, MetresPerUnitAreExact) {
    EXPECT_DOUBLE_EQ(radiant::meters_per_unit(radiant::LengthUnit::m), 1.0);
    EXPECT_DOUBLE_EQ(radiant::meters_per_unit(radiant::LengthUnit::mm), 0.001);
    EXPECT_DOUBLE_EQ(radiant::meters_per_unit(radiant::LengthUnit::ft), 0.3048);
    EXPECT_DOUBLE_EQ(radiant::meters_per_unit(radiant::LengthUnit::in), 0.0254);
}
