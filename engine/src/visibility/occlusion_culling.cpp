#include "visibility/occlusion_culling.h"
#include "radiant/box.h"

#include <algorithm>
#include <atomic>

#include "parallel/fork_join.h"

namespace radiant {
namespace {

// Beyond this many occluders a point query casts rays rather than testing each one.
constexpr std::size_t kMaxPointTests = 256;

}  // namespace

namespace {

// Every point a segment may end at: the pieces' corners, the luminaires and the sensors.
std::vector<Vec3> everything_placed(const PreparedScene& scene) {
    std::vector<Vec3> points;
    for (const Piece& p : scene.pieces)
        points.insert(points.end(), p.vertices.begin(), p.vertices.end());
    for (const PreparedLuminaire& l : scene.luminaires) points.push_back(l.position);
    for (const PreparedSensorSet& s : scene.sensors)
        points.insert(points.end(), s.points.begin(), s.points.end());
    return points;
}

// A piece with all geometry, luminaires and sensors on or in front of its plane (a wall of a
// convex room, a facet of a sphere) bounds the scene's convex hull: a segment between two points
// in that closed half-space cannot cross it, so it never blocks anything.
bool may_occlude(const Piece& p, std::span<const Vec3> points, double eps) {
    return std::any_of(points.begin(), points.end(),
                       [&](const Vec3& v) { return dot(v - p.vertices[0], p.normal) < -eps; });
}

double culling_epsilon(const PreparedScene& scene) { return 1e-7 * scene.diagonal_m; }

std::vector<int> potential_occluders(const PreparedScene& scene, double eps) {
    const std::vector<Vec3> points = everything_placed(scene);
    const std::size_t k = scene.pieces.size();
    std::vector<char> occludes(k, 0);
    parallel_for(0, k,
                 [&](std::size_t q) { occludes[q] = may_occlude(scene.pieces[q], points, eps); });
    std::vector<int> out;
    for (std::size_t q = 0; q < k; ++q) {
        if (occludes[q]) out.push_back(static_cast<int>(q));
    }
    return out;
}

}  // namespace

bool nothing_can_occlude(const PreparedScene& scene) {
    const std::vector<Vec3> points = everything_placed(scene);
    const double eps = culling_epsilon(scene);
    std::atomic<bool> found{false};
    parallel_for(0, scene.pieces.size(), [&](std::size_t q) {
        if (!found.load(std::memory_order_relaxed) && may_occlude(scene.pieces[q], points, eps))
            found = true;
    });
    return !found;
}

OcclusionCulling::OcclusionCulling(const PreparedScene& scene, std::size_t max_tests)
    : scene_(scene), eps_(culling_epsilon(scene)) {
    const std::size_t k = scene.pieces.size();
    boxes_.reserve(k);
    for (const Piece& p : scene.pieces) boxes_.push_back(bounding_box(p.vertices));
    occluders_ = potential_occluders(scene, eps_);
    enabled_ = !occluders_.empty() && k * k <= max_tests / occluders_.size();
    if (!enabled_) return;
    pair_candidates_.resize(k * k);
    // A two-sided piece's back patches face the other way, so its lists may not drop what lies
    // behind its front (the slat beyond the next one of a blind would be seen through it).
    auto facing = [&](const Piece& p) {
        return scene.materials[static_cast<std::size_t>(p.material)].two_sided ? Vec3{} : p.normal;
    };
    parallel_for(0, k, [&](std::size_t a) {
        const Piece& pa = scene.pieces[a];
        for (std::size_t b = 0; b < k; ++b) {
            if (a == b) continue;
            const Piece& pb = scene.pieces[b];
            Box shaft = boxes_[a];
            shaft.add(pb.vertices);
            auto& list = pair_candidates_[a * k + b];
            for (const int q : occluders_) {
                if (q == static_cast<int>(a) || q == static_cast<int>(b)) continue;
                if (can_block(q, shaft, pa.vertices[0], facing(pa), pb.vertices[0], facing(pb))) {
                    list.push_back(q);
                }
            }
        }
    });
}

// q cannot block when it is entirely behind (or on) either end's plane, or when it lies outside
// (or on) one face of the shaft's bounding box. A flat q inside the box does block: only the
// box's faces, not a zero-volume overlap, decide.
bool OcclusionCulling::can_block(int q, const Box& shaft, const Vec3& pa, const Vec3& na,
                                 const Vec3& pb, const Vec3& nb) const {
    const Box& box = boxes_[static_cast<std::size_t>(q)];
    for (int a = 0; a < 3; ++a) {
        if (box.hi[a] <= shaft.lo[a] + eps_ || box.lo[a] >= shaft.hi[a] - eps_) return false;
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
    return pair_candidates_[static_cast<std::size_t>(a) * scene_.pieces.size() +
                            static_cast<std::size_t>(b)];
}

bool OcclusionCulling::maybe_blocked(int piece_a, std::span<const Vec3> a, const Vec3& na,
                                     int piece_b, std::span<const Vec3> b, const Vec3& nb) const {
    // Without the pair lists, testing every occluder per pair would cost more than the rays.
    if (!enabled_) return !occluders_.empty();
    const auto& list = candidates(piece_a, piece_b);
    if (list.empty()) return false;
    Box shaft = bounding_box(a);
    shaft.add(b);
    for (const int q : list) {
        if (q == piece_a || q == piece_b) continue;
        if (can_block(q, shaft, a[0], na, b[0], nb)) return true;
    }
    return false;
}

bool OcclusionCulling::maybe_blocked_from_point(const Vec3& x, const Vec3& n, int piece_b,
                                                std::span<const Vec3> b, const Vec3& nb) const {
    if (occluders_.size() > kMaxPointTests) return true;
    Box shaft = bounding_box(b);
    shaft.add(x);
    for (const int q : occluders_) {
        if (q == piece_b) continue;
        if (can_block(q, shaft, x, n, b[0], nb)) return true;
    }
    return false;
}

}  // namespace radiant
