// A model drawn y-up (as three.js and glTF draw), written as a radiant-scene/1 document, which
// is z-up: its work planes face +y and its luminaires hang under a ceiling at the top of y, but
// a luminaire's default aim [0, 0, -1] then points along the floor, at a wall. The room reads
// about half its light, and nothing looks wrong.
#pragma once

#include <vector>

#include "radiant/warnings.h"
#include "scene/prepared_scene.h"

namespace radiant {

/// up_axis_suspect when sensor points face +y and none face +z, and most of the aimed
/// luminaires' flux hangs near the model's top along y, not also near its top along z (a z-up
/// room's downlights along its +y wall), with aims along the y-up floor: only
/// then do the z-up defaults give a wrong answer (isotropic luminaires, or aims given in y,
/// light a consistent y-up model as meant).
void check_up_axis(const Scene& scene, const PreparedScene& prepared, std::vector<Warning>& out);

}  // namespace radiant
