#include "formfactor/sampled_views.h"

#include <algorithm>
#include <cmath>

#include "formfactor/shadow_rays.h"
#include "geometry/random.h"

namespace radiant {
namespace {

// Keys the second samples' streams apart from the first samples' of the same point and source.
constexpr std::uint64_t kResampleKey = 0x5bd1e9955bd1e995ull;

}  // namespace

void SampledViews::add(const SampledView& view) {
    if (view.weight > 0 && view.rays > 0) views_.push_back(view);
}

void SampledViews::resample(const Visibility& visibility, const Vec3& x, const Vec3& n,
                            double sigma, int max_rays, std::uint64_t seed, std::uint64_t key,
                            Rgb& irradiance, std::uint64_t& rays) const {
    double variance = 0;
    for (const SampledView& v : views_) {
        variance += v.weight * v.weight * v.fraction * (1 - v.fraction) / v.rays;
    }
    if (!(variance > sigma * sigma)) return;
    // Every view's variance shrinks by the same factor: the sum meets the budget where the caps
    // allow. Which views are sampled again may not depend on their own first samples (keeping
    // those that saw all or nothing biases the sum), only on what they could add at most.
    const double factor = variance / (sigma * sigma);
    const double share = sigma * sigma / static_cast<double>(views_.size());
    Rgb change{0, 0, 0};
    for (const SampledView& v : views_) {
        if (v.weight * v.weight / (4.0 * v.rays) <= share) continue;
        const double wanted = std::ceil(v.rays * factor);
        const int m = wanted >= max_rays ? max_rays : static_cast<int>(wanted);
        if (m <= v.rays) continue;
        SampleStream rng(seed, key ^ kResampleKey, v.stream);
        const double fraction =
            visible_fraction(visibility, x, n, v.polygon, v.centre, v.normal, m, rng, rays);
        for (int c = 0; c < 3; ++c) change[c] += v.light[c] * (fraction - v.fraction);
    }
    for (int c = 0; c < 3; ++c) irradiance[c] = std::max(0.0, irradiance[c] + change[c]);
}

}  // namespace radiant
