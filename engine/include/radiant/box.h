// Axis-aligned bounding boxes of points: scene extents, occluder shafts, camera framing.
#pragma once

#include <algorithm>
#include <cmath>
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

/// Gap between two boxes (0 where they touch or overlap).
inline double distance(const Box& a, const Box& b) {
    double d2 = 0;
    for (int k = 0; k < 3; ++k) {
        const double d = std::max({b.lo[k] - a.hi[k], 0.0, a.lo[k] - b.hi[k]});
        d2 += d * d;
    }
    return std::sqrt(d2);
}

/// Whether no corner of `box` lies strictly in front of the plane through `point` with
/// normal `normal`.
constexpr bool behind(const Box& box, const Vec3& point, const Vec3& normal) {
    for (int k = 0; k < 8; ++k) {
        const Vec3 c{(k & 1) ? box.hi.x : box.lo.x, (k & 2) ? box.hi.y : box.lo.y,
                     (k & 4) ? box.hi.z : box.lo.z};
        if (dot(c - point, normal) > 0) return false;
    }
    return true;
}

/// The box of `points`; empty when there are none.
constexpr Box bounding_box(std::span<const Vec3> points) {
    Box box;
    box.add(points);
    return box;
}

}  // namespace radiant
