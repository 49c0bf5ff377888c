#include "montecarlo/bright_sides.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/triangle_point.h"
#include "montecarlo/channel_product.h"
#include "solution/surface_summary.h"

namespace radiant {
namespace {

// A side is bright when it reflects this many times the surfaces' mean: a few times the mean is
// what any well-lit desk under a panel does, and cosine rays already see those well.
constexpr double kBrightOverMean = 4;
// At most this many bright sides in all, the most light first (light times area): every point
// weighs each of them once. Four times a point's most, as the sides near each lamp compete
// with those near the others: at 4 096 the living room's small bright sides near its lamps
// (8 168 in all) were cut, and its solve at 0.01 took 4.0–4.3 s for 2.4.
constexpr std::size_t kMaxBrightSides = 4 * BrightSides::kMaxAimed;
// A point aims only where its aimed sides send at least this share of the room's mean reflected
// light: elsewhere the aimed rays would cost more than the spread they take out.
constexpr double kMinAimedShare = 0.1;

}  // namespace

BrightSides::BrightSides(const PreparedScene& scene, const ElementMesh& mesh,
                         const PhotonField& field)
    : mesh_(&mesh), mean_reflected_(field.mean_reflected()) {
    if (!(mean_reflected_ > 0)) return;
    std::vector<Bright> found;
    for (std::size_t s = 0; s < mesh.sides().size(); ++s) {
        const int side = static_cast<int>(s);
        const MeshElement& e = element(side);
        const Rgb& rho = scene.materials[static_cast<std::size_t>(e.material)].reflectance;
        const double b = photometric(times(rho, field.total(side)), scene.channels);
        if (b > kBrightOverMean * mean_reflected_ && e.area_m2 > 0) {
            found.push_back({side, (e.triangle.a + e.triangle.b + e.triangle.c) / 3.0,
                             mesh.side_normal(side), e.area_m2, b * e.area_m2});
        }
    }
    const std::size_t kept = std::min(found.size(), kMaxBrightSides);
    std::partial_sort(found.begin(), found.begin() + static_cast<std::ptrdiff_t>(kept), found.end(),
                      [](const Bright& a, const Bright& b) {
                          return a.power > b.power || (a.power == b.power && a.side < b.side);
                      });
    found.resize(kept);
    sides_ = std::move(found);
}

std::size_t BrightSides::most_aimed(std::size_t points) {
    const std::size_t fitting = kAimsBytes / (std::max<std::size_t>(points, 1) * sizeof(AimedSide));
    return std::clamp(fitting, kMinAimed, kMaxAimed);
}

Aim BrightSides::aim(const Vec3& x, const Vec3& n, std::size_t most) const {
    std::vector<std::pair<double, int>> light;
    for (const Bright& b : sides_) {
        const Vec3 d = b.centre - x;
        const double d2 = length_squared(d);
        const double cos_x = dot(n, d), cos_s = -dot(b.normal, d);
        if (!(cos_x > 0 && cos_s > 0 && d2 > 0)) continue;
        // Roughly the irradiance the side sends to x: B A cos cos / (π r²), its r² kept at least
        // the side's area so that a side x nearly touches does not take every aimed ray.
        light.push_back(
            {b.power * (cos_x * cos_s / d2) / (std::numbers::pi * std::max(d2, b.area)), b.side});
    }
    if (light.size() > most) {
        std::nth_element(light.begin(), light.begin() + static_cast<std::ptrdiff_t>(most),
                         light.end(), [](const auto& a, const auto& b) {
                             return a.first > b.first ||
                                    (a.first == b.first && a.second < b.second);
                         });
        light.resize(most);
    }
    double total = 0;
    for (const auto& l : light) total += l.first;
    Aim out;
    if (!(total >= kMinAimedShare * mean_reflected_)) return out;
    std::sort(light.begin(), light.end(),
              [](const auto& a, const auto& b) { return a.second < b.second; });
    double cdf = 0;
    for (const auto& [l, side] : light) {
        cdf += l / total;
        out.push_back({side, static_cast<float>(l / total), static_cast<float>(cdf)});
    }
    out.back().cdf = 1;
    return out;
}

AimedRay BrightSides::draw(const Aim& aimed, const Vec3& origin, SampleStream& rng,
                           double u) const {
    const auto r = static_cast<float>(u);
    const auto it = std::upper_bound(aimed.begin(), aimed.end(), r,
                                     [](float v, const AimedSide& a) { return v < a.cdf; });
    const AimedSide& a = it == aimed.end() ? aimed.back() : *it;
    const Triangle& t = element(a.side).triangle;
    const double r1 = rng.next(), r2 = rng.next();
    return {normalized(uniform_triangle_point(t.a, t.b, t.c, r1, r2) - origin), a.side};
}

double BrightSides::density(const Aim& aimed, int side, double t, const Vec3& d) const {
    const auto it = std::lower_bound(aimed.begin(), aimed.end(), side,
                                     [](const AimedSide& a, int s) { return a.side < s; });
    if (it == aimed.end() || it->side != side) return 0;
    const double cos_s = -dot(mesh_->side_normal(side), d);
    const double area = element(side).area_m2;
    return cos_s > 0 && area > 0 ? it->probability * t * t / (area * cos_s) : 0.0;
}

}  // namespace radiant
