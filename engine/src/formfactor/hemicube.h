// The hemicube (Cohen & Greenberg 1985), ray-cast: kept to compare against the analytic
// point-to-polygon estimator, as in the lecture.
#pragma once

#include <span>
#include <vector>

#include "radiant/vec3.h"
#include "visibility/visibility.h"

namespace radiant {

/// Form factors from a differential area at `x` (unit normal `n`) to every patch, estimated
/// with a hemicube of `resolution` × `resolution` pixels on the top face (the side faces are
/// resolution × resolution/2). Each pixel casts one ray through its centre; the first triangle
/// hit is mapped to its patch by `triangle_patch` (−1: not a patch). Result size `patch_count`.
/// The ray origin is lifted by vis.epsilon() along n. Thread-safe.
std::vector<double> hemicube_factors(const Vec3& x, const Vec3& n, int resolution,
                                     const Visibility& vis, std::span<const int> triangle_patch,
                                     std::size_t patch_count);

}  // namespace radiant
