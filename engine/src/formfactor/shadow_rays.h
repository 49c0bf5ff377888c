// Sampled visibility between a point and a polygon: one coherent shaft of shadow rays.
#pragma once

#include <cstdint>
#include <span>

#include "geometry/random.h"
#include "visibility/visibility.h"

namespace radiant {

/// Share of the point-to-polygon factor that `m` stratified shadow rays from x (lifted ε along its
/// unit normal n) find unblocked, each ray weighted by the kernel toward its target, of the convex
/// polygon (unit normal `normal`, centroid `centre`). Targets are inset 2ε toward the
/// centre: a blocker standing on the polygon's edge (a partition on a floor) must cross the ray
/// farther from its end than the end margin that spares the polygon itself, or light leaks.
double visible_fraction(const Visibility& visibility, const Vec3& x, const Vec3& n,
                        std::span<const Vec3> polygon, const Vec3& centre, const Vec3& normal,
                        int m, SampleStream& rng, std::uint64_t& rays);

}  // namespace radiant
