// Area-to-area factors by quadrature of Lambert's exact point-to-polygon factor over the
// receiver (the analytic inner integral of algorithms.md §3), checked against the closed forms
// of validation README §1 and the identities of §1.9 and §5.2.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "analytic_form_factors.h"
#include "formfactor/area_average.h"
#include "formfactor/point_polygon.h"
#include "formfactor/quadrature.h"

namespace radiant {
namespace {

using Quad = std::array<Vec3, 4>;

Quad rect(const Vec3& o, const Vec3& e1, const Vec3& e2) {
    return {o, o + e1, o + e1 + e2, o + e2};
}

Vec3 bilinear(const Quad& q, double s, double t) {
    return q[0] * ((1 - s) * (1 - t)) + q[1] * (s * (1 - t)) + q[2] * (s * t) +
           q[3] * ((1 - s) * t);
}

// F_ij = (1/A_i) Σ_k w_k F(x_k → P_j): receiver i split into n × n sub-quads, each with a
// degree-5 rule, so no sample sits on a shared edge.
double area_factor(const Quad& receiver, std::span<const Vec3> source, int n) {
    const Vec3 normal = polygon_normal(receiver);
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const double s0 = double(i) / n, s1 = double(i + 1) / n;
            const double t0 = double(j) / n, t1 = double(j + 1) / n;
            const Quad sub{bilinear(receiver, s0, t0), bilinear(receiver, s1, t0),
                           bilinear(receiver, s1, t1), bilinear(receiver, s0, t1)};
            for (const auto& q : polygon_quadrature(sub, 5)) {
                sum += q.weight * point_to_polygon_factor(q.position, normal, source);
            }
        }
    }
    return sum / polygon_area(receiver);
}

// The six faces of the box [0,a]×[0,b]×[0,c], vertex order giving inward normals:
// floor, ceiling, y = 0, y = b, x = 0, x = a.
std::array<Quad, 6> box(double a, double b, double c) {
    const Vec3 x{a, 0, 0}, y{0, b, 0}, z{0, 0, c};
    return {rect({}, x, y), rect(z, y, x),  rect({}, z, x),
            rect(y, x, z),  rect({}, y, z), rect(x, z, y)};
}

TEST(AnalyticFormFactors, TabulatedValues) {
    EXPECT_NEAR(analytic::parallel_coaxial_rectangles(1, 1, 1), 0.199825, 1e-6);
    EXPECT_NEAR(analytic::parallel_coaxial_rectangles(1, 1, 0.5), 0.415253, 1e-6);
    EXPECT_NEAR(analytic::parallel_coaxial_rectangles(4, 4, 3), 0.282733, 1e-6);
    EXPECT_NEAR(analytic::parallel_coaxial_rectangles(1, 1, 0.001), 0.998006, 1e-6);
    EXPECT_NEAR(analytic::perpendicular_common_edge(1, 1, 1), 0.200044, 1e-6);
    EXPECT_NEAR(analytic::perpendicular_common_edge(1, 2, 1), 0.116426, 1e-6);
    EXPECT_NEAR(analytic::perpendicular_common_edge(4, 4, 3), 0.179317, 1e-6);
    EXPECT_NEAR(analytic::perpendicular_common_edge(1, 0.01, 1), 0.489585, 1e-6);
    EXPECT_NEAR(analytic::perpendicular_common_edge(1, 1e-4, 1), 0.499823, 1e-6);
    EXPECT_NEAR(analytic::point_to_corner_rectangle(1, 1, 1), 0.138532, 1e-6);
    EXPECT_NEAR(4 * analytic::point_to_corner_rectangle(0.5, 0.5, 1), 0.239456, 1e-6);
    EXPECT_NEAR(4 * analytic::point_to_corner_rectangle(2, 2, 3), 0.357685, 1e-6);
    EXPECT_NEAR(analytic::point_to_coaxial_disc(1, 0.1), 0.990099, 1e-6);
    EXPECT_NEAR(analytic::point_to_offset_disc(1, 1, 2), 0.0527864, 1e-7);
    EXPECT_NEAR(analytic::point_to_offset_disc(1, 2, 1), 0.146447, 1e-6);
    EXPECT_NEAR(analytic::coaxial_discs(1, 1, 1), (3 - std::sqrt(5.0)) / 2, 1e-15);
    EXPECT_NEAR(analytic::coaxial_discs(0.5, 1, 2), 0.192236, 1e-6);
    EXPECT_NEAR(analytic::coaxial_discs(2, 1, 1), 0.190983, 1e-6);
}

TEST(AnalyticFormFactors, GeneralPositionSumsReproduceSpecialCases) {
    EXPECT_NEAR(analytic::parallel_rectangles(0, 1, 0, 1, 0, 1, 0, 1, 1), 0.199825, 1e-6);
    EXPECT_NEAR(analytic::parallel_rectangles(0, 4, 0, 4, 0, 4, 0, 4, 3),
                analytic::parallel_coaxial_rectangles(4, 4, 3), 1e-13);
    EXPECT_NEAR(analytic::perpendicular_rectangles(0, 1, 0, 1, 0, 1, 0, 1), 0.200044, 1e-6);
    EXPECT_NEAR(analytic::perpendicular_rectangles(0, 2, 0, 1, 0, 1, 0, 1),
                analytic::perpendicular_common_edge(1, 2, 1), 1e-13);
    // Cube closure through the general sums: 4 F_adj + F_opp = 1.
    EXPECT_NEAR(4 * analytic::perpendicular_rectangles(0, 1, 0, 1, 0, 1, 0, 1) +
                    analytic::parallel_rectangles(0, 1, 0, 1, 0, 1, 0, 1, 1),
                1.0, 1e-14);
}

TEST(AreaFactor, ParallelSquaresConvergeWithinOnePermille) {
    struct Case {
        double side, distance;
    };
    for (const Case c : {Case{1, 0.5}, Case{1, 1}, Case{1, 2}, Case{4, 3}}) {
        const Quad receiver = rect({}, {c.side, 0, 0}, {0, c.side, 0});
        const Quad source = rect({0, 0, c.distance}, {0, c.side, 0}, {c.side, 0, 0});
        const double exact = analytic::parallel_coaxial_rectangles(c.side, c.side, c.distance);
        // One 3 × 3 rule is 0.28 % off at d = 0.5 (the kernel peaks sharply under x);
        // from N = 2 on every case is within 0.1 % (measured ≤ 3.3e-5 relative).
        EXPECT_NEAR(area_factor(receiver, source, 1), exact, 3e-3 * exact);
        for (const int n : {2, 4, 8}) {
            EXPECT_NEAR(area_factor(receiver, source, n), exact, 1e-3 * exact)
                << "side " << c.side << " d " << c.distance << " N " << n;
        }
    }
}

TEST(AreaFactor, PerpendicularSharedEdgeSingularCase) {
    const Quad floor = rect({}, {1, 0, 0}, {0, 1, 0});
    const Quad wall = rect({}, {0, 0, 1}, {0, 1, 0});
    const double exact = analytic::perpendicular_common_edge(1, 1, 1);
    EXPECT_NEAR(area_factor(floor, wall, 2), exact, 5e-3 * exact);
    EXPECT_NEAR(area_factor(floor, wall, 8), exact, 1e-4);
    // The unit-square case converges unusually fast (measured 3e-11 at N = 8). Generically the
    // δ·log δ term at the edge gives O(h²): a 2 × 1 floor is 3.3e-4 off at N = 2, 2.1e-5 at 8.
    const Quad long_floor = rect({}, {2, 0, 0}, {0, 1, 0});
    EXPECT_NEAR(area_factor(long_floor, wall, 8), analytic::perpendicular_common_edge(1, 2, 1),
                1e-4);
}

TEST(AreaFactor, SliverStripsAlongSharedEdge) {
    const Quad wall = rect({}, {0, 0, 1}, {0, 1, 0});
    // The error sits at the strip's ends, where F(x) changes over the scale w along the edge;
    // the isotropic N × N split needs N = 8 for w = 0.01 (measured 8.6e-4 absolute).
    for (const double w : {0.01, 1e-4}) {
        const Quad strip = rect({}, {w, 0, 0}, {0, 1, 0});
        EXPECT_NEAR(area_factor(strip, wall, 8), analytic::perpendicular_common_edge(1, w, 1), 1e-3)
            << "w " << w;
    }
}

TEST(AreaFactor, GeneralPositionRectangles) {
    // Offset parallel pair and a perpendicular pair not touching the common line.
    const Quad low = rect({0.2, -0.3, 0}, {1.5, 0, 0}, {0, 0.8, 0});
    const Quad high = rect({1.0, 0.1, 0.7}, {0, 1.2, 0}, {0.6, 0, 0});
    EXPECT_NEAR(area_factor(low, high, 4),
                analytic::parallel_rectangles(0.2, 1.7, -0.3, 0.5, 1.0, 1.6, 0.1, 1.3, 0.7), 1e-6);
    const Quad floor = rect({0.3, 0, 0}, {0.9, 0, 0}, {0, 1, 0});
    const Quad wall = rect({0, 0.4, 0.2}, {0, 0, 0.5}, {0, 1.1, 0});
    EXPECT_NEAR(area_factor(floor, wall, 4),
                analytic::perpendicular_rectangles(0.3, 1.2, 0, 1, 0.2, 0.7, 0.4, 1.5), 1e-6);
}

TEST(AreaFactor, Reciprocity) {
    const Quad floor = rect({}, {2, 0, 0}, {0, 1, 0});
    const Quad wall = rect({}, {0, 1, 0}, {0, 0, 1});
    const double g12 = polygon_area(floor) * area_factor(floor, wall, 4);
    const double g21 = polygon_area(wall) * area_factor(wall, floor, 4);
    EXPECT_NEAR(g12, g21, 1e-3 * g12);
    EXPECT_NEAR(area_factor(floor, wall, 4), 0.116426, 1e-3 * 0.116426);
    EXPECT_NEAR(area_factor(wall, floor, 4), 0.232853, 1e-3 * 0.232853);
}

TEST(AreaFactor, UnitCubeClosure) {
    const auto faces = box(1, 1, 1);
    // Lambert is additive, so one point on the floor sees the other five faces summing to 1.
    for (const Vec3 x : {Vec3{0.5, 0.5, 0}, Vec3{0.03, 0.91, 0}}) {
        double total = 0.0;
        for (int j = 1; j < 6; ++j) total += point_to_polygon_factor(x, {0, 0, 1}, faces[j]);
        EXPECT_NEAR(total, 1.0, 1e-6);
    }
    double row = 0.0;
    for (int j = 1; j < 6; ++j) row += area_factor(faces[0], faces[j], 4);
    EXPECT_NEAR(row, 1.0, 1e-4);
    EXPECT_NEAR(area_factor(faces[0], faces[1], 4), 0.199825, 1e-4);
}

TEST(AreaFactor, RoomRowSums) {
    const auto faces = box(4, 4, 3);
    for (const int i : {0, 2}) {  // floor and one 4 × 3 wall
        double row = 0.0;
        for (int j = 0; j < 6; ++j) {
            if (j != i) row += area_factor(faces[i], faces[j], 4);
        }
        EXPECT_NEAR(row, 1.0, 1e-4) << "row " << i;
    }
    EXPECT_NEAR(area_factor(faces[0], faces[1], 4), 0.282733, 1e-3 * 0.282733);
    EXPECT_NEAR(area_factor(faces[0], faces[2], 4), 0.179317, 1e-3 * 0.179317);
}

// Near-singular pairs (the receiver far larger than its distance to the source): the
// adaptive cubature resolves the strip along the source's edges that a fixed rule misses
// (every fixed-rule point of a 1 m square 1 mm under another sees a factor of ~1, not 0.998).
TEST(AreaAveragedFactor, NearlyTouchingSquaresAndTheirNeighbours) {
    const Quad floor = rect({}, {1, 0, 0}, {0, 1, 0});
    const Vec3 up{0, 0, 1}, down{0, 0, -1};
    for (const double c : {1.0, 0.1, 0.01, 0.001}) {
        // Facing down: e1 × e2 = −z.
        const Quad above = rect({0, 0, c}, {0, 1, 0}, {1, 0, 0});
        const Quad beside = rect({1, 0, c}, {0, 1, 0}, {1, 0, 0});
        const Quad corner = rect({1, 1, c}, {0, 1, 0}, {1, 0, 0});
        const double exact = analytic::parallel_coaxial_rectangles(1, 1, c);
        EXPECT_NEAR(area_averaged_factor(floor, up, above, down) / exact, 1.0, 1e-3) << "c " << c;
        EXPECT_NEAR(area_averaged_factor(floor, up, beside, down) /
                        analytic::parallel_rectangles(0, 1, 0, 1, 1, 2, 0, 1, c),
                    1.0, 1e-2)
            << "c " << c;
        EXPECT_NEAR(area_averaged_factor(floor, up, corner, down) /
                        analytic::parallel_rectangles(0, 1, 0, 1, 1, 2, 1, 2, c),
                    1.0, 2e-2)
            << "c " << c;
    }
    EXPECT_NEAR(analytic::parallel_coaxial_rectangles(1, 1, 0.001), 0.998006, 1e-6);
}

// Scale-free: the same pair in millimetres and 10 km from the origin gives the same factor (to
// well within the cubature's own 1e-3: rounding may reorder pieces of equal error).
TEST(AreaAveragedFactor, SameAtEveryScale) {
    auto at = [](const Quad& q, double s, Vec3 o) {
        return Quad{q[0] * s + o, q[1] * s + o, q[2] * s + o, q[3] * s + o};
    };
    const Quad floor = rect({}, {1, 0, 0}, {0, 1, 0});
    const Quad above = rect({0.3, 0.2, 0.001}, {0, 1, 0}, {1, 0, 0});
    const Vec3 up{0, 0, 1}, down{0, 0, -1};
    const double base = area_averaged_factor(floor, up, above, down);
    EXPECT_NEAR(area_averaged_factor(at(floor, 1e-3, {}), up, at(above, 1e-3, {}), down) / base,
                1.0, 1e-4);
    EXPECT_NEAR(
        area_averaged_factor(at(floor, 1, {1e4, 1e4, 0}), up, at(above, 1, {1e4, 1e4, 0}), down) /
            base,
        1.0, 1e-6);
    EXPECT_NEAR(base / analytic::parallel_rectangles(0, 1, 0, 1, 0.3, 1.3, 0.2, 1.2, 0.001), 1.0,
                1e-3);
}

}  // namespace
}  // namespace radiant
