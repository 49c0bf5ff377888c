// Triangles covering a planar polygon minus its holes (Honeybee faces with `holes`): each hole is
// bridged into the outer ring at a vertex it can see (Eberly, "Triangulation by Ear Clipping",
// 2002), then the single ring is ear-clipped.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "radiant/vec3.h"

namespace radiant::proto {

/// Vertex indices count through `outer`, then each hole in turn. Triangles turn the same way as
/// `outer` (holes may be given either way round). nullopt when the rings are degenerate or
/// overlap so that no triangulation exists.
std::optional<std::vector<std::array<int, 3>>> triangulate_with_holes(
    const std::vector<Vec3>& outer, const std::vector<std::vector<Vec3>>& holes);

}  // namespace radiant::proto
