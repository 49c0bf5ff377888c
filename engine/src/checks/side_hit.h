// Which side of which piece a ray meets first: the question every placement check asks.
#pragma once

#include "checks/modelling_checks.h"

namespace radiant {

struct SideHit {
    int piece = -1;      ///< −1: the ray left the model
    bool back = false;   ///< it arrived from behind the piece
    bool black = false;  ///< a back of a one-sided material: light that arrives there is lost
    double t = 0;        ///< distance along the (unit) direction, metres
    bool escaped() const { return piece < 0; }
};

/// The first side hit from `origin` (local frame) along unit `direction`; the first
/// visibility.epsilon() of the ray is skipped, so that a point on a surface does not hit it.
SideHit side_hit(const CheckedScene& input, const Vec3& origin, const Vec3& direction);

/// Direction k of n spread evenly over the sphere (a Fibonacci lattice: equal solid angles).
Vec3 sphere_direction(std::size_t k, std::size_t n);

}  // namespace radiant
