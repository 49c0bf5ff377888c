#include "formfactor/point_polygon.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "formfactor/quadrature.h"

namespace radiant {
namespace {

// Edges whose end directions are parallel to within this relative sine carry no measurable
// contour contribution (or pass through x, where the integrand is undefined): skip them.
constexpr double kParallelSine = 1e-12;

// One edge term of Lambert's contour integral: γ n·(a×b)/|a×b| with γ = atan2(|a×b|, a·b),
// which stays accurate for the small angles seen from far or grazing points.
double lambert_edge(const Vec3& n, const Vec3& a, const Vec3& b) {
    const Vec3 c = cross(a, b);
    const double sine = length(c);
    if (sine <= kParallelSine * length(a) * length(b)) return 0.0;
    return std::atan2(sine, dot(a, b)) * dot(n, c) / sine;
}

// Signed solid angle of the triangle (a, b, c) seen from the origin (Van Oosterom & Strackee
// 1983): tan(Ω/2) = a·(b×c) / (abc + (a·b)c + (a·c)b + (b·c)a).
double signed_triangle_solid_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
    const double la = length(a), lb = length(b), lc = length(c);
    const double numerator = dot(a, cross(b, c));
    const double denominator = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
    return 2.0 * std::atan2(numerator, denominator);
}

}  // namespace

double point_to_polygon_factor(const Vec3& x, const Vec3& n, std::span<const Vec3> polygon) {
    const Vec3 normal = normalized(n);
    const std::vector<Vec3> front = clip_to_halfspace(polygon, x, normal);
    if (front.size() < 3) return 0.0;
    double sum = 0.0;
    for (std::size_t k = 0; k < front.size(); ++k) {
        sum += lambert_edge(normal, front[k] - x, front[(k + 1) % front.size()] - x);
    }
    // The sign only reflects the vertex order as seen from x; clamping absorbs rounding.
    const double f = std::abs(sum) / (2.0 * std::numbers::pi);
    return std::isfinite(f) ? std::clamp(f, 0.0, 1.0) : 0.0;
}

double polygon_solid_angle(const Vec3& x, std::span<const Vec3> polygon) {
    if (polygon.size() < 3) return 0.0;
    // A point in the polygon's own plane sees it edge-on; atan2(±0, ·) would be ambiguous there.
    const Vec3 m = polygon_normal(polygon);
    if (m == Vec3{}) return 0.0;
    const Vec3 a = polygon[0] - x;
    // Signed fan terms: triangles folding back over a non-convex polygon cancel correctly.
    double sum = 0.0;
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
        sum += signed_triangle_solid_angle(a, polygon[k] - x, polygon[k + 1] - x);
    }
    const double omega = std::abs(sum);
    return std::isfinite(omega) ? omega : 0.0;
}

std::vector<Vec3> clip_to_halfspace(std::span<const Vec3> polygon, const Vec3& origin,
                                    const Vec3& n) {
    // Sutherland & Hodgman 1974 against one plane. Vertices on the plane (d = 0) count as
    // inside and never spawn an intersection, so touching polygons gain no sliver edges.
    std::vector<Vec3> out;
    out.reserve(polygon.size() + 1);
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const Vec3& a = polygon[k];
        const Vec3& b = polygon[(k + 1) % polygon.size()];
        const double da = dot(n, a - origin);
        const double db = dot(n, b - origin);
        if (da >= 0.0) out.push_back(a);
        if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) {
            out.push_back(a + (b - a) * (da / (da - db)));
        }
    }
    return out;
}

double front_point_to_polygon_factor(const Vec3& x, const Vec3& n, std::span<const Vec3> polygon,
                                     const Vec3& polygon_normal) {
    if (dot(x - polygon[0], polygon_normal) <= 0) return 0;
    return point_to_polygon_factor(x, n, polygon);
}

}  // namespace radiant
