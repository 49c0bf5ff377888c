#include "formfactor/quadrature.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace radiant {
namespace {

// Newell's vector Σ (v_k − v_0) × (v_{k+1} − v_0): twice the vector area. Taken relative to v_0
// so that polygons far from the origin keep their digits.
Vec3 newell_vector(std::span<const Vec3> polygon) {
    Vec3 sum;
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
        sum += cross(polygon[k] - polygon[0], polygon[k + 1] - polygon[0]);
    }
    return sum;
}

// Barycentric point (a, b, c) with weight w (fraction of the triangle's area).
struct BaryPoint {
    double a, b, c, w;
};

// Symmetric triangle rules (Dunavant 1985). Degree 3 uses the degree-4 rule: Dunavant's
// degree-3 rule has a negative weight, which a form-factor estimator should never see.
std::vector<BaryPoint> triangle_rule(int degree) {
    if (degree <= 1) return {{1.0 / 3, 1.0 / 3, 1.0 / 3, 1.0}};
    if (degree == 2) {
        constexpr double a = 1.0 / 6, b = 2.0 / 3, w = 1.0 / 3;
        return {{a, a, b, w}, {a, b, a, w}, {b, a, a, w}};
    }
    std::vector<BaryPoint> rule;
    const auto orbit = [&rule](double a, double w) {
        const double b = 1.0 - 2.0 * a;
        rule.insert(rule.end(), {{a, a, b, w}, {a, b, a, w}, {b, a, a, w}});
    };
    if (degree <= 4) {
        orbit(0.44594849091596488631832925388305, 0.22338158967801146569500700843312);
        orbit(0.091576213509770743459571463402202, 0.10995174365532186763832632490021);
        return rule;
    }
    // Radon's 7-point degree-5 rule in closed form.
    const double s15 = std::sqrt(15.0);
    rule.push_back({1.0 / 3, 1.0 / 3, 1.0 / 3, 9.0 / 40});
    orbit((6.0 - s15) / 21.0, (155.0 - s15) / 1200.0);
    orbit((6.0 + s15) / 21.0, (155.0 + s15) / 1200.0);
    return rule;
}

struct GaussNode {
    double t, w;  ///< node in (0, 1), weight summing to 1
};

// Gauss–Legendre on [0, 1], n = 1..4 (exact to degree 2n − 1).
std::vector<GaussNode> gauss_legendre(int n) {
    std::vector<std::array<double, 2>> sym;  // (node, weight) on [−1, 1], node ≥ 0
    switch (n) {
        case 1:
            sym = {{0.0, 2.0}};
            break;
        case 2:
            sym = {{1.0 / std::sqrt(3.0), 1.0}};
            break;
        case 3:
            sym = {{0.0, 8.0 / 9}, {std::sqrt(0.6), 5.0 / 9}};
            break;
        default: {
            const double r = 2.0 * std::sqrt(1.2) / 7.0;
            const double s30 = std::sqrt(30.0);
            sym = {{std::sqrt(3.0 / 7 - r), (18.0 + s30) / 36},
                   {std::sqrt(3.0 / 7 + r), (18.0 - s30) / 36}};
        }
    }
    std::vector<GaussNode> nodes;
    for (const auto& [x, w] : sym) {
        nodes.push_back({0.5 * (1.0 - x), 0.5 * w});
        if (x != 0.0) nodes.push_back({0.5 * (1.0 + x), 0.5 * w});
    }
    return nodes;
}

std::vector<QuadraturePoint> triangle_quadrature(const Vec3& a, const Vec3& b, const Vec3& c,
                                                 double area, int degree) {
    std::vector<QuadraturePoint> points;
    for (const BaryPoint& q : triangle_rule(degree)) {
        points.push_back({a * q.a + b * q.b + c * q.c, q.w * area});
    }
    return points;
}

// Tensor Gauss–Legendre on the bilinear map p(s,t) of a planar quad, weighted by the exact
// Jacobian |p_s × p_t|. That Jacobian is affine in s and t, so a parallelogram (constant
// Jacobian) needs ceil((degree+1)/2) points per direction and a general quad one more.
std::vector<QuadraturePoint> quad_quadrature(std::span<const Vec3> q, int degree) {
    const Vec3 twist = q[0] - q[1] + q[2] - q[3];
    const double size = length_squared(q[1] - q[0]) + length_squared(q[3] - q[0]);
    const bool parallelogram = length_squared(twist) <= 1e-28 * size;
    const int n = (degree + 2) / 2 + (parallelogram ? 0 : 1);
    const auto rule = gauss_legendre(std::min(n, 4));
    std::vector<QuadraturePoint> points;
    for (const GaussNode& gs : rule) {
        for (const GaussNode& gt : rule) {
            const double s = gs.t, t = gt.t;
            const Vec3 p = q[0] * ((1 - s) * (1 - t)) + q[1] * (s * (1 - t)) + q[2] * (s * t) +
                           q[3] * ((1 - s) * t);
            const Vec3 ps = (q[1] - q[0]) + twist * t;
            const Vec3 pt = (q[3] - q[0]) + twist * s;
            points.push_back({p, gs.w * gt.w * length(cross(ps, pt))});
        }
    }
    return points;
}

// Fan triangles (v0, v_k, v_{k+1}) with their areas; zero-area ones are dropped so no
// quadrature point or sample can land on a collinear run of vertices.
struct FanTriangle {
    Vec3 a, b, c;
    double area;
};

std::vector<FanTriangle> fan(std::span<const Vec3> polygon) {
    std::vector<FanTriangle> triangles;
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
        const double area =
            0.5 * length(cross(polygon[k] - polygon[0], polygon[k + 1] - polygon[0]));
        if (area > 0.0) triangles.push_back({polygon[0], polygon[k], polygon[k + 1], area});
    }
    return triangles;
}

// Area-preserving map of the unit square onto a triangle (square-root map, Shirley 1990).
Vec3 square_to_triangle(const FanTriangle& t, double u, double v) {
    const double r = std::sqrt(u);
    return t.a * (1.0 - r) + t.b * (r * (1.0 - v)) + t.c * (r * v);
}

// Area-preserving map of the unit square onto the fan: u picks the triangle through the
// area CDF and is rescaled within it.
Vec3 square_to_fan(std::span<const FanTriangle> triangles, double total, double u, double v) {
    double start = 0.0;
    for (const FanTriangle& t : triangles) {
        const double end = start + t.area / total;
        if (u < end || &t == &triangles.back()) {
            return square_to_triangle(t, std::clamp((u - start) / (end - start), 0.0, 1.0), v);
        }
        start = end;
    }
    return {};
}

}  // namespace

std::vector<QuadraturePoint> polygon_quadrature(std::span<const Vec3> polygon, int degree) {
    degree = std::clamp(degree, 1, 5);
    if (polygon.size() == 4) return quad_quadrature(polygon, degree);
    std::vector<QuadraturePoint> points;
    for (const FanTriangle& t : fan(polygon)) {
        const auto tri = triangle_quadrature(t.a, t.b, t.c, t.area, degree);
        points.insert(points.end(), tri.begin(), tri.end());
    }
    return points;
}

std::vector<Vec3> stratified_points(std::span<const Vec3> polygon, int n,
                                    std::span<const double> u) {
    const auto triangles = fan(polygon);
    n = std::min(n, static_cast<int>(u.size() / 2));
    if (triangles.empty() || n <= 0) return {};
    double total = 0.0;
    for (const FanTriangle& t : triangles) total += t.area;
    // Equal-area strata of the unit square for any n: `rows` rows, row j holding count_j
    // cells of width 1/count_j and height count_j/n, then mapped area-preservingly.
    const int rows = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(n))));
    std::vector<Vec3> points;
    points.reserve(static_cast<std::size_t>(n));
    int first = 0;
    for (int row = 0; row < rows; ++row) {
        const int count = n / rows + (row < n % rows ? 1 : 0);
        for (int c = 0; c < count; ++c) {
            const auto i = static_cast<std::size_t>(first + c);
            const double su = (c + u[2 * i]) / count;
            const double sv = (first + count * u[2 * i + 1]) / n;
            points.push_back(square_to_fan(triangles, total, su, sv));
        }
        first += count;
    }
    return points;
}

double polygon_area(std::span<const Vec3> polygon) { return 0.5 * length(newell_vector(polygon)); }

Vec3 polygon_normal(std::span<const Vec3> polygon) {
    const Vec3 v = newell_vector(polygon);
    double extent = 0.0;  // squared size scale, so "degenerate" is judged relative to it
    for (const Vec3& p : polygon) extent = std::max(extent, length_squared(p - polygon[0]));
    return length_squared(v) > 1e-28 * extent * extent ? normalized(v) : Vec3{};
}

Vec3 polygon_centroid(std::span<const Vec3> polygon) {
    if (polygon.empty()) return {};
    // Signed fan areas along the Newell normal, so non-convex polygons are weighted right.
    const Vec3 m = newell_vector(polygon);
    Vec3 weighted;
    double total = 0.0;
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
        const double w = dot(m, cross(polygon[k] - polygon[0], polygon[k + 1] - polygon[0]));
        weighted += (polygon[0] + polygon[k] + polygon[k + 1]) * (w / 3.0);
        total += w;
    }
    if (total > 0.0) return weighted / total;
    Vec3 mean;
    for (const Vec3& p : polygon) mean += p;
    return mean / static_cast<double>(polygon.size());
}

}  // namespace radiant
