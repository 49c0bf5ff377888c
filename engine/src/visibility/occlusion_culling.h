// Shaft culling (Haines & Wallace 1991, simplified): decides from geometry alone when nothing can
// stand between two patches, so no shadow ray is cast there. Conservative: "maybe" is always safe.
#pragma once

#include <span>
#include <vector>

#include "radiant/box.h"
#include "scene/prepared_scene.h"

namespace radiant {

/// True when no piece can block anything: every piece has all geometry, luminaires and sensors
/// on or in front of its plane (a convex room, a sphere), so every two points that face each
/// other see each other. Stops at the first piece that might block.
bool nothing_can_occlude(const PreparedScene& scene);

class OcclusionCulling {
public:
    /// Finds the pieces that can block anything at all, then precomputes for every ordered pair
    /// of pieces those that might block between them, unless that would take more than
    /// `max_tests` plane tests (then every potential occluder is a candidate for every pair).
    explicit OcclusionCulling(const PreparedScene& scene, std::size_t max_tests = 200'000'000);

    /// Pieces that might block some segment (those not on the scene's convex hull).
    std::size_t occluder_count() const { return occluders_.size(); }

    /// True when some piece might block a segment between points of polygons a and b, which lie
    /// on pieces piece_a and piece_b with unit normals na and nb (front sides facing each other).
    bool maybe_blocked(int piece_a, std::span<const Vec3> a, const Vec3& na, int piece_b,
                       std::span<const Vec3> b, const Vec3& nb) const;

    /// True when some piece might block between point x (hemisphere about n) and polygon b.
    bool maybe_blocked_from_point(const Vec3& x, const Vec3& n, int piece_b,
                                  std::span<const Vec3> b, const Vec3& nb) const;

private:
    bool can_block(int q, const Box& shaft, const Vec3& pa, const Vec3& na, const Vec3& pb,
                   const Vec3& nb) const;
    const std::vector<int>& candidates(int a, int b) const;

    const PreparedScene& scene_;
    double eps_;
    bool enabled_;
    std::vector<Box> boxes_;                         // of each piece
    std::vector<std::vector<int>> pair_candidates_;  // [a * k + b]
    std::vector<int> occluders_;
};

}  // namespace radiant
