#include "formfactor/quadrature.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace radiant {
namespace {

// An in-plane frame tilted in 3-D, so that the rules are exercised off the coordinate planes.
const Vec3 kE1 = normalized({1, 2, 2});
const Vec3 kE2 = normalized(cross({0, 0, 1}, kE1));
const Vec3 kOrigin{3, -1, 2};

Vec3 lift(double x, double y) { return kOrigin + kE1 * x + kE2 * y; }

struct Planar {
    std::vector<std::array<double, 2>> xy;
    std::vector<Vec3> polygon() const {
        std::vector<Vec3> out;
        for (const auto& p : xy) out.push_back(lift(p[0], p[1]));
        return out;
    }
};

const Planar kTriangle{{{0, 0}, {1, 0}, {0.2, 0.9}}};
const Planar kSquare{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
const Planar kTrapezoid{{{0, 0}, {2, 0}, {1.4, 1}, {0.3, 1.2}}};
const Planar kPentagon{{{0, 0}, {1, -0.2}, {1.6, 0.5}, {0.9, 1.3}, {-0.2, 0.8}}};

// ∫∫ x^a y^b dA by Green's theorem, ∮ x^(a+1) y^b / (a+1) dy, each edge integrated exactly by
// 5-point Gauss–Legendre (degree ≤ 9 is exact): independent of the 2-D rules under test.
double exact_monomial(const Planar& p, int a, int b) {
    const double nodes[] = {0.0, 0.5384693101056831, 0.9061798459386640};
    const double weights[] = {0.5688888888888889, 0.4786286704993665, 0.2369268850561891};
    double sum = 0.0;
    for (std::size_t k = 0; k < p.xy.size(); ++k) {
        const auto& s = p.xy[k];
        const auto& e = p.xy[(k + 1) % p.xy.size()];
        for (int i = 0; i < 3; ++i) {
            for (const double sign : {-1.0, 1.0}) {
                if (i == 0 && sign > 0) continue;
                const double t = 0.5 * (1 + sign * nodes[i]);
                const double x = s[0] + t * (e[0] - s[0]), y = s[1] + t * (e[1] - s[1]);
                sum += 0.5 * weights[i] * std::pow(x, a + 1) * std::pow(y, b) / (a + 1) *
                       (e[1] - s[1]);
            }
        }
    }
    return sum;
}

double rule_monomial(const std::vector<QuadraturePoint>& rule, int a, int b) {
    double sum = 0.0;
    for (const auto& q : rule) {
        const Vec3 d = q.position - kOrigin;
        sum += q.weight * std::pow(dot(d, kE1), a) * std::pow(dot(d, kE2), b);
    }
    return sum;
}

bool strictly_inside(const std::vector<Vec3>& polygon, const Vec3& p) {
    const Vec3 n = polygon_normal(polygon);
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const Vec3& a = polygon[k];
        const Vec3& b = polygon[(k + 1) % polygon.size()];
        if (dot(cross(b - a, p - a), n) <= 1e-12) return false;
    }
    return std::abs(dot(p - polygon[0], n)) < 1e-12;
}

TEST(Quadrature, ExactOnPolynomialsUpToDegree) {
    for (const Planar* shape : {&kTriangle, &kSquare, &kTrapezoid, &kPentagon}) {
        const auto polygon = shape->polygon();
        for (int degree = 1; degree <= 5; ++degree) {
            const auto rule = polygon_quadrature(polygon, degree);
            for (int a = 0; a <= degree; ++a) {
                for (int b = 0; a + b <= degree; ++b) {
                    const double exact = exact_monomial(*shape, a, b);
                    EXPECT_NEAR(rule_monomial(rule, a, b), exact, 1e-13 * (1 + std::abs(exact)))
                        << "vertices " << polygon.size() << " degree " << degree << " x^" << a
                        << " y^" << b;
                }
            }
        }
    }
}

TEST(Quadrature, WeightsPositiveSumToAreaPointsInside) {
    for (const Planar* shape : {&kTriangle, &kSquare, &kTrapezoid, &kPentagon}) {
        const auto polygon = shape->polygon();
        const double area = exact_monomial(*shape, 0, 0);
        EXPECT_NEAR(polygon_area(polygon), area, 1e-15 * area);
        for (int degree = 1; degree <= 5; ++degree) {
            double sum = 0.0;
            for (const auto& q : polygon_quadrature(polygon, degree)) {
                EXPECT_GT(q.weight, 0.0);
                EXPECT_TRUE(strictly_inside(polygon, q.position));
                sum += q.weight;
            }
            EXPECT_NEAR(sum, area, 4e-16 * area * polygon.size());
        }
    }
}

TEST(Quadrature, PointCounts) {
    EXPECT_EQ(polygon_quadrature(kSquare.polygon(), 5).size(), 9u);      // 3 × 3 Gauss
    EXPECT_EQ(polygon_quadrature(kTrapezoid.polygon(), 5).size(), 16u);  // Jacobian not constant
    EXPECT_EQ(polygon_quadrature(kTriangle.polygon(), 5).size(), 7u);    // Radon / Dunavant
    EXPECT_EQ(polygon_quadrature(kPentagon.polygon(), 5).size(), 21u);   // 3 fan triangles
    EXPECT_EQ(polygon_quadrature(kSquare.polygon(), 1).size(), 1u);
}

TEST(PolygonGeometry, AreaNormalCentroid) {
    const std::vector<Vec3> square{{0, 0, 5}, {2, 0, 5}, {2, 2, 5}, {0, 2, 5}};
    EXPECT_DOUBLE_EQ(polygon_area(square), 4.0);
    EXPECT_EQ(polygon_normal(square), (Vec3{0, 0, 1}));
    const Vec3 c = polygon_centroid(square);
    EXPECT_NEAR(length(c - Vec3{1, 1, 5}), 0.0, 1e-15);
    // L shape: centroid of the union of [0,2]×[0,1] and [0,1]×[1,2].
    const std::vector<Vec3> ell{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
    EXPECT_NEAR(length(polygon_centroid(ell) - Vec3{5.0 / 6, 5.0 / 6, 0}), 0.0, 1e-15);
    EXPECT_DOUBLE_EQ(polygon_area(ell), 3.0);
    const std::vector<Vec3> line{{0, 0, 0}, {1, 1, 1}, {3, 3, 3}};
    EXPECT_EQ(polygon_normal(line), Vec3{});
    EXPECT_EQ(polygon_area(line), 0.0);
}

TEST(PolygonGeometry, FarFromOriginKeepsDigits) {
    const Vec3 far{1e7, -1e7, 1e7};
    const std::vector<Vec3> square{far, far + Vec3{1e-3, 0, 0}, far + Vec3{1e-3, 1e-3, 0},
                                   far + Vec3{0, 1e-3, 0}};
    // Exact area of the representable square: its sides are rounded at this magnitude.
    const double side_x = (far.x + 1e-3) - far.x, side_y = (far.y + 1e-3) - far.y;
    EXPECT_NEAR(polygon_area(square), side_x * side_y, 1e-12 * side_x * side_y);
    EXPECT_NEAR(length(polygon_normal(square) - Vec3{0, 0, 1}), 0.0, 1e-9);
}

std::vector<double> random_u(int n, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::vector<double> u(2 * static_cast<std::size_t>(n));
    for (double& v : u) v = uniform(rng);
    return u;
}

TEST(StratifiedPoints, InsideDeterministicAndAreaUniform) {
    for (const Planar* shape : {&kTriangle, &kTrapezoid, &kPentagon}) {
        const auto polygon = shape->polygon();
        const double area = exact_monomial(*shape, 0, 0);
        for (const int n : {1, 7, 16, 1000}) {
            const auto u = random_u(n, 42);
            const auto points = stratified_points(polygon, n, u);
            ASSERT_EQ(points.size(), static_cast<std::size_t>(n));
            EXPECT_EQ(points, stratified_points(polygon, n, u));
            for (const Vec3& p : points) {
                EXPECT_TRUE(strictly_inside(polygon, p));
            }
        }
        // Unbiased for area-uniform targets: the average over many jitters of the estimate
        // A/n Σ f(x_i) converges to ∫ f (fixed seed, so deterministic).
        const int n = 64, repetitions = 200;
        std::vector<QuadraturePoint> rule;
        for (int r = 0; r < repetitions; ++r) {
            for (const Vec3& p : stratified_points(polygon, n, random_u(n, 1000u + r))) {
                rule.push_back({p, area / (n * repetitions)});
            }
        }
        for (const auto& [a, b] : {std::pair{1, 0}, {0, 1}, {2, 0}, {1, 1}}) {
            const double exact = exact_monomial(*shape, a, b);
            EXPECT_NEAR(rule_monomial(rule, a, b), exact, 2e-3 * (std::abs(exact) + area))
                << "x^" << a << " y^" << b;
        }
    }
}

}  // namespace
}  // namespace radiant
