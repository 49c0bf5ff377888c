#include "visibility/occlusion_culling.h"

#include <algorithm>

#include <tbb/parallel_for.h>

namespace radiant {
namespace {

void extend(Vec3& lo, Vec3& hi, std::span<const Vec3> points) {
    for (const Vec3& v : points) {
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], v[a]);
            hi[a] = std::max(hi[a], v[a]);
        }
    }
}

}  // namespace

OcclusionCulling::OcclusionCulling(const PreparedScene& scene, std::size_t max_pieces)
    : scene_(scene), eps_(1e-7 * scene.diagonal_m) {
    const std::size_t k = scene.pieces.size();
    enabled_ = k <= max_pieces;
    lo_.assign(k, Vec3{1e300, 1e300, 1e300});
    hi_.assign(k, Vec3{-1e300, -1e300, -1e300});
    for (std::size_t i = 0; i < k; ++i) extend(lo_[i], hi_[i], scene.pieces[i].vertices);
    all_.resize(k);
    for (std::size_t i = 0; i < k; ++i) all_[i] = static_cast<int>(i);
    if (!enabled_) return;
    pair_candidates_.resize(k * k);
    tbb::parallel_for(std::size_t{0}, k, [&](std::size_t a) {
        const Piece& pa = scene.pieces[a];
        for (std::size_t b = 0; b < k; ++b) {
            if (a == b) continue;
            const Piece& pb = scene.pieces[b];
            Vec3 lo = lo_[a], hi = hi_[a];
            extend(lo, hi, pb.vertices);
            auto& list = pair_candidates_[a * k + b];
            for (std::size_t q = 0; q < k; ++q) {
                if (q == a || q == b) continue;
                if (can_block(static_cast<int>(q), lo, hi, pa.vertices[0], pa.normal,
                              pb.vertices[0], pb.normal)) {
                    list.push_back(static_cast<int>(q));
                }
            }
        }
    });
}

// q cannot block when it is entirely behind (or on) either end's plane, or when its bounding box
// does not overlap the shaft's bounding box with positive volume.
bool OcclusionCulling::can_block(int q, const Vec3& lo, const Vec3& hi, const Vec3& pa,
                                 const Vec3& na, const Vec3& pb, const Vec3& nb) const {
    for (int a = 0; a < 3; ++a) {
        if (std::min(hi[a], hi_[q][a]) - std::max(lo[a], lo_[q][a]) <= eps_) return false;
    }
    const auto& v = scene_.pieces[static_cast<std::size_t>(q)].vertices;
    // A zero normal (a point luminaire) restricts nothing on that end.
    const bool behind_a = na != Vec3{} && std::all_of(v.begin(), v.end(), [&](const Vec3& p) {
        return dot(p - pa, na) <= eps_;
    });
    if (behind_a) return false;
    const bool behind_b = nb != Vec3{} && std::all_of(v.begin(), v.end(), [&](const Vec3& p) {
        return dot(p - pb, nb) <= eps_;
    });
    return !behind_b;
}

const std::vector<int>& OcclusionCulling::candidates(int a, int b) const {
    if (!enabled_) return all_;
    return pair_candidates_[static_cast<std::size_t>(a) * scene_.pieces.size() +
                            static_cast<std::size_t>(b)];
}

bool OcclusionCulling::maybe_blocked(int piece_a, std::span<const Vec3> a, const Vec3& na,
                                     int piece_b, std::span<const Vec3> b, const Vec3& nb) const {
    const auto& list = candidates(piece_a, piece_b);
    if (list.empty()) return false;
    Vec3 lo = a[0], hi = a[0];
    extend(lo, hi, a);
    extend(lo, hi, b);
    for (const int q : list) {
        if (q == piece_a || q == piece_b) continue;
        if (can_block(q, lo, hi, a[0], na, b[0], nb)) return true;
    }
    return false;
}

bool OcclusionCulling::maybe_blocked_from_point(const Vec3& x, const Vec3& n, int piece_b,
                                                std::span<const Vec3> b, const Vec3& nb) const {
    Vec3 lo = x, hi = x;
    extend(lo, hi, b);
    for (std::size_t q = 0; q < scene_.pieces.size(); ++q) {
        if (static_cast<int>(q) == piece_b) continue;
        if (can_block(static_cast<int>(q), lo, hi, x, n, b[0], nb)) return true;
    }
    return false;
}

}  // namespace radiant
