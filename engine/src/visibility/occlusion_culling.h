// Shaft culling (Haines & Wallace 1991, simplified): decides from geometry alone when nothing can
// stand between two patches, so no shadow ray is cast there. Conservative: "maybe" is always safe.
#pragma once

#include <span>
#include <vector>

#include "scene/prepared_scene.h"

namespace radiant {

class OcclusionCulling {
public:
    /// Precomputes, for every ordered pair of pieces, the pieces that might block between them.
    /// Above `max_pieces` pieces it gives up (every pair may be occluded) to stay sub-cubic.
    OcclusionCulling(const PreparedScene& scene, std::size_t max_pieces = 600);

    /// True when some piece might block a segment between points of polygons a and b, which lie
    /// on pieces piece_a and piece_b with unit normals na and nb (front sides facing each other).
    bool maybe_blocked(int piece_a, std::span<const Vec3> a, const Vec3& na, int piece_b,
                       std::span<const Vec3> b, const Vec3& nb) const;

    /// True when some piece might block between point x (hemisphere about n) and polygon b.
    bool maybe_blocked_from_point(const Vec3& x, const Vec3& n, int piece_b,
                                  std::span<const Vec3> b, const Vec3& nb) const;

private:
    bool can_block(int q, const Vec3& lo, const Vec3& hi, const Vec3& pa, const Vec3& na,
                   const Vec3& pb, const Vec3& nb) const;
    const std::vector<int>& candidates(int a, int b) const;

    const PreparedScene& scene_;
    double eps_;
    bool enabled_;
    std::vector<Vec3> lo_, hi_;
    std::vector<std::vector<int>> pair_candidates_;  // [a * k + b]
    std::vector<int> all_;
};

}  // namespace radiant
