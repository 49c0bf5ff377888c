#include "design/light_components.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace radiant {
namespace {

// Lookups by map: a scene may have up to SceneLimits::max_luminaires sources, each naming its
// own group or factor, and check_scene() sorts them before it refuses too many components.
struct Assigner {
    const Scene& scene;
    LightComponents& out;
    std::map<std::string, int> group_index{};
    std::map<std::pair<int, double>, int> component_index{};
    std::map<std::pair<double, std::string>, std::size_t> use_index{};

    int group_of(const SourceDesign& d) {
        const std::string name = d.group.value_or(kDefaultGroup);
        out.named_groups = out.named_groups || d.group.has_value();
        const auto [it, added] = group_index.try_emplace(name, static_cast<int>(out.groups.size()));
        if (added) {
            out.groups.push_back(name);
            out.group_ra.emplace_back(d.ra);
        }
        return it->second;
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
        // check_scene() refuses a factor that is not finite; as a key it must still order.
        const double key = std::isfinite(factor) ? factor : -1.0;
        const auto [use, new_use] = use_index.try_emplace({key, from}, out.uses.size());
        if (new_use) out.uses.push_back({factor, from, 0, 0});
        ++(luminaire ? out.uses[use->second].luminaires : out.uses[use->second].materials);
        const auto [it, added] =
            component_index.try_emplace({group, key}, static_cast<int>(out.components.size()));
        if (added) out.components.push_back({group, factor});
        return it->second;
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
