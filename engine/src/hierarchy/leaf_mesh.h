// The display mesh of a solved hierarchy: its leaves as triangles, with vertex radiosity
// averaged (by area) over the leaves of one surface side that share the vertex, never across
// surfaces or creases.
#pragma once

#include <span>

#include "hierarchy/element_tree.h"
#include "meshing/patch_mesh.h"
#include "radiant/result.h"

namespace radiant {

SolvedMesh leaf_mesh(const ElementTree& tree, const PatchMesh& patches, int channels,
                     const Vec3& world_origin);

/// The same, showing `radiosity[e]` (photometric) on leaf e instead of its solved radiosity.
SolvedMesh leaf_mesh(const ElementTree& tree, const PatchMesh& patches,
                     std::span<const double> radiosity, const Vec3& world_origin);

}  // namespace radiant
