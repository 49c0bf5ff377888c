#include "formfactor/luminaire_light.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "formfactor/point_polygon.h"

namespace radiant {
namespace {

constexpr double kPi = std::numbers::pi;
// Spherical triangles narrower than this see a smooth table as nearly linear (tables step
// 1–10°); deeper subdivision only costs time.
constexpr double kMaxTriangleAngle = 3 * kPi / 180;
constexpr int kMaxDepth = 8;

/// Solid angle of the spherical triangle of unit vectors a, b, c (Van Oosterom & Strackee 1983).
double triangle_solid_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
    const double numerator = std::abs(dot(a, cross(b, c)));
    const double denominator = 1 + dot(a, b) + dot(b, c) + dot(c, a);
    return 2 * std::atan2(numerator, denominator);
}

/// ∫ I/Φ dω over a spherical triangle: the mean of the edge midpoints' intensities (exact for
/// quadratic intensity on a flat triangle) times its solid angle, on subdivided triangles.
double table_fraction(const PreparedLuminaire& l, const Vec3& a, const Vec3& b, const Vec3& c,
                      int depth) {
    const double widest =
        std::acos(std::clamp(std::min({dot(a, b), dot(b, c), dot(c, a)}), -1.0, 1.0));
    const Vec3 ab = normalized(a + b), bc = normalized(b + c), ca = normalized(c + a);
    if (widest <= kMaxTriangleAngle || depth >= kMaxDepth) {
        const double mean =
            (intensity_per_lm(l, ab) + intensity_per_lm(l, bc) + intensity_per_lm(l, ca)) / 3;
        return triangle_solid_angle(a, b, c) * mean;
    }
    return table_fraction(l, a, ab, ca, depth + 1) + table_fraction(l, ab, b, bc, depth + 1) +
           table_fraction(l, ca, bc, c, depth + 1) + table_fraction(l, ab, bc, ca, depth + 1);
}

}  // namespace

double intensity_per_lm(const PreparedLuminaire& l, const Vec3& u) {
    switch (l.distribution) {
        case Distribution::isotropic:
            return 1.0 / (4 * kPi);
        case Distribution::lambertian:
            return std::max(0.0, dot(l.aim, u)) / kPi;
        case Distribution::photometric: {
            const double gamma = std::acos(std::clamp(dot(l.aim, u), -1.0, 1.0));
            const double c = std::atan2(dot(u, l.c90_axis), dot(u, l.c0_axis));
            return l.table->candela(gamma, c) / l.table->flux_lm();
        }
    }
    return 0;
}

// isotropic: Ω/4π; lambertian about `aim`: the projected solid angle / π = F(aim → polygon).
double flux_fraction_on(const PreparedLuminaire& l, std::span<const Vec3> polygon) {
    switch (l.distribution) {
        case Distribution::isotropic:
            return polygon_solid_angle(l.position, polygon) / (4 * kPi);
        case Distribution::lambertian:
            return point_to_polygon_factor(l.position, l.aim, polygon);
        case Distribution::photometric:
            break;
    }
    double sum = 0;
    const Vec3 first = normalized(polygon[0] - l.position);
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
        sum += table_fraction(l, first, normalized(polygon[k] - l.position),
                              normalized(polygon[k + 1] - l.position), 0);
    }
    return sum;
}

double direct_kernel_per_lm(const PreparedLuminaire& l, const Vec3& x, const Vec3& n) {
    const Vec3 d = l.position - x;
    const double d2 = length_squared(d);
    if (!(d2 > 0)) return 0;
    const double r = std::sqrt(d2);
    const double cos_r = dot(n, d) / r;
    if (cos_r <= 0) return 0;
    return std::max(0.0, intensity_per_lm(l, -d / r)) * cos_r / d2;
}

Rgb unoccluded_luminaire_irradiance_at(const PreparedScene& scene, const Vec3& x, const Vec3& n) {
    Rgb e{0, 0, 0};
    for (const PreparedLuminaire& l : scene.luminaires) {
        const double k = direct_kernel_per_lm(l, x, n);
        for (int c = 0; c < 3; ++c) e[c] += l.flux_lm[c] * k;
    }
    return e;
}

Rgb luminaire_irradiance_from(const PreparedLuminaire& l, const Visibility& visibility,
                              const Vec3& x, const Vec3& n, std::uint64_t& rays) {
    const double k = direct_kernel_per_lm(l, x, n);
    if (!(k > 0)) return {0, 0, 0};
    ++rays;
    if (!visibility.visible(x + n * visibility.epsilon(), l.position)) return {0, 0, 0};
    return {l.flux_lm[0] * k, l.flux_lm[1] * k, l.flux_lm[2] * k};
}

Rgb luminaire_irradiance_at(const PreparedScene& scene, const Visibility& visibility, const Vec3& x,
                            const Vec3& n, std::uint64_t& rays) {
    Rgb e{0, 0, 0};
    for (const PreparedLuminaire& l : scene.luminaires) {
        const Rgb one = luminaire_irradiance_from(l, visibility, x, n, rays);
        for (int c = 0; c < 3; ++c) e[c] += one[c];
    }
    return e;
}

Rgb luminaire_irradiance_on_polygon(
    const PreparedScene& scene, const Visibility& visibility, std::span<const Vec3> polygon,
    const Vec3& n, double area_m2, std::span<const QuadraturePoint> points,
    const std::function<bool(const PreparedLuminaire&)>& maybe_blocked, std::uint64_t& rays) {
    Rgb e{0, 0, 0};
    if (!(area_m2 > 0)) return e;
    const double eps = visibility.epsilon();
    for (const PreparedLuminaire& l : scene.luminaires) {
        if (dot(l.position - polygon[0], n) <= 0) continue;
        const double fraction = flux_fraction_on(l, polygon);
        if (fraction <= 0) continue;
        double visible = 1;
        if (maybe_blocked(l)) {
            // Weight each point by its share of the direct kernel I·cos/d².
            double seen = 0, total = 0;
            for (const QuadraturePoint& q : points) {
                const double k = q.weight * direct_kernel_per_lm(l, q.position, n);
                if (k <= 0) continue;
                total += k;
                ++rays;
                if (visibility.visible(q.position + n * eps, l.position)) seen += k;
            }
            visible = total > 0 ? seen / total : 0;
        }
        for (int c = 0; c < 3; ++c) e[c] += l.flux_lm[c] * fraction * visible / area_m2;
    }
    return e;
}

}  // namespace radiant
