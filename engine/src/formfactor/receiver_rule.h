// The quadrature rule a patch uses as a receiver: one fixed set of points per patch for every
// source, so that Σ_j F_ij is exactly the integral of Σ_j F(x→P_j), which Lambert's formula makes
// exactly 1 at every point of a closed, unoccluded enclosure. Row sums are therefore exact to
// rounding, which keeps furnaces right at ρ → 1 (an error δ in a row sum costs ρδ/(1−ρ)).
#pragma once

#include <vector>

#include "formfactor/quadrature.h"
#include "meshing/patch_mesh.h"

namespace radiant {

/// Fine rules near other patches (adjacent walls: the kernel is near-singular along the shared
/// edge), coarse ones for patches that only see far-away geometry.
std::vector<std::vector<QuadraturePoint>> receiver_rules(const PatchMesh& patches);

/// Splits a convex polygon into 4 (quads at edge midpoints, others into a centroid fan).
std::vector<std::vector<Vec3>> split_in_four(const std::vector<Vec3>& polygon);

}  // namespace radiant
