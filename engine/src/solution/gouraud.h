// Vertex radiosity for smooth (Gouraud) display of piecewise-constant patches (Cohen & Wallace
// 1993, ch. 9): area-weighted averages at interior vertices, linear extrapolation at the edges of
// a surface, never averaged across surfaces (the patch mesh shares vertices within a piece only).
#pragma once

#include <vector>

#include "meshing/patch_mesh.h"
#include "radiant/result.h"

namespace radiant {

/// The solved mesh as triangles in world coordinates, given one display value per patch.
SolvedMesh gouraud_mesh(const PatchMesh& patches, const std::vector<double>& patch_value,
                        const Vec3& world_origin);

}  // namespace radiant
