// Brute-force visibility in double precision: every query tests every triangle. Slow (O(n) per
// query) but simple enough to trust, so the tests use it as the oracle for the Embree version.
#include <optional>
#include <vector>

#include "visibility/visibility.h"

namespace radiant {
namespace {

// Same relative margin at the target as EmbreeVisibility: the target surface never blocks.
constexpr double kSegmentEnd = 1.0 - 1e-6;

/// Möller–Trumbore: ray parameter t where origin + t·dir meets the closed triangle, if any.
/// Edges count as inside, so a ray through a shared edge hits (no cracks between triangles).
std::optional<double> segment_triangle_t(const Triangle& tri, const Vec3& origin, const Vec3& dir) {
    const Vec3 e1 = tri.b - tri.a;
    const Vec3 e2 = tri.c - tri.a;
    const Vec3 p = cross(dir, e2);
    const double det = dot(e1, p);
    if (det == 0.0) return std::nullopt;  // parallel to the plane
    const double inv = 1.0 / det;
    const Vec3 s = origin - tri.a;
    const double u = dot(s, p) * inv;
    if (u < 0.0 || u > 1.0) return std::nullopt;
    const Vec3 q = cross(s, e1);
    const double v = dot(dir, q) * inv;
    if (v < 0.0 || u + v > 1.0) return std::nullopt;
    return dot(e2, q) * inv;
}

class BruteForceVisibility final : public Visibility {
public:
    explicit BruteForceVisibility(std::span<const Triangle> triangles)
        : Visibility(ray_epsilon(triangles)) {
        for (std::size_t i = 0; i < triangles.size(); ++i) {
            if (is_degenerate(triangles[i])) continue;
            triangles_.push_back(triangles[i]);
            index_.push_back(static_cast<int>(i));
        }
    }

    /// Thread-safe: reads immutable state only.
    bool visible(const Vec3& from, const Vec3& to) const override {
        if (!is_finite(from) || !is_finite(to)) return false;  // same rule as Embree
        const Vec3 dir = to - from;
        for (const Triangle& t : triangles_) {
            const auto hit = segment_triangle_t(t, from, dir);
            if (hit && *hit > 0.0 && *hit < kSegmentEnd) return false;
        }
        return true;
    }

    /// Thread-safe: reads immutable state only. Ties in t go to the lower input index.
    RayHit intersect(const Vec3& origin, const Vec3& direction, double t_max) const override {
        if (!is_finite(origin) || !is_finite(direction) || !(t_max > 0.0)) return {};
        int best = -1;
        double best_t = t_max;
        for (std::size_t i = 0; i < triangles_.size(); ++i) {
            const auto hit = segment_triangle_t(triangles_[i], origin, direction);
            if (hit && *hit > 0.0 && (*hit < best_t || (best < 0 && *hit == best_t))) {
                best_t = *hit;
                best = index_[i];
            }
        }
        return best < 0 ? RayHit{} : RayHit{best, best_t};
    }

private:
    std::vector<Triangle> triangles_;  // non-degenerate input triangles
    std::vector<int> index_;           // triangles_[k] is input triangle index_[k]
};

}  // namespace

std::unique_ptr<Visibility> make_brute_force_visibility(std::span<const Triangle> triangles) {
    return std::make_unique<BruteForceVisibility>(triangles);
}

}  // namespace radiant
