// convex_pieces must partition a simple polygon: every piece convex, facing the polygon's way,
// and the pieces' areas adding up to the polygon's area.
#include <gtest/gtest.h>

#include "formfactor/quadrature.h"

#include <sstream>
#include <vector>

#include "geometry/polygon_split.h"

namespace radiant {
namespace {

double total_area(const std::vector<std::vector<Vec3>>& pieces) {
    double a = 0;
    for (const auto& p : pieces) a += polygon_area(p);
    return a;
}

double signed_area(const std::vector<Vec3>& p, const Vec3& n) {
    double a = 0;
    for (std::size_t k = 1; k + 1 < p.size(); ++k)
        a += 0.5 * dot(cross(p[k] - p[0], p[k + 1] - p[0]), n);
    return a;
}

struct SplitCase {
    const char* name;
    std::vector<Vec3> polygon;  // counter-clockwise about n
    Vec3 n;
    double area;
};

std::vector<SplitCase> cases() {
    const std::vector<Vec3> l_shape{{0, 0, 0}, {4, 0, 0}, {4, 2, 0},
                                    {2, 2, 0}, {2, 4, 0}, {0, 4, 0}};
    std::vector<Vec3> l_reversed(l_shape.rbegin(), l_shape.rend());
    const std::vector<Vec3> u_shape{{0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {2, 3, 0},
                                    {2, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}};
    return {{"l_floor", l_shape, {0, 0, 1}, 12},
            {"l_ceiling", l_reversed, {0, 0, -1}, 12},
            {"u_floor", u_shape, {0, 0, 1}, 7}};
}

class ConvexPieces : public ::testing::TestWithParam<std::size_t> {};

TEST_P(ConvexPieces, PartitionThePolygon) {
    const SplitCase c = cases()[GetParam()];
    const auto pieces = convex_pieces(c.polygon, c.n, 1e-9);
    ASSERT_FALSE(pieces.empty());
    double sum = 0, sum_abs = 0;
    std::ostringstream listing;
    bool reversed = false;
    for (const auto& p : pieces) {
        const double a = signed_area(p, c.n);
        sum += a;
        sum_abs += std::abs(a);
        reversed = reversed || a <= 0;
        listing << " [";
        for (const Vec3& v : p) listing << " (" << v.x << "," << v.y << ")";
        listing << " ] area " << a << ";";
    }
    const std::string what = std::string(c.name) + ": " + std::to_string(pieces.size()) +
                             " pieces, signed areas sum " + std::to_string(sum) +
                             ", absolute areas sum " + std::to_string(sum_abs) + " (exact " +
                             std::to_string(c.area) + "):" + listing.str();
    EXPECT_NEAR(sum, c.area, 1e-9) << what;
    EXPECT_NEAR(sum_abs, c.area, 1e-9) << what;
    for (const auto& p : pieces) EXPECT_TRUE(is_convex(p, c.n)) << what;
}

INSTANTIATE_TEST_SUITE_P(Shapes, ConvexPieces, ::testing::Range<std::size_t>(0, 3),
                         [](const auto& param_info) { return cases()[param_info.param].name; });

// The reflex vertex (2,2) lies exactly on the diagonal (4,0)-(0,4): a cut there overlaps.
TEST(Triangulate, LShapeWithReflexVertexOnADiagonal) {
    const std::vector<Vec3> l{{0, 0, 0}, {4, 0, 0}, {4, 2, 0}, {2, 2, 0}, {2, 4, 0}, {0, 4, 0}};
    const auto tris = triangulate(l, {0, 0, 1});
    EXPECT_EQ(tris.size(), 4u);
    EXPECT_NEAR(total_area(tris), 12.0, 1e-12);
}

TEST(Triangulate, KeepsOrientationSeenFromBelow) {
    const std::vector<Vec3> l{{0, 0, 3}, {0, 4, 3}, {2, 4, 3}, {2, 2, 3}, {4, 2, 3}, {4, 0, 3}};
    const auto tris = triangulate(l, {0, 0, -1});
    EXPECT_NEAR(total_area(tris), 12.0, 1e-12);
    for (const auto& t : tris) EXPECT_LT(polygon_normal(t).z, 0);
}

TEST(Triangulate, CombWithCollinearVertices) {
    const std::vector<Vec3> comb{{0, 0, 0}, {3, 0, 0}, {3, 2, 0}, {2, 2, 0}, {2, 1, 0},
                                 {1, 1, 0}, {1, 2, 0}, {0, 2, 0}, {0, 1, 0}};
    EXPECT_NEAR(total_area(triangulate(comb, {0, 0, 1})), 5.0, 1e-12);
}

TEST(ConvexPieces, ConvexPlanarPolygonStaysWhole) {
    const std::vector<Vec3> quad{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const auto pieces = convex_pieces(quad, {0, 0, 1}, 1e-9);
    ASSERT_EQ(pieces.size(), 1u);
    EXPECT_EQ(pieces[0].size(), 4u);
}

TEST(SplitByPlane, HalvesASquare) {
    const std::vector<Vec3> quad{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
    const auto [pos, neg] = split_by_plane(quad, {1, 0, 0}, {1, 0, 0}, 1e-12);
    EXPECT_NEAR(polygon_area(pos), 2.0, 1e-12);
    EXPECT_NEAR(polygon_area(neg), 2.0, 1e-12);
}

}  // namespace
}  // namespace radiant
