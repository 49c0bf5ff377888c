// A sensor point's sampled views of its sources. Sampled visibility is the noisy term of its
// illuminance: a window pane seen between blind slats through 16 shadow rays is off by about
// ±12 % of its light, view by view. Where the views' binomial standard deviation adds up to more
// than the point's budget, the views that could matter are sampled again with more rays.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "radiant/scene.h"
#include "visibility/visibility.h"

namespace radiant {

/// A point's view of a source polygon: Lambert's unoccluded factor and the share of it sampled
/// visible (`rays` 0: not sampled, proven clear or facing away).
struct PointView {
    double factor = 0;
    double fraction = 1;
    int rays = 0;
    double product() const { return factor * fraction; }
};

struct SampledView {
    std::span<const Vec3> polygon;  ///< convex source polygon, alive until resample() returns
    Vec3 centre;
    Vec3 normal;
    std::uint64_t stream = 0;  ///< the source's index: its sample stream
    Rgb light{0, 0, 0};        ///< per channel: what the point would receive, fully visible
    double weight = 0;         ///< the same in lux (photometric), for the variance
    double fraction = 0;       ///< sampled visible share
    int rays = 0;
};

class SampledViews {
public:
    void add(const SampledView& view);

    /// If the views' sampled shares p have a standard deviation (w²·p(1−p)/m each: stratified
    /// samples do at least this well) over `sigma` lux, samples again every view that could
    /// hold a share of it, with the rays that bring the sum under `sigma` (at most `max_rays`),
    /// from streams apart from the first samples' (seed, key, stream), and moves the point's
    /// `irradiance` (per channel) by what changed.
    void resample(const Visibility& visibility, const Vec3& x, const Vec3& n, double sigma,
                  int max_rays, std::uint64_t seed, std::uint64_t key, Rgb& irradiance,
                  std::uint64_t& rays) const;

private:
    std::vector<SampledView> views_;
};

}  // namespace radiant
