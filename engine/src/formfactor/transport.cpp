#include "formfactor/transport.h"

#include <algorithm>
#include <cmath>

#include "formfactor/luminaire_light.h"
#include "formfactor/point_polygon.h"
#include "formfactor/receiver_rule.h"
#include "formfactor/shadow_rays.h"
#include "geometry/random.h"
#include "parallel/fork_join.h"
#include "parallel/per_thread.h"

namespace radiant {
namespace {

double front_factor(const Vec3& x, const Vec3& n, const PatchGeometry& src) {
    return front_point_to_polygon_factor(x, n, src.vertices, src.normal);
}

}  // namespace

Transport::Transport(const PreparedScene& scene, const PatchMesh& patches,
                     const Visibility& visibility, const OcclusionCulling& culling,
                     TransportOptions options, std::vector<char> enclosed)
    : scene_(scene),
      patches_(patches),
      visibility_(visibility),
      culling_(culling),
      options_(options),
      rules_(receiver_rules(patches)),
      enclosed_(std::move(enclosed)) {}

bool Transport::patch_emits(std::size_t j) const {
    const PatchGeometry& p = patches_.patch(j);
    return !p.back_side && !p.hidden &&
           scene_.materials[static_cast<std::size_t>(p.material)].emits();
}

// Light passes from j to i only when each lies (partly) in front of the other.
bool Transport::faces_each_other(std::size_t i, std::size_t j) const {
    const PatchGeometry& a = patches_.patch(i);
    const PatchGeometry& b = patches_.patch(j);
    if (a.hidden || b.hidden) return false;
    const double eps = 1e-9 * (a.diameter_m + b.diameter_m);
    const bool b_in_front_of_a =
        std::any_of(b.vertices.begin(), b.vertices.end(),
                    [&](const Vec3& v) { return dot(v - a.vertices[0], a.normal) > eps; });
    const bool a_in_front_of_b =
        std::any_of(a.vertices.begin(), a.vertices.end(),
                    [&](const Vec3& v) { return dot(v - b.vertices[0], b.normal) > eps; });
    return b_in_front_of_a && a_in_front_of_b;
}

double Transport::visible_fraction(const Vec3& x, const Vec3& n, std::size_t j, int m,
                                   std::uint64_t key, std::uint64_t& rays) const {
    const PatchGeometry& src = patches_.patch(j);
    SampleStream rng(options_.seed, key, j);
    return radiant::visible_fraction(visibility_, x, n, src.vertices, src.centroid, src.normal, m,
                                     rng, rays);
}

PointView Transport::point_view(const Vec3& x, const Vec3& n, std::size_t j, std::uint64_t key,
                                std::uint64_t& rays) const {
    const PatchGeometry& src = patches_.patch(j);
    PointView v;
    if (src.hidden) return v;
    v.factor = std::max(0.0, front_factor(x, n, src));
    if (v.factor <= 0) return v;
    if (!culling_.maybe_blocked_from_point(x, n, src.piece, src.vertices, src.normal)) return v;
    v.rays = patch_emits(j) ? options_.emitter_rays_per_point : options_.rays_per_point;
    v.fraction = visible_fraction(x, n, j, v.rays, key, rays);
    return v;
}

void Transport::resample(const SampledViews& views, const Vec3& x, const Vec3& n, double sigma,
                         std::uint64_t key, Rgb& irradiance, std::uint64_t& rays) const {
    views.resample(visibility_, x, n, sigma, options_.max_rays_per_point, options_.seed, key,
                   irradiance, rays);
}

void Transport::form_factor_row(std::size_t i, float* row, std::uint64_t& rays,
                                bool parallel) const {
    const PatchGeometry& rcv = patches_.patch(i);
    const auto& rule = rules_[i];
    const std::size_t n = patches_.size();
    const std::size_t points = rule.size();
    const int per_point = std::max(
        1, (options_.rays_per_link + static_cast<int>(points) - 1) / static_cast<int>(points));
    // Per source: none, clear (unoccluded: exact) or sampled, with its factor at every receiver
    // point. Unoccluded and sampled sources are kept apart so that an enclosed receiver can
    // complete the sampled ones to 1 point by point.
    enum : char { kNone, kClear, kSampled };
    std::vector<char> kind(n, kNone);
    std::vector<double> factor(n * points, 0.0);  // [j * points + k]
    auto source = [&](std::size_t j, std::uint64_t& local_rays) {
        if (j == i || !faces_each_other(i, j)) return;
        const PatchGeometry& src = patches_.patch(j);
        const bool blocked = culling_.maybe_blocked(rcv.piece, rcv.vertices, rcv.normal, src.piece,
                                                    src.vertices, src.normal);
        kind[j] = blocked ? kSampled : kClear;
        for (std::size_t k = 0; k < points; ++k) {
            double f = front_factor(rule[k].position, rcv.normal, src);
            if (blocked && f > 0) {
                f *= visible_fraction(rule[k].position, rcv.normal, j, per_point,
                                      (static_cast<std::uint64_t>(i) << 20) ^ k, local_rays);
            }
            factor[j * points + k] = f;
        }
    };
    if (parallel) {
        PerThread<std::uint64_t> ray_count([] { return std::uint64_t{0}; });
        parallel_for_chunks(0, n, 64, [&](std::size_t begin, std::size_t end) {
            std::uint64_t& local = ray_count.local();
            for (std::size_t j = begin; j != end; ++j) source(j, local);
        });
        rays += ray_count.combine([](std::uint64_t a, std::uint64_t b) { return a + b; });
    } else {
        for (std::size_t j = 0; j < n; ++j) source(j, rays);
    }
    // Sums in source order, so that the row does not depend on how the sources were shared out.
    std::vector<double> clear_sum(points, 0.0), sampled_sum(points, 0.0);
    for (std::size_t j = 0; j < n; ++j) {
        if (kind[j] == kNone) continue;
        auto& sum = kind[j] == kClear ? clear_sum : sampled_sum;
        for (std::size_t k = 0; k < points; ++k) sum[k] += factor[j * points + k];
    }
    std::vector<double> scale(points, 1.0);
    if (enclosed_[i]) {
        for (std::size_t k = 0; k < points; ++k) {
            if (sampled_sum[k] > 0) scale[k] = std::max(0.0, 1.0 - clear_sum[k]) / sampled_sum[k];
        }
    }
    for (std::size_t j = 0; j < n; ++j) {
        double sum = 0;
        if (kind[j] == kClear) {
            for (std::size_t k = 0; k < points; ++k) sum += rule[k].weight * factor[j * points + k];
        } else if (kind[j] == kSampled) {
            for (std::size_t k = 0; k < points; ++k)
                sum += rule[k].weight * scale[k] * factor[j * points + k];
        }
        row[j] = static_cast<float>(sum / rcv.area_m2);
    }
}

Rgb Transport::luminaire_irradiance_on_patch(std::size_t i, std::uint64_t& rays) const {
    const PatchGeometry& p = patches_.patch(i);
    if (p.hidden) return Rgb{0, 0, 0};
    return luminaire_irradiance_on_polygon(
        scene_, visibility_, p.vertices, p.normal, p.area_m2, rules_[i],
        [&](const PreparedLuminaire& l) {
            return culling_.maybe_blocked_from_point(l.position, Vec3{}, p.piece, p.vertices,
                                                     p.normal);
        },
        rays);
}

Rgb Transport::luminaire_irradiance_at(const Vec3& x, const Vec3& n, std::uint64_t /*key*/,
                                       std::uint64_t& rays) const {
    return radiant::luminaire_irradiance_at(scene_, visibility_, x, n, rays);
}

}  // namespace radiant
