#include "formfactor/enclosure.h"

#include <algorithm>
#include <cmath>

#include "formfactor/quadrature.h"
#include "geometry/cosine_direction.h"
#include "geometry/random.h"
#include "parallel/fork_join.h"
#include "parallel/stop_poll.h"

namespace radiant {
namespace {

// A facing parallel surface nearer than this fraction of either's size is in near contact.
constexpr double kNearContact = 0.02;
constexpr double kParallelCosine = 0.99;

}  // namespace

double mean_free_path(const PreparedScene& scene, const Visibility& visibility,
                      std::span<const int> triangle_piece, std::uint64_t seed, std::uint64_t& cast,
                      int rays) {
    if (scene.pieces.empty() || !(scene.total_area_m2 > 0)) return scene.diagonal_m;
    std::vector<double> cdf;
    double total = 0;
    for (const Piece& p : scene.pieces) cdf.push_back(total += p.area_m2);
    const double eps = visibility.epsilon();
    const double reach = 4 * scene.diagonal_m + 1;
    SampleStream rng(seed, 0x6d6670ull, 0);
    double sum = 0;
    int hits = 0;
    for (int r = 0; r < rays; ++r) {
        // Stratified over the area so that small scenes get a stable estimate.
        const double pick = (r + rng.next()) / rays * total;
        const auto at = std::upper_bound(cdf.begin(), cdf.end(), pick) - cdf.begin();
        const Piece& p = scene.pieces[static_cast<std::size_t>(
            std::min<std::ptrdiff_t>(at, static_cast<std::ptrdiff_t>(cdf.size()) - 1))];
        const double u[2] = {rng.next(), rng.next()};
        const Vec3 x = stratified_points(p.vertices, 1, u)[0] + p.normal * eps;
        const Vec3 dir = cosine_direction(p.normal, rng.next(), rng.next());
        const RayHit hit = visibility.intersect(x, dir, reach);
        ++cast;
        if (hit.triangle < 0) continue;
        const auto tri = static_cast<std::size_t>(hit.triangle);
        if (tri < triangle_piece.size()) {
            const Piece& q = scene.pieces[static_cast<std::size_t>(triangle_piece[tri])];
            const double size = std::sqrt(std::min(p.area_m2, q.area_m2));
            if (dot(p.normal, q.normal) < -kParallelCosine &&
                hit.t * dot(dir, p.normal) < kNearContact * size) {
                continue;
            }
        }
        sum += hit.t;
        ++hits;
    }
    return hits > 0 ? sum / hits : scene.diagonal_m;
}

namespace {

// What rays from a patch found: how many were cast, escaped the scene, or hit the back of a
// one-sided piece (light comes back from neither).
struct HemisphereSurvey {
    int cast = 0, escaped = 0, backs = 0;
};

// Rays after which front_shares judges whether a patch's share is worth measuring.
constexpr int kProbeRays = 64;
// The surveys ask whether to stop once per this many patches.
constexpr std::size_t kStopCheckEvery = 256;

// Casts about `rays` rays (rounded up to g²) from stratified points of patch i, in
// cosine-distributed directions on a jittered g × g grid of the hemisphere's cosine-weighted
// square (cells in random order, so any first k are a fair sample); with `stop_at_first`,
// stops at the first that does not end on a front, and after kProbeRays if fewer than
// `least_share` of them did.
HemisphereSurvey survey_hemisphere(const PreparedScene& scene, const PatchMesh& patches,
                                   const Visibility& visibility,
                                   std::span<const int> triangle_piece, std::uint64_t seed,
                                   std::size_t i, int rays, bool stop_at_first,
                                   double least_share = 0) {
    const PatchGeometry& p = patches.patch(i);
    const double eps = visibility.epsilon();
    const double reach = 4 * scene.diagonal_m + 1;
    const auto g = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(rays))));
    const int n = g * g;
    SampleStream rng(seed, 0x656e636cull, i, static_cast<std::uint64_t>(n));
    std::vector<double> u(2 * static_cast<std::size_t>(n));
    for (double& v : u) v = rng.next();
    const std::vector<Vec3> origins = stratified_points(p.vertices, n, u);
    // Cells in random order, so that a point's place on the patch and its ray's direction are
    // not correlated.
    std::vector<int> cell(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) cell[static_cast<std::size_t>(k)] = k;
    for (int k = n - 1; k > 0; --k) {
        const auto j = static_cast<int>(rng.next() * (k + 1));
        std::swap(cell[static_cast<std::size_t>(k)], cell[static_cast<std::size_t>(j)]);
    }
    HemisphereSurvey out;
    for (int k = 0; k < n; ++k) {
        if (k == kProbeRays && out.cast - out.escaped - out.backs < least_share * out.cast) break;
        const int c = cell[static_cast<std::size_t>(k)];
        const Vec3 dir =
            cosine_direction(p.normal, (c % g + rng.next()) / g, (c / g + rng.next()) / g);
        const Vec3 x = origins[static_cast<std::size_t>(k)] + p.normal * eps;
        const int hit = visibility.first_hit(x, dir, reach);
        ++out.cast;
        if (hit < 0) {
            ++out.escaped;
            if (stop_at_first) break;
            continue;
        }
        const Piece& q =
            scene.pieces[static_cast<std::size_t>(triangle_piece[static_cast<std::size_t>(hit)])];
        if (dot(dir, q.normal) >= 0 &&
            !scene.materials[static_cast<std::size_t>(q.material)].two_sided) {
            ++out.backs;
            if (stop_at_first) break;
        }
    }
    return out;
}

}  // namespace

std::vector<char> enclosed_patches(const PreparedScene& scene, const PatchMesh& patches,
                                   const Visibility& visibility,
                                   std::span<const int> triangle_piece, std::uint64_t seed,
                                   std::uint64_t& cast, const std::function<bool()>& should_stop,
                                   int min_rays_per_patch, int min_rays_per_piece) {
    std::vector<int> piece_patches(scene.pieces.size(), 0);
    for (std::size_t i = 0; i < patches.size(); ++i)
        ++piece_patches[static_cast<std::size_t>(patches.patch(i).piece)];
    // A back of a one-sided piece is local (as under a box standing on the floor): it marks its
    // own patch. An escape is an opening, which the whole piece sees (a patch that found a back
    // looks no further: its piece's other patches see the opening as well).
    std::vector<HemisphereSurvey> found(patches.size());
    std::vector<char> surveyed(patches.size(), 0);
    StopPoll stop(should_stop, kStopCheckEvery);
    parallel_for(0, patches.size(), [&](std::size_t i) {
        if (stop(i)) return;
        surveyed[i] = 1;
        const int count = piece_patches[static_cast<std::size_t>(patches.patch(i).piece)];
        const int rays = std::max(min_rays_per_patch, (min_rays_per_piece + count - 1) / count);
        found[i] =
            survey_hemisphere(scene, patches, visibility, triangle_piece, seed, i, rays, true);
    });
    std::vector<char> piece_open(scene.pieces.size(), 0);
    for (std::size_t i = 0; i < patches.size(); ++i) {
        cast += static_cast<std::uint64_t>(found[i].cast);
        if (found[i].escaped > 0) piece_open[static_cast<std::size_t>(patches.patch(i).piece)] = 1;
    }
    std::vector<char> enclosed(patches.size(), 0);
    for (std::size_t i = 0; i < patches.size(); ++i) {
        enclosed[i] = surveyed[i] && found[i].escaped == 0 && found[i].backs == 0 &&
                      !piece_open[static_cast<std::size_t>(patches.patch(i).piece)];
    }
    return enclosed;
}

std::vector<double> front_shares(const PreparedScene& scene, const PatchMesh& patches,
                                 const Visibility& visibility, std::span<const int> triangle_piece,
                                 std::uint64_t seed, std::span<const char> enclosed, double wanted,
                                 std::uint64_t& cast, const std::function<bool()>& should_stop,
                                 int rays_per_patch, std::size_t max_rays) {
    std::vector<double> share(patches.size(), 1.0);
    const auto open = static_cast<std::size_t>(std::count(enclosed.begin(), enclosed.end(), 0));
    if (open == 0) return share;
    const int rays = std::max(
        kMinFrontShareRays,
        static_cast<int>(std::min(static_cast<std::size_t>(rays_per_patch), max_rays / open)));
    std::vector<int> cast_from(patches.size(), 0);
    StopPoll stop(should_stop, kStopCheckEvery);
    parallel_for(0, patches.size(), [&](std::size_t i) {
        if (enclosed[i] || stop(i)) return;
        const HemisphereSurvey s = survey_hemisphere(scene, patches, visibility, triangle_piece,
                                                     seed, i, rays, false, wanted / 2);
        share[i] = 1 - static_cast<double>(s.escaped + s.backs) / s.cast;
        cast_from[i] = s.cast;
    });
    for (const int c : cast_from) cast += static_cast<std::uint64_t>(c);
    return share;
}

}  // namespace radiant
