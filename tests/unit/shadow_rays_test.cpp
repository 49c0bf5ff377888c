// Sampled visibility between a point and a polygon: the share of the factor, not of the area.
#include "formfactor/shadow_rays.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "formfactor/point_polygon.h"
#include "visibility/visibility.h"

namespace radiant {
namespace {

const Vec3 kUp{0, 0, 1};
const Vec3 kDown{0, 0, -1};

// A 4 × 4 m source 1 m above a point facing it; an opaque sheet halfway up covers x > 0.25, so
// the point sees the source where x < 0.5: the part right above it, where the kernel is largest.
TEST(ShadowRays, CountEachRayByTheKernelTowardItsTarget) {
    const std::vector<Vec3> source{{-2, 2, 1}, {2, 2, 1}, {2, -2, 1}, {-2, -2, 1}};
    const std::vector<Vec3> seen{{-2, 2, 1}, {0.5, 2, 1}, {0.5, -2, 1}, {-2, -2, 1}};
    const std::vector<Triangle> sheet{{{0.25, -9, 0.5}, {9, -9, 0.5}, {9, 9, 0.5}},
                                      {{0.25, -9, 0.5}, {9, 9, 0.5}, {0.25, 9, 0.5}}};
    const auto visibility = make_embree_visibility(sheet);
    const Vec3 x{0, 0, 0};
    const double exact = front_point_to_polygon_factor(x, kUp, seen, kDown) /
                         front_point_to_polygon_factor(x, kUp, source, kDown);
    const double area_share = 2.5 / 4;
    ASSERT_GT(exact - area_share, 0.1);  // the case tells the two apart

    SampleStream rng(7, 1, 2);
    std::uint64_t rays = 0;
    const double fraction =
        visible_fraction(*visibility, x, kUp, source, {0, 0, 1}, kDown, 256, rng, rays);
    EXPECT_EQ(rays, 256u);
    EXPECT_NEAR(fraction, exact, 0.02);
}

// Every target behind the point: no kernel to weigh by, so the rays count alike.
TEST(ShadowRays, TargetsBehindThePointCountAlike) {
    const std::vector<Vec3> source{{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}};
    const auto visibility = make_embree_visibility(std::vector<Triangle>{});
    SampleStream rng(7, 1, 2);
    std::uint64_t rays = 0;
    EXPECT_EQ(visible_fraction(*visibility, {0, 0, 0}, kUp, source, {0, 0, -1}, kUp, 16, rng, rays),
              1.0);
}

}  // namespace
}  // namespace radiant
