// The triangles a scene's visibility is built from: a fan of each prepared piece.
#pragma once

#include <utility>
#include <vector>

#include "scene/prepared_scene.h"
#include "visibility/visibility.h"

namespace radiant {

/// Every piece of `scene` as a fan of triangles, with the piece of each triangle (what a ray's
/// hit is traced back to).
std::pair<std::vector<Triangle>, std::vector<int>> occluder_triangles(const PreparedScene& scene);

}  // namespace radiant
