#include "design/glare.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "formfactor/luminaire_light.h"

namespace radiant {
namespace {

constexpr double kDegrees = 180 / std::numbers::pi;
constexpr double kDarkestBackground = 1e-6;

}  // namespace

double guth_position_index(double forward, double lateral, double up) {
    const double alpha = std::atan2(std::abs(lateral), up) * kDegrees;
    const double beta = std::atan2(std::hypot(lateral, up), forward) * kDegrees;
    const double linear = 35.2 - 0.31889 * alpha - 1.22 * std::exp(-2 * alpha / 9);
    const double quadratic = 21 + 0.26667 * alpha - 0.002963 * alpha * alpha;
    return std::exp(linear * 1e-3 * beta + quadratic * 1e-5 * beta * beta);
}

double projected_area_m2(const LuminousShape& s, double c0, double c90, double nadir) {
    if (s.sphere) return std::numbers::pi * s.length * s.length / 4;
    const double bottom = s.round ? std::numbers::pi * s.length * s.width / 4 : s.length * s.width;
    // Sides: a box's faces across C0 are `width` long, across C90 `length`; a cylinder's
    // silhouette is its footprint's width across the horizontal direction.
    const double sides = s.round ? s.height * std::hypot(s.width * c0, s.length * c90)
                                 : s.height * (s.width * std::abs(c0) + s.length * std::abs(c90));
    return bottom * std::max(0.0, nadir) + sides;
}

double glare_sum(const PreparedScene& scene, const PreparedObserver& observer,
                 const Visibility& visibility, int component, std::uint64_t& rays) {
    const Vec3 forward = observer.view;
    const Vec3 up = normalized(Vec3{0, 0, 1} - forward * forward.z);
    const Vec3 lateral = cross(forward, up);
    const Vec3 eye = observer.position + forward * visibility.epsilon();
    double sum = 0;
    for (const PreparedLuminaire& l : scene.luminaires) {
        if (component >= 0 && l.component != component) continue;
        const Vec3 d = l.position - observer.position;
        const double r = dot(d, forward), h = dot(d, up), t = dot(d, lateral);
        // Behind the eye, or below the line of sight where the Guth index does not apply.
        if (!(r > 0) || h < 0) continue;
        const double d2 = length_squared(d);
        const Vec3 to_eye = -d / std::sqrt(d2);
        const double intensity = luminance(l.flux_lm) * intensity_per_lm(l, to_eye);
        if (!(intensity > 0)) continue;
        const double full = projected_area_m2(l.luminous, 0, 0, 1);
        const double area = l.luminous.point() || full < kSmallSourceAreaM2
                                ? kSmallSourceAreaM2
                                : projected_area_m2(l.luminous, dot(to_eye, l.c0_axis),
                                                    dot(to_eye, l.c90_axis), dot(to_eye, l.aim));
        if (!(area > 0)) continue;
        ++rays;
        if (!visibility.visible(eye, l.position)) continue;
        // L²ω = (I/A)²·(A/d²) = I²/(A·d²).
        const double p = guth_position_index(r, t, h);
        sum += intensity * intensity / (area * d2 * p * p);
    }
    return sum;
}

double unified_glare_rating(double glare_sum, double background_luminance) {
    if (!(glare_sum > 0)) return 0;
    const double lb = std::max(background_luminance, kDarkestBackground);
    return std::max(0.0, 8 * std::log10(0.25 * glare_sum / lb));
}

}  // namespace radiant
