// A scene in the wrong `units`: metre coordinates under "mm" make a room of a few millimetres
// (and one point at 6·10⁸ lx), millimetre coordinates under "m" a room kilometres across.
#pragma once

#include <vector>

#include "radiant/warnings.h"
#include "scene/prepared_scene.h"

namespace radiant {

/// units_suspect when the model's size, its luminaires' spacing, or the light they spread over
/// its surfaces is far outside what any interior has, with the unit that would make it right.
void check_units(const Scene& scene, const PreparedScene& prepared, std::vector<Warning>& out);

}  // namespace radiant
