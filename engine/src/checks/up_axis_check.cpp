#include "checks/up_axis_check.h"

#include "checks/modelling_checks.h"
#include "checks/warning_text.h"

namespace radiant {
namespace {

// A normal this near an axis faces along it (cos 10°).
constexpr double kAlong = 0.98;
// Luminaires hang near the top of y within this share of the model's height along y, and aim
// along the floor when their aim's y part is under kLevelAim.
constexpr double kTopShare = 0.25;
constexpr double kLevelAim = 0.5;
// The share of the aimed luminaires' flux that must look so.
constexpr double kMostFlux = 0.8;

}  // namespace

void check_up_axis(const Scene& scene, const PreparedScene& prepared, std::vector<Warning>& out) {
    std::size_t facing_y = scene.sensors.size();
    for (std::size_t s = 0; s < prepared.sensors.size(); ++s) {
        const PreparedSensorSet& set = prepared.sensors[s];
        if (scene.sensors[s].workplane || set.normal.z > kAlong) return;  // something faces up
        if (set.kind == SensorKind::planar && set.normal.y > kAlong &&
            facing_y == scene.sensors.size())
            facing_y = s;
    }
    if (facing_y == scene.sensors.size()) return;
    const Box bounds = model_bounds(prepared);
    const double top = bounds.hi.y - kTopShare * (bounds.hi.y - bounds.lo.y);
    const double top_z = bounds.hi.z - kTopShare * (bounds.hi.z - bounds.lo.z);
    double aimed_lm = 0, level_lm = 0, high_lm = 0;
    for (const PreparedLuminaire& l : prepared.luminaires) {
        if (l.distribution == Distribution::isotropic) continue;
        const double lm = luminance(l.flux_lm);
        aimed_lm += lm;
        if (l.position.y >= top && std::abs(l.aim.y) < kLevelAim) level_lm += lm;
        if (l.position.z >= top_z) high_lm += lm;
    }
    // Luminaires near the top of z as well are a z-up room's, along one wall.
    if (!(aimed_lm > 0) || level_lm < kMostFlux * aimed_lm || high_lm >= kMostFlux * aimed_lm)
        return;
    out.push_back({"up_axis_suspect",
                   "the model looks y-up: sensor set " + quoted(scene.sensors[facing_y].name) +
                       " faces +y, and " + percent(level_lm / aimed_lm) +
                       " of the aimed luminaires' light hangs near the top of y, aimed along "
                       "its floor; radiant-scene/1 is z-up (luminaires aim [0, 0, -1] unless "
                       "told, work planes face +z): write each point (x, y, z) of a y-up model "
                       "as (x, -z, y)",
                   "/sensors/" + std::to_string(facing_y) + "/normal"});
}

}  // namespace radiant
