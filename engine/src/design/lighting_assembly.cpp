#include "design/lighting_assembly.h"

#include <algorithm>
#include <numbers>

#include "design/light_scene_sum.h"
#include "design/requirements.h"
#include "solution/sensors.h"

namespace radiant {
namespace {

std::vector<GroupContribution> group_contributions(const PreparedScene& prepared,
                                                   const std::vector<ComponentValues>& components) {
    const LightComponents& lc = prepared.components;
    const bool maintained =
        std::any_of(lc.components.begin(), lc.components.end(),
                    [](const LightComponent& c) { return c.maintenance_factor != 1; });
    std::vector<GroupContribution> groups(lc.groups.size());
    for (std::size_t g = 0; g < groups.size(); ++g) {
        GroupContribution& group = groups[g];
        group.name = lc.groups[g];
        group.ra = lc.group_ra[g];
        for (std::size_t s = 0; s < prepared.sensors.size(); ++s) {
            GroupContribution::Sensors& set = group.sensors.emplace_back();
            set.name = prepared.sensors[s].name;
            set.illuminance.assign(prepared.sensors[s].points.size(), 0.0);
            if (maintained) set.initial_illuminance = set.illuminance;
        }
        for (const PreparedObserver& o : prepared.observers)
            group.observers.push_back({o.name, 0, 0, 0});
    }
    // A scene without light sources has no component: its groups stay empty, its values 0.
    for (std::size_t c = 0; c < std::min(components.size(), lc.components.size()); ++c) {
        const LightComponent& component = lc.components[c];
        const double mf = component.maintenance_factor;
        GroupContribution& group = groups[static_cast<std::size_t>(component.group)];
        const ComponentValues& values = components[c];
        for (std::size_t s = 0; s < group.sensors.size(); ++s) {
            GroupContribution::Sensors& set = group.sensors[s];
            for (std::size_t i = 0; i < set.illuminance.size(); ++i) {
                set.illuminance[i] += mf * values.sets[s][i];
                if (maintained) set.initial_illuminance[i] += values.sets[s][i];
            }
            set.error_lx += mf * values.set_error_lx[s];
        }
        for (std::size_t k = 0; k < group.observers.size(); ++k) {
            // UGR rates the new installation: initial light (CIE 117's tables do too).
            group.observers[k].background_luminance += values.eye_indirect_lx[k] / std::numbers::pi;
            group.observers[k].glare_sum += values.glare_sums[k];
            group.observers[k].background_error +=
                values.eye_indirect_error_lx[k] / std::numbers::pi;
        }
    }
    return groups;
}

}  // namespace

void assemble_lighting(const Scene& scene, const PreparedScene& prepared,
                       const std::vector<ComponentValues>& components, Result& result) {
    const double m = meters_per_unit(scene.units);
    // The shapes the sums fill: names, grids, kinds, bands and requirements.
    std::vector<SensorResult> shapes;
    for (std::size_t s = 0; s < prepared.sensors.size(); ++s) {
        SensorResult r = sensor_result_for(prepared.sensors[s], prepared.world_origin);
        const SensorSet& set = scene.sensors[s];
        r.kind = set.kind;
        if (set.surrounding_of) r.surrounding_of = scene.sensors[*set.surrounding_of].name;
        if (set.requirement) {
            Compliance c;
            c.requirement = set.surrounding_of
                                ? surrounding_requirement(apply_requirement(
                                      *scene.sensors[*set.surrounding_of].requirement))
                                : apply_requirement(*set.requirement);
            r.compliance = std::move(c);
        }
        shapes.push_back(std::move(r));
    }
    std::vector<ObserverResult> observers;
    for (const Observer& o : scene.observers) {
        ObserverResult r;
        r.name = o.name;
        r.position = o.position * m;
        r.view = normalized(o.view);
        r.task = o.task;
        r.standard = o.standard;
        observers.push_back(std::move(r));
    }
    std::vector<GroupContribution> groups = group_contributions(prepared, components);
    const std::vector<double> full(groups.size(), 1.0);
    LightSceneResult all = sum_groups(shapes, observers, groups, full);
    result.sensors = std::move(all.sensors);
    result.observers = std::move(all.observers);
    result.maintenance = prepared.components.uses;
    // The stored solution light scenes are evaluated from later; kept when asked for.
    if (!prepared.components.named_groups && scene.light_scenes.empty()) return;
    result.groups = std::move(groups);
    for (const LightScene& ls : scene.light_scenes) {
        std::vector<double> dimming(result.groups.size(), 0.0);
        for (const auto& [name, value] : ls.dimming) {
            for (std::size_t g = 0; g < result.groups.size(); ++g) {
                if (result.groups[g].name == name) dimming[g] = value;
            }
        }
        LightSceneResult r = sum_groups(shapes, observers, result.groups, dimming);
        r.name = ls.name;
        r.dimming = ls.dimming;
        result.light_scenes.push_back(std::move(r));
    }
}

}  // namespace radiant
