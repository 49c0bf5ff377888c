// A solved scene as binary glTF 2.0 (.glb) for viewers: the solved mesh with per-vertex colours
// and radiosity, and the sensor points with their illuminance.
#pragma once

#include <string>

#include "radiant/result.h"
#include "radiant/scene.h"

namespace radiant::proto {

/// The .glb bytes. glTF conventions: metres, y up (Radiant's z-up scene is turned a quarter turn
/// about x). Node "surfaces" holds Result::mesh as triangles with COLOR_0 = vertex radiosity /
/// the largest vertex radiosity (linear, unlit material) and `_RADIOSITY` (lm/m²); node "sensors"
/// holds the points of `scene`'s sensor sets as a POINTS primitive with COLOR_0 = illuminance /
/// the largest and `_ILLUMINANCE` (lux). The scene's extras give the scene name, its units and
/// both colour scales. Parts without data (no mesh, no sensors) are left out.
std::string result_to_glb(const Result& result, const Scene& scene);

}  // namespace radiant::proto
