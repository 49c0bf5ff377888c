#include "hierarchy/sensor_importance.h"

#include <algorithm>
#include <cmath>

#include "geometry/cosine_direction.h"
#include "geometry/random.h"
#include "hierarchy/root_patch_locator.h"
#include "parallel/fork_join.h"
#include "parallel/per_thread.h"
#include "solution/surface_summary.h"

namespace radiant {
namespace {

// A patch whose importance per area is at least this fraction of the scene's mean keeps the
// full accuracy: in a closed room of reflectance ≥ 0.2 that is everything a sensor sees directly
// or through one reflection (the floor under a work plane facing up).
constexpr double kFullWeightShare = 1.0 / 8;
// Walks end after this many bounces: what lies beyond is seen by the sensors through so many
// reflections that the margin above covers it.
constexpr int kMaxBounces = 16;
// Walks in all: enough for a stable mean on small scenes, bounded on huge ones.
constexpr std::size_t kMinWalks = 16384;
constexpr std::size_t kMaxWalks = std::size_t{1} << 21;
// A hit point lies within this many ray epsilons of the patch it hit (single-precision rays).
constexpr double kLocateMargin = 4;

struct SensorPoint {
    Vec3 position;
    Vec3 normal;
};

class Walker {
public:
    Walker(const PreparedScene& scene, const PatchMesh& roots, const ElementTree& tree,
           const Visibility& visibility, std::span<const int> triangle_piece)
        : scene_(scene),
          visibility_(visibility),
          triangle_piece_(triangle_piece),
          eps_(visibility.epsilon()),
          reach_(4 * scene.diagonal_m + 1),
          locator_(scene, roots, tree, kLocateMargin * eps_) {}

    /// Counts the walk's visits to each root patch in `visits`; returns the rays cast. `stack`
    /// is scratch space for the tree search.
    std::uint64_t walk(const SensorPoint& start, SampleStream& rng,
                       std::vector<std::uint64_t>& visits, std::vector<int>& stack) const {
        Vec3 origin = start.position + start.normal * eps_;
        Vec3 normal = start.normal;
        std::uint64_t rays = 0;
        for (int bounce = 0; bounce < kMaxBounces; ++bounce) {
            const Vec3 dir = cosine_direction(normal, rng.next(), rng.next());
            ++rays;
            const RayHit hit = visibility_.intersect(origin, dir, reach_);
            if (hit.triangle < 0) break;
            const auto tri = static_cast<std::size_t>(hit.triangle);
            if (tri >= triangle_piece_.size()) break;
            const auto piece = static_cast<std::size_t>(triangle_piece_[tri]);
            const Piece& q = scene_.pieces[piece];
            const PreparedMaterial& m = scene_.materials[static_cast<std::size_t>(q.material)];
            const bool front = dot(dir, q.normal) < 0;
            if (!front && !m.two_sided) break;  // the back of a one-sided surface sends nothing
            const Vec3 at = origin + dir * hit.t;
            const int patch = locator_.locate(at, dir, static_cast<int>(piece), stack);
            if (patch >= 0) ++visits[static_cast<std::size_t>(patch)];
            // Russian roulette: the walk goes on with the reflectance's probability, so that
            // every visit weighs the same and the counts are exact integers.
            if (rng.next() >= photometric(m.reflectance, scene_.channels)) break;
            normal = front ? q.normal : q.normal * -1.0;
            origin = at + normal * eps_;
        }
        return rays;
    }

private:
    const PreparedScene& scene_;
    const Visibility& visibility_;
    std::span<const int> triangle_piece_;
    double eps_;
    double reach_;
    RootPatchLocator locator_;
};

}  // namespace

ImportanceEstimate estimate_sensor_importance(const PreparedScene& scene, const PatchMesh& roots,
                                              const ElementTree& tree, const Visibility& visibility,
                                              std::span<const int> triangle_piece,
                                              std::uint64_t seed,
                                              const std::function<bool()>& should_stop,
                                              int walks_per_patch) {
    const std::size_t root_patches = roots.size();
    ImportanceEstimate out{std::vector<double>(root_patches, 0.0),
                           std::vector<double>(root_patches, 1.0), 0};
    std::vector<SensorPoint> points;
    for (const PreparedSensorSet& set : scene.sensors) {
        for (const Vec3& x : set.points) points.push_back({x, set.normal});
    }
    if (points.empty() || tree.top() < 0) return out;

    const std::size_t walks =
        std::clamp(static_cast<std::size_t>(std::max(walks_per_patch, 1)) * root_patches, kMinWalks,
                   kMaxWalks);
    const std::size_t per_point =
        std::max<std::size_t>(1, (walks + points.size() - 1) / points.size());
    const Walker walker(scene, roots, tree, visibility, triangle_piece);
    PerThread<std::vector<std::uint64_t>> visits(
        [root_patches] { return std::vector<std::uint64_t>(root_patches, 0); });
    PerThread<std::vector<int>> stacks;
    PerThread<std::uint64_t> rays([] { return std::uint64_t{0}; });
    // A cancel or deadline stops the walks between points; linking, which comes next, then stops
    // too, so the partial counts are never used for a result.
    parallel_for(0, points.size(), [&](std::size_t i) {
        if (should_stop && should_stop()) return;
        std::vector<std::uint64_t>& local = visits.local();
        std::vector<int>& stack = stacks.local();
        for (std::size_t w = 0; w < per_point; ++w) {
            SampleStream rng(seed, 0x696d70ull, i, w);
            rays.local() += walker.walk(points[i], rng, local, stack);
        }
    });
    std::vector<std::uint64_t> total(root_patches, 0);
    visits.combine_each([&](const std::vector<std::uint64_t>& local) {
        for (std::size_t p = 0; p < root_patches; ++p) total[p] += local[p];
    });
    out.rays = rays.combine([](std::uint64_t a, std::uint64_t b) { return a + b; });

    // Per-area importance of the root elements (hidden patches have none and no area here).
    const double walks_done = static_cast<double>(per_point * points.size());
    double visited = 0, area = 0;
    for (std::size_t e = 0; e < tree.size(); ++e) {
        const Element& x = tree[e];
        if (x.cluster || x.depth > 0) continue;
        const auto p = static_cast<std::size_t>(x.patch);
        const double v = static_cast<double>(total[p]) / walks_done;
        visited += v;
        area += x.area_m2;
        out.per_area[p] = x.area_m2 > 0 ? v / x.area_m2 : 0;
    }
    // Sensors that see no surface at all say nothing about which surfaces matter.
    if (!(visited > 0) || !(area > 0)) return out;
    const double full = kFullWeightShare * visited / area;
    for (std::size_t p = 0; p < root_patches; ++p) {
        out.refinement_weight[p] = std::clamp(out.per_area[p] / full, kMinRefinementWeight, 1.0);
    }
    return out;
}

}  // namespace radiant
