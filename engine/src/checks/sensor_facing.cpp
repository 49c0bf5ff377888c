#include "checks/sensor_facing.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "checks/side_hit.h"
#include "checks/warning_text.h"
#include "formfactor/luminaire_light.h"
#include "formfactor/quadrature.h"

namespace radiant {
namespace {

// Points of a set weighed, evenly spaced, and of all sets (a scene may have a million sets of
// a point each); luminaires and emitting pieces weighed, evenly spaced (their power scaled up
// to the whole): the check stays cheap beside a floor of many rooms, or a hostile scene.
constexpr std::size_t kPointsPerSet = 64;
constexpr std::size_t kMaxPoints = 1024;
constexpr std::size_t kMaxSources = 1024;
constexpr double kOnSurface = 1e-3;  ///< metres
// Only sets facing down are weighed: a work plane facing up under uplighters receives no direct
// light either, and is right (its light comes from the ceiling).
constexpr double kDownward = -0.5;

// The light sources weighed: luminaires (each standing for `weight` of them) and emitting
// pieces as point sources (centre, front, power in lm, scaled the same way).
struct Emitter {
    Vec3 centre, normal;
    double power_lm = 0;
};
struct Sources {
    std::vector<const PreparedLuminaire*> luminaires;
    double luminaire_weight = 1;
    std::vector<Emitter> emitters;
};

Sources sources_of(const PreparedScene& scene) {
    Sources out;
    const std::size_t every = stride_for(scene.luminaires.size(), kMaxSources);
    for (std::size_t i = 0; i < scene.luminaires.size(); i += every)
        out.luminaires.push_back(&scene.luminaires[i]);
    out.luminaire_weight = static_cast<double>(every);
    std::vector<std::pair<const Piece*, double>> glowing;  // with its exitance (lm/m²)
    for (const Piece& p : scene.pieces) {
        const double exitance =
            luminance(scene.materials[static_cast<std::size_t>(p.material)].exitance_lm_m2);
        if (exitance > 0) glowing.emplace_back(&p, exitance);
    }
    const std::size_t stride = stride_for(glowing.size(), kMaxSources);
    for (std::size_t i = 0; i < glowing.size(); i += stride) {
        const auto& [p, exitance] = glowing[i];
        out.emitters.push_back({polygon_centroid(p->vertices), p->normal,
                                exitance * p->area_m2 * static_cast<double>(stride)});
    }
    return out;
}

// Direct illuminance at x facing n, unoccluded, from the sources (lux).
double direct_light(const Sources& sources, const Vec3& x, const Vec3& n) {
    double e = 0;
    for (const PreparedLuminaire* l : sources.luminaires)
        e += direct_kernel_per_lm(*l, x, n) * luminance(l->flux_lm);
    e *= sources.luminaire_weight;
    for (const Emitter& s : sources.emitters) {
        const Vec3 d = s.centre - x;
        const double d2 = dot(d, d);
        if (!(d2 > 0)) continue;
        const double cos_receiver = dot(d, n), cos_emitter = -dot(d, s.normal);
        if (cos_receiver <= 0 || cos_emitter <= 0) continue;
        e += s.power_lm * cos_receiver * cos_emitter / (std::numbers::pi * d2 * d2);
    }
    return e;
}

}  // namespace

void check_sensor_facing(const CheckedScene& input, const std::vector<bool>& skip,
                         std::vector<Warning>& out, std::uint64_t& rays) {
    const PreparedScene& scene = input.prepared;
    const Sources sources = sources_of(scene);
    std::size_t weighed = 0;  // points, of all sets
    // The probe behind a point starts this far in front of it, so that it meets the surface the
    // point lies on (side_hit() skips its first stretch).
    const double lift = std::max(kOnSurface, 16 * input.visibility.epsilon());
    for (std::size_t s = 0; s < scene.sensors.size(); ++s) {
        const SensorSet& given = input.scene.sensors[s];
        const PreparedSensorSet& set = scene.sensors[s];
        if ((s < skip.size() && skip[s]) || given.workplane || given.surrounding_of ||
            set.kind != SensorKind::planar || set.points.empty() || set.normal.z > kDownward)
            continue;
        if (weighed >= kMaxPoints) break;
        const std::size_t stride = stride_for(set.points.size(), kPointsPerSet);
        double facing = 0, away = 0;
        std::size_t points = 0, measured = 0;
        for (std::size_t i = 0; i < set.points.size(); i += stride) {
            const Vec3& x = set.points[i];
            facing += direct_light(sources, x, set.normal);
            away += direct_light(sources, x, -set.normal);
            ++points;
            ++weighed;
            ++rays;
            const SideHit behind = side_hit(input, x + set.normal * lift, -set.normal);
            if (!behind.escaped() && behind.t < lift + kMeasuredGap) ++measured;
        }
        if (!(away > 0) || facing > kAwayShare * away || 2 * measured >= points) continue;
        out.push_back({"sensor_faces_away",
                       "sensor set " + quoted(given.name) + " faces " + point_text(given.normal) +
                           ", away from the light: its points receive " + percent(facing / away) +
                           " of the direct light they would facing the other way; is its "
                           "normal reversed?",
                       "/sensors/" + std::to_string(s) + "/normal"});
    }
}

}  // namespace radiant
