#include "formfactor/point_polygon.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "analytic_form_factors.h"

namespace radiant {
namespace {

constexpr double kPi = std::numbers::pi;
const Vec3 kUp{0, 0, 1};

// Axis-aligned square [−s/2, s/2]² centred above the origin at height h.
std::vector<Vec3> centred_square(double s, double h) {
    const double r = 0.5 * s;
    return {{-r, -r, h}, {r, -r, h}, {r, r, h}, {-r, r, h}};
}

// Rotation about the axis (1, 2, 3)/|·| by 0.7 rad (Rodrigues), for invariance checks.
Vec3 rotate(const Vec3& v) {
    const Vec3 k = normalized({1, 2, 3});
    const double c = std::cos(0.7), s = std::sin(0.7);
    return v * c + cross(k, v) * s + k * (dot(k, v) * (1 - c));
}

TEST(PointPolygon, CentredSquareMatchesCornerSuperposition) {
    const double expected[] = {0.239456, 0.968340, 0.999673, 0.999997};
    const double heights[] = {1.0, 0.1, 0.01, 0.001};
    for (int i = 0; i < 4; ++i) {
        const double exact = 4 * analytic::point_to_corner_rectangle(0.5, 0.5, heights[i]);
        const double f = point_to_polygon_factor({}, kUp, centred_square(1, heights[i]));
        EXPECT_NEAR(f, exact, 1e-9 * exact) << "h = " << heights[i];
        EXPECT_NEAR(f, expected[i], 1e-6) << "h = " << heights[i];
    }
}

TEST(PointPolygon, CornerRectangleTable) {
    // §1.4 rows: (a, b, c) → F.
    const double rows[][4] = {{1, 1, 1, 0.138532},
                              {0.5, 0.5, 1, 0.0598641},
                              {2, 1, 1, 0.167375},
                              {10, 10, 1, 0.247971},
                              {1, 1, 0.01, 0.249980}};
    for (const auto& r : rows) {
        const std::vector<Vec3> rect{
            {0, 0, r[2]}, {r[0], 0, r[2]}, {r[0], r[1], r[2]}, {0, r[1], r[2]}};
        EXPECT_NEAR(point_to_polygon_factor({}, kUp, rect), r[3], 1e-6);
        EXPECT_NEAR(point_to_polygon_factor({}, kUp, rect),
                    analytic::point_to_corner_rectangle(r[0], r[1], r[2]), 1e-14);
    }
}

TEST(PointPolygon, OrientationAndRigidMotionInvariance) {
    std::vector<Vec3> square = centred_square(1, 0.3);
    const double f = point_to_polygon_factor({}, kUp, square);
    const std::vector<Vec3> reversed(square.rbegin(), square.rend());
    EXPECT_NEAR(point_to_polygon_factor({}, kUp, reversed), f, 1e-15);
    std::vector<Vec3> moved;
    const Vec3 shift{1e3, -2e3, 5e2};
    for (const Vec3& v : square) moved.push_back(rotate(v) + shift);
    EXPECT_NEAR(point_to_polygon_factor(shift, rotate(kUp), moved), f, 1e-11);
}

TEST(PointPolygon, TiltedPyramidFacesShareTheHemisphere) {
    // The four faces of a pyramid over the base [−1,1]² close the hemisphere above the base
    // centre: each sees 1/4 by symmetry, and any apex gives a total of 1 (closure).
    for (const Vec3 apex : {Vec3{0, 0, 1}, Vec3{0.3, -0.6, 0.4}}) {
        const Vec3 base[] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
        double total = 0.0;
        for (int k = 0; k < 4; ++k) {
            const std::vector<Vec3> face{base[k], base[(k + 1) % 4], apex};
            const double f = point_to_polygon_factor({0.1, 0.2, 0}, kUp, face);
            if (apex == Vec3{0, 0, 1}) {
                EXPECT_NEAR(point_to_polygon_factor({}, kUp, face), 0.25, 1e-15);
            }
            total += f;
        }
        EXPECT_NEAR(total, 1.0, 1e-14);
    }
}

TEST(PointPolygon, PartlyBehindPolygonIsClipped) {
    // Box [−1,1]² × [0,1] around the point: top + 4 sides = 1, so one side (a wall reaching
    // below the receiver plane to z = −1) sees (1 − 4 F_corner(1,1,1)) / 4.
    const double exact = (1 - 4 * analytic::point_to_corner_rectangle(1, 1, 1)) / 4;
    const std::vector<Vec3> wall{{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}};
    EXPECT_NEAR(point_to_polygon_factor({}, kUp, wall), exact, 1e-14);
    const std::vector<Vec3> behind{{-1, -1, -1}, {1, -1, -1}, {1, 1, -0.5}, {-1, 1, -0.5}};
    EXPECT_EQ(point_to_polygon_factor({}, kUp, behind), 0.0);
}

TEST(PointPolygon, CollinearAndDuplicateVerticesChangeNothing) {
    const double f = point_to_polygon_factor({}, kUp, centred_square(1, 1));
    const std::vector<Vec3> padded{{-0.5, -0.5, 1}, {-0.5, -0.5, 1}, {0, -0.5, 1},  {0.5, -0.5, 1},
                                   {0.5, 0.5, 1},   {0.5, 0.5, 1},   {-0.5, 0.5, 1}};
    EXPECT_NEAR(point_to_polygon_factor({}, kUp, padded), f, 1e-15);
}

TEST(PointPolygon, DegenerateInputGivesZeroNotNaN) {
    const std::vector<Vec3> line{{0, 0, 1}, {1, 0, 1}, {2, 0, 1}};
    const std::vector<Vec3> two{{0, 0, 1}, {1, 0, 1}};
    const std::vector<Vec3> point{{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    EXPECT_EQ(point_to_polygon_factor({}, kUp, line), 0.0);
    EXPECT_EQ(point_to_polygon_factor({}, kUp, two), 0.0);
    EXPECT_EQ(point_to_polygon_factor({}, kUp, point), 0.0);
    EXPECT_EQ(point_to_polygon_factor({0, 0, 1}, kUp, point), 0.0);
    EXPECT_EQ(point_to_polygon_factor({}, Vec3{}, centred_square(1, 1)), 0.0);
    EXPECT_EQ(polygon_solid_angle({}, line), 0.0);
}

TEST(PointPolygon, EdgeOnPolygonSeesNothing) {
    // Polygon in a plane through x (x outside it) and polygon in the receiver plane.
    const std::vector<Vec3> vertical{{1, 0, 0.5}, {2, 0, 0.5}, {2, 0, 1.5}, {1, 0, 1.5}};
    EXPECT_NEAR(point_to_polygon_factor({0, 0, 0.5}, kUp, vertical), 0.0, 1e-15);
    const std::vector<Vec3> flat{{1, 1, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0}};
    EXPECT_NEAR(point_to_polygon_factor({}, kUp, flat), 0.0, 1e-15);
}

TEST(PointPolygon, FactorStaysInUnitInterval) {
    EXPECT_NEAR(point_to_polygon_factor({}, kUp, centred_square(1e6, 1e-6)), 1.0, 1e-12);
    EXPECT_LE(point_to_polygon_factor({}, kUp, centred_square(1e6, 1e-6)), 1.0);
}

TEST(PointPolygon, NonConvexPolygonEqualsSumOfParts) {
    // An L shape = unit square + the square to its right + the square above.
    const double h = 0.7;
    const std::vector<Vec3> ell{{0, 0, h}, {2, 0, h}, {2, 1, h}, {1, 1, h}, {1, 2, h}, {0, 2, h}};
    const double parts = analytic::point_to_corner_rectangle(2, 1, h) +
                         analytic::point_to_corner_rectangle(1, 2, h) -
                         analytic::point_to_corner_rectangle(1, 1, h);
    EXPECT_NEAR(point_to_polygon_factor({}, kUp, ell), parts, 1e-14);
}

TEST(SolidAngle, CubeFacesFromInsideSumToFourPi) {
    const Vec3 c[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                       {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    const std::vector<std::vector<Vec3>> faces{{c[0], c[3], c[2], c[1]}, {c[4], c[5], c[6], c[7]},
                                               {c[0], c[1], c[5], c[4]}, {c[1], c[2], c[6], c[5]},
                                               {c[2], c[3], c[7], c[6]}, {c[3], c[0], c[4], c[7]}};
    for (const Vec3 x : {Vec3{0.5, 0.5, 0.5}, Vec3{0.1, 0.7, 0.25}}) {
        double total = 0.0;
        for (const auto& f : faces) {
            const double omega = polygon_solid_angle(x, f);
            if (x == Vec3{0.5, 0.5, 0.5}) {
                EXPECT_NEAR(omega, 2 * kPi / 3, 1e-14);
            }
            total += omega;
        }
        EXPECT_NEAR(total, 4 * kPi, 1e-13);
    }
}

TEST(SolidAngle, LargeNearPlaneApproachesHemisphere) {
    EXPECT_NEAR(polygon_solid_angle({}, centred_square(1e6, 1e-6)), 2 * kPi, 1e-11);
    // Lambert's projected solid angle of the same plane is π (F = 1), a cross-check of both.
    EXPECT_NEAR(point_to_polygon_factor({}, kUp, centred_square(1e6, 1e-6)) * kPi, kPi, 1e-11);
}

TEST(SolidAngle, NonConvexAndTriangleCases) {
    const double h = 0.7;
    const std::vector<Vec3> ell{{0, 0, h}, {2, 0, h}, {2, 1, h}, {1, 1, h}, {1, 2, h}, {0, 2, h}};
    const std::vector<Vec3> a{{0, 0, h}, {2, 0, h}, {2, 1, h}, {0, 1, h}};
    const std::vector<Vec3> b{{0, 1, h}, {1, 1, h}, {1, 2, h}, {0, 2, h}};
    EXPECT_NEAR(polygon_solid_angle({}, ell),
                polygon_solid_angle({}, a) + polygon_solid_angle({}, b), 1e-14);
    // Start the fan at the reflex vertex: the fan folds over, signed terms must cancel.
    const std::vector<Vec3> rotated{{1, 1, h}, {1, 2, h}, {0, 2, h},
                                    {0, 0, h}, {2, 0, h}, {2, 1, h}};
    EXPECT_NEAR(polygon_solid_angle({}, rotated), polygon_solid_angle({}, ell), 1e-14);
    // Octant triangle: π/2 sr.
    const std::vector<Vec3> octant{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    EXPECT_NEAR(polygon_solid_angle({}, octant), kPi / 2, 1e-14);
}

TEST(Clip, SutherlandHodgmanKeepsFrontPart) {
    const std::vector<Vec3> square{{0, 0, -1}, {1, 0, -1}, {1, 0, 1}, {0, 0, 1}};
    const auto front = clip_to_halfspace(square, {}, kUp);
    ASSERT_EQ(front.size(), 4u);
    for (const Vec3& p : front) EXPECT_GE(p.z, 0.0);
    // Vertices exactly on the plane are kept once, without extra intersection points.
    const std::vector<Vec3> touching{{0, 0, 0}, {1, 0, 0}, {1, 0, 1}};
    EXPECT_EQ(clip_to_halfspace(touching, {}, kUp).size(), 3u);
    const std::vector<Vec3> below{{0, 0, 0}, {1, 0, 0}, {1, 0, -1}};
    EXPECT_EQ(clip_to_halfspace(below, {}, kUp).size(), 2u);
}

}  // namespace
}  // namespace radiant
