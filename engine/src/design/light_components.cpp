#include "design/light_components.h"

#include <algorithm>

namespace radiant {
namespace {

struct Assigner {
    const Scene& scene;
    LightComponents& out;

    int group_of(const SourceDesign& d) {
        const std::string name = d.group.value_or(kDefaultGroup);
        out.named_groups = out.named_groups || d.group.has_value();
        const auto it = std::find(out.groups.begin(), out.groups.end(), name);
        if (it != out.groups.end()) return static_cast<int>(it - out.groups.begin());
        out.groups.push_back(name);
        out.group_ra.emplace_back(d.ra);
        return static_cast<int>(out.groups.size()) - 1;
    }

    int component_of(const SourceDesign& d, bool luminaire) {
        const int group = group_of(d);
        auto& ra = out.group_ra[static_cast<std::size_t>(group)];
        ra = ra && d.ra ? std::optional<double>(std::min(*ra, *d.ra)) : std::nullopt;
        const char* from = d.maintenance_factor ? (luminaire ? "luminaire" : "material")
                           : scene.settings.maintenance_factor ? "settings"
                                                               : "default";
        const double factor =
            d.maintenance_factor.value_or(scene.settings.maintenance_factor.value_or(1.0));
        auto use = std::find_if(out.uses.begin(), out.uses.end(), [&](const MaintenanceUse& u) {
            return u.factor == factor && u.from == from;
        });
        if (use == out.uses.end()) use = out.uses.insert(out.uses.end(), {factor, from, 0, 0});
        ++(luminaire ? use->luminaires : use->materials);
        const auto it = std::find_if(out.components.begin(), out.components.end(),
                                     [&](const LightComponent& c) {
                                         return c.group == group && c.maintenance_factor == factor;
                                     });
        if (it != out.components.end()) return static_cast<int>(it - out.components.begin());
        out.components.push_back({group, factor});
        return static_cast<int>(out.components.size()) - 1;
    }
};

}  // namespace

LightComponents light_components(const Scene& scene) {
    LightComponents out;
    Assigner assign{scene, out};
    for (const Luminaire& l : scene.luminaires)
        out.luminaire_component.push_back(assign.component_of(l.design, true));
    for (const Material& m : scene.materials) {
        out.material_component.push_back(m.emission ? assign.component_of(m.emission->design, false)
                                                    : -1);
    }
    return out;
}

std::string monte_carlo_only_reason(const Scene& scene) {
    if (light_components(scene).components.size() > 1) {
        return "light scene groups and per-source maintenance factors are solved apart only by "
               "method \"monte-carlo\"";
    }
    for (const SensorSet& s : scene.sensors) {
        if (s.kind != SensorKind::planar) {
            return "sensor kind \"" + std::string(to_string(s.kind)) +
                   "\" is measured only by method \"monte-carlo\"";
        }
    }
    return {};
}

}  // namespace radiant
