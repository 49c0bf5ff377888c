#include "geometry/polygon_split.h"

#include <gtest/gtest.h>

#include "formfactor/quadrature.h"

namespace radiant {
namespace {

double total_area(const std::vector<std::vector<Vec3>>& pieces) {
    double a = 0;
    for (const auto& p : pieces) a += polygon_area(p);
    return a;
}

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
