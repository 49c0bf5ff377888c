// Light sources sorted into components: one per (group, maintenance factor) pair. Light is
// linear in the emission, so a solve that keeps the components apart gives every group's
// contribution (light scenes) and the initial and maintained values (each component times its
// factor) at once.
#pragma once

#include <string>
#include <vector>

#include "radiant/result.h"
#include "radiant/scene.h"

namespace radiant {

/// Sources without a group are in this one.
inline constexpr const char* kDefaultGroup = "default";

struct LightComponent {
    int group = 0;  ///< index into LightComponents::groups
    double maintenance_factor = 1;
};

struct LightComponents {
    std::vector<std::string> groups;  ///< in first-seen order: luminaires, then materials
    std::vector<LightComponent> components;
    std::vector<int> luminaire_component;  ///< per luminaire of the scene
    std::vector<int> material_component;   ///< per material; −1 when it does not emit
    std::vector<MaintenanceUse> uses;      ///< which factor applied to how many sources
    /// The smallest Ra of each group's sources; unset when a source of it lacks one.
    std::vector<std::optional<double>> group_ra;
    bool named_groups = false;  ///< some source names a group
};

/// The components of a scene that passed check_scene(). Pure.
LightComponents light_components(const Scene& scene);

/// Why `scene` can be solved only by the Monte Carlo method (several components, or a sensor
/// kind other than planar), or empty when any method will do.
std::string monte_carlo_only_reason(const Scene& scene);

}  // namespace radiant
