// The checks of what a lighting designer adds to a scene: groups, maintenance factors, sensor
// kinds, requirements, observers, luminous areas and light scenes (part of check_scene).
#pragma once

#include <vector>

#include "radiant/scene.h"

namespace radiant {

/// Appends every problem of the scene's lighting-design keys to `problems`, their limits
/// (components, light scenes, observers, kept sensor values) included.
void check_lighting_design(const Scene& scene, const SceneLimits& limits,
                           std::vector<Problem>& problems);

}  // namespace radiant
