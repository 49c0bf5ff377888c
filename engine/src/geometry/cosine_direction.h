// Directions distributed as cos θ about a surface normal: how diffuse light leaves a surface,
// and how a sensor weighs the light it receives.
#pragma once

#include <cmath>
#include <numbers>

#include "radiant/vec3.h"

namespace radiant {

/// Cosine-distributed unit direction about unit n from two uniform numbers (Malley's method).
inline Vec3 cosine_direction(const Vec3& n, double r1, double r2) {
    const Vec3 t =
        normalized(std::abs(n.x) < 0.9 ? cross(n, Vec3{1, 0, 0}) : cross(n, Vec3{0, 1, 0}));
    const Vec3 b = cross(n, t);
    const double s = std::sqrt(r1), phi = 2 * std::numbers::pi * r2;
    return t * (s * std::cos(phi)) + b * (s * std::sin(phi)) + n * std::sqrt(1 - r1);
}

}  // namespace radiant
