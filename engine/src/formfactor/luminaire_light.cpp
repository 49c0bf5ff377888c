#include "formfactor/luminaire_light.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "formfactor/point_polygon.h"

namespace radiant {
namespace {
constexpr double kPi = std::numbers::pi;
}  // namespace

double intensity_per_lm(const PreparedLuminaire& l, const Vec3& u) {
    if (l.distribution == Distribution::isotropic) return 1.0 / (4 * kPi);
    return std::max(0.0, dot(l.aim, u)) / kPi;
}

// isotropic: Ω/4π; lambertian about `aim`: the projected solid angle / π = F(aim → polygon).
double flux_fraction_on(const PreparedLuminaire& l, std::span<const Vec3> polygon) {
    if (l.distribution == Distribution::isotropic) {
        return polygon_solid_angle(l.position, polygon) / (4 * kPi);
    }
    return point_to_polygon_factor(l.position, l.aim, polygon);
}

Rgb luminaire_irradiance_at(const PreparedScene& scene, const Visibility& visibility, const Vec3& x,
                            const Vec3& n, std::uint64_t& rays) {
    Rgb e{0, 0, 0};
    const double eps = visibility.epsilon();
    for (const PreparedLuminaire& l : scene.luminaires) {
        const Vec3 d = l.position - x;
        const double d2 = length_squared(d);
        if (!(d2 > 0)) continue;
        const double r = std::sqrt(d2);
        const double cos_r = dot(n, d) / r;
        if (cos_r <= 0) continue;
        const double i_per_lm = intensity_per_lm(l, -d / r);
        if (i_per_lm <= 0) continue;
        ++rays;
        if (!visibility.visible(x + n * eps, l.position)) continue;
        for (int c = 0; c < 3; ++c) e[c] += l.flux_lm[c] * i_per_lm * cos_r / d2;
    }
    return e;
}

}  // namespace radiant
