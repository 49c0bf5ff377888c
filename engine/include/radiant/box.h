// Axis-aligned bounding boxes of points: scene extents, occluder shafts, camera framing.
#pragma once

#include <algorithm>
#include <limits>
#include <span>

#include "radiant/vec3.h"

namespace radiant {

struct Box {
    static constexpr double kInf = std::numeric_limits<double>::infinity();
    Vec3 lo{kInf, kInf, kInf};  ///< empty until a point is added
    Vec3 hi{-kInf, -kInf, -kInf};

    /// Grows the box to contain `p`.
    constexpr void add(const Vec3& p) {
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], p[a]);
            hi[a] = std::max(hi[a], p[a]);
        }
    }
    constexpr void add(std::span<const Vec3> points) {
        for (const Vec3& p : points) add(p);
    }
    constexpr bool empty() const { return lo.x > hi.x; }
    constexpr Vec3 size() const { return hi - lo; }
    constexpr Vec3 centre() const { return 0.5 * (lo + hi); }
};

/// The box of `points`; empty when there are none.
constexpr Box bounding_box(std::span<const Vec3> points) {
    Box box;
    box.add(points);
    return box;
}

}  // namespace radiant
