// Points of a triangle drawn uniformly by area.
#pragma once

#include <cmath>

#include "radiant/vec3.h"

namespace radiant {

/// The point of triangle (a, b, c) that two uniform numbers give, uniform over its area.
inline Vec3 uniform_triangle_point(const Vec3& a, const Vec3& b, const Vec3& c, double r1,
                                   double r2) {
    const double s = std::sqrt(r1);
    return a * (1 - s) + b * (s * (1 - r2)) + c * (s * r2);
}

}  // namespace radiant
