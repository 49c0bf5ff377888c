#include "design/light_scene_sum.h"

#include <algorithm>
#include <cmath>

#include "design/compliance.h"
#include "design/glare.h"
#include "radiant/lighting.h"
#include "scene/json_pointer.h"
#include "solution/sensors.h"

namespace radiant {
namespace {

SensorResult summed_set(const SensorResult& shape, std::size_t s,
                        const std::vector<GroupContribution>& groups,
                        const std::vector<double>& dimming) {
    // The shape's description (name, points, grid, kind, band) as it is, like the observers';
    // its values, initial values and compliance are the sum's own.
    SensorResult r = shape;
    r.initial.reset();
    r.compliance.reset();
    const std::size_t n = shape.illuminance.size();
    r.illuminance.assign(n, 0.0);
    std::vector<double> initial;
    double error_lx = 0;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        const double d = dimming[g];
        const GroupContribution::Sensors& c = groups[g].sensors[s];
        for (std::size_t i = 0; i < n; ++i) r.illuminance[i] += d * c.illuminance[i];
        error_lx += d * c.error_lx;
        if (c.initial_illuminance.empty()) continue;
        initial.resize(n, 0.0);
    }
    if (!initial.empty()) {
        for (std::size_t g = 0; g < groups.size(); ++g) {
            const GroupContribution::Sensors& c = groups[g].sensors[s];
            const std::vector<double>& v =
                c.initial_illuminance.empty() ? c.illuminance : c.initial_illuminance;
            for (std::size_t i = 0; i < n; ++i) initial[i] += dimming[g] * v[i];
        }
        SensorResult i;
        i.illuminance = std::move(initial);
        fill_sensor_statistics(i);
        r.initial = InitialValues{std::move(i.illuminance), i.min, i.max, i.average, i.u0};
    }
    fill_sensor_statistics(r);
    r.error_estimate = r.average > 0 ? error_lx / r.average : 0.0;
    return r;
}

}  // namespace

LightSceneResult sum_groups(const std::vector<SensorResult>& sensors,
                            const std::vector<ObserverResult>& observers,
                            const std::vector<GroupContribution>& groups,
                            const std::vector<double>& dimming) {
    LightSceneResult out;
    for (std::size_t k = 0; k < observers.size(); ++k) {
        ObserverResult o = observers[k];
        double indirect = 0, glare = 0, error = 0;
        for (std::size_t g = 0; g < groups.size(); ++g) {
            indirect += dimming[g] * groups[g].observers[k].background_luminance;
            glare += dimming[g] * dimming[g] * groups[g].observers[k].glare_sum;
            error += dimming[g] * groups[g].observers[k].background_error;
        }
        o.background_luminance = indirect;
        o.glare_sum = glare;
        o.ugr = unified_glare_rating(glare, indirect);
        // A background off by a share δ moves UGR by 8·log10(1 + δ).
        o.ugr_error_estimate =
            glare > 0 && indirect > 0 ? 8 * std::log10(1 + error / indirect) : 0.0;
        out.observers.push_back(std::move(o));
    }
    // Ra of the lit groups: their smallest, unknown if a lit one has none.
    std::optional<double> ra;
    bool ra_known = true;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        if (!(dimming[g] > 0)) continue;
        ra_known = ra_known && groups[g].ra.has_value();
        if (groups[g].ra) ra = std::min(ra.value_or(*groups[g].ra), *groups[g].ra);
    }
    if (!ra_known) ra.reset();
    for (std::size_t s = 0; s < sensors.size(); ++s) {
        SensorResult r = summed_set(sensors[s], s, groups, dimming);
        if (sensors[s].compliance) {
            std::vector<const ObserverResult*> checking;
            const bool own = std::any_of(out.observers.begin(), out.observers.end(),
                                         [&](const ObserverResult& o) { return o.task == r.name; });
            for (const ObserverResult& o : out.observers) {
                // An observer checks its own task area; those without one check every area
                // that has none of its own.
                if (o.task ? *o.task == r.name : !own) checking.push_back(&o);
            }
            r.compliance = check_requirement(sensors[s].compliance->requirement, r, checking, ra);
        }
        out.error_estimate = std::max(out.error_estimate, r.error_estimate);
        out.sensors.push_back(std::move(r));
    }
    return out;
}

std::variant<LightSceneResult, std::vector<Problem>> evaluate_light_scene(const Result& solved,
                                                                          const LightScene& scene) {
    std::vector<Problem> problems;
    if (solved.groups.empty()) {
        problems.push_back({"",
                            "the solve kept no group contributions: its scene names no "
                            "groups and no light scenes"});
        return problems;
    }
    if (scene.dimming.size() > solved.groups.size()) {
        // Every name past the groups' count is unknown: one problem, not one per name.
        problems.push_back(
            {"/dimming", "the light scene dims " + std::to_string(scene.dimming.size()) +
                             " groups; the solve has " + std::to_string(solved.groups.size())});
        return problems;
    }
    std::vector<double> dimming(solved.groups.size(), 0.0);
    for (const auto& [name, value] : scene.dimming) {
        // Named, not captured: clang 14 (the sanitizer builds) cannot capture a binding.
        const std::string& group = name;
        const auto it = std::find_if(solved.groups.begin(), solved.groups.end(),
                                     [&](const GroupContribution& g) { return g.name == group; });
        const std::string pointer = "/dimming/" + escape_pointer_token(name);
        if (it == solved.groups.end()) {
            std::string known;
            for (const GroupContribution& g : solved.groups)
                known += (known.empty() ? "\"" : ", \"") + g.name + "\"";
            problems.push_back(
                {pointer, "the solve has no group \"" + name + "\" (groups: " + known + ")"});
        } else if (!(value >= 0 && value <= 1)) {
            problems.push_back({pointer, "a dimming must be in [0, 1]"});
        } else {
            dimming[static_cast<std::size_t>(it - solved.groups.begin())] = value;
        }
    }
    if (!problems.empty()) return problems;
    LightSceneResult out = sum_groups(solved.sensors, solved.observers, solved.groups, dimming);
    out.name = scene.name;
    out.dimming = scene.dimming;
    return out;
}

}  // namespace radiant
