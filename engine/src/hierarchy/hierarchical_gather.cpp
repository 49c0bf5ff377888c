#include "hierarchy/hierarchical_gather.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "formfactor/luminaire_light.h"
#include "formfactor/point_polygon.h"
#include "formfactor/quadrature.h"
#include "formfactor/sampled_views.h"
#include "formfactor/shadow_rays.h"
#include "parallel/fork_join.h"
#include "parallel/per_thread.h"
#include "radiant/box.h"
#include "solution/sensors.h"
#include "solution/surface_summary.h"

namespace radiant {
namespace {

constexpr double kPi = std::numbers::pi;

class PointGather {
public:
    PointGather(const ElementTree& tree, const Visibility& visibility, const GatherCriteria& c,
                int channels)
        : tree_(tree), visibility_(visibility), criteria_(c), channels_(channels) {}

    /// `known`: the lux the point gets from elsewhere (luminaires), part of its noise budget.
    Rgb at(const Vec3& x, const Vec3& n, std::uint64_t key, double known,
           std::uint64_t& rays) const {
        Rgb h{0, 0, 0};
        SampledViews views;
        std::vector<int> stack{tree_.top()};
        while (!stack.empty()) {
            const int index = stack.back();
            stack.pop_back();
            const Element& e = tree_[static_cast<std::size_t>(index)];
            const Box box{e.lo, e.hi};
            if (behind(box, x, n)) continue;
            if (!e.cluster && dot(x - e.polygon[0], e.normal) <= 0) continue;
            double factor = 0;
            if (e.leaf()) {
                factor = leaf_factor(x, n, e, index, key, views, rays);
            } else {
                const double d = distance(box, Box{x, x});
                const double bound = d > 0 ? std::min(1.0, e.area_m2 / (kPi * d * d)) : 1.0;
                if (bound * e.radiosity_max > criteria_.irradiance_epsilon) {
                    for (const int c : e.children) stack.push_back(c);
                    continue;
                }
                factor = e.cluster ? cluster_factor(x, n, e, rays)
                                   : surface_view(x, n, e, index, key, rays).product();
            }
            for (int c = 0; c < channels_; ++c) h[c] += factor * e.radiosity[c];
        }
        const double sigma = criteria_.noise_share * (known + photometric(h, channels_));
        views.resample(visibility_, x, n, sigma, criteria_.max_rays_per_point, criteria_.seed, key,
                       h, rays);
        return h;
    }

private:
    struct View : PointView {
        Vec3 centre;  ///< of the polygon the rays were aimed at
    };

    View surface_view(const Vec3& x, const Vec3& n, const Element& e, int index, std::uint64_t key,
                      std::uint64_t& rays, bool emitter_rays = false) const {
        View v;
        v.factor = std::max(0.0, front_point_to_polygon_factor(x, n, e.polygon, e.normal));
        if (v.factor <= 0 || criteria_.unoccluded) return v;
        v.rays = emitter_rays ? criteria_.emitter_rays_per_point : criteria_.rays_per_point;
        v.centre = polygon_centroid(e.polygon);
        SampleStream rng(criteria_.seed, key, static_cast<std::uint64_t>(index));
        v.fraction =
            visible_fraction(visibility_, x, n, e.polygon, v.centre, e.normal, v.rays, rng, rays);
        return v;
    }

    // A leaf's exact factor; its sampled view is kept, to be sampled again if need be.
    double leaf_factor(const Vec3& x, const Vec3& n, const Element& e, int index, std::uint64_t key,
                       SampledViews& views, std::uint64_t& rays) const {
        const View v = surface_view(x, n, e, index, key, rays, e.emits);
        if (v.rays > 0) {
            Rgb light{0, 0, 0};
            for (int c = 0; c < channels_; ++c) light[c] = v.factor * e.radiosity[c];
            views.add({e.polygon, v.centre, e.normal, static_cast<std::uint64_t>(index), light,
                       photometric(light, channels_), v.fraction, v.rays});
        }
        return v.product();
    }

    double cluster_factor(const Vec3& x, const Vec3& n, const Element& e,
                          std::uint64_t& rays) const {
        double g = 0;
        const double eps = visibility_.epsilon();
        for (const SamplePoint& y : e.samples) {
            const double k = sample_kernel(x, n, y);
            if (k <= 0) continue;
            if (!criteria_.unoccluded) {
                ++rays;
                if (!visibility_.visible(x + n * eps, y.position + y.normal * eps)) continue;
            }
            g += k;
        }
        return g;
    }

    const ElementTree& tree_;
    const Visibility& visibility_;
    const GatherCriteria& criteria_;
    int channels_;
};

}  // namespace

std::vector<SensorResult> gather_sensors_from_tree(const PreparedScene& scene,
                                                   const ElementTree& tree,
                                                   const Visibility& visibility,
                                                   const GatherCriteria& criteria, int channels,
                                                   std::uint64_t& rays) {
    const PointGather gather(tree, visibility, criteria, channels);
    std::vector<SensorResult> out;
    PerThread<std::uint64_t> ray_count([] { return std::uint64_t{0}; });
    for (std::size_t s = 0; s < scene.sensors.size(); ++s) {
        const PreparedSensorSet& set = scene.sensors[s];
        SensorResult r = sensor_result_for(set, scene.world_origin);
        parallel_for(0, set.points.size(), [&](std::size_t i) {
            std::uint64_t& local = ray_count.local();
            const Vec3& x = set.points[i];
            Rgb h = criteria.with_luminaires
                        ? luminaire_irradiance_at(scene, visibility, x, set.normal, local)
                        : Rgb{0, 0, 0};
            if (tree.top() >= 0) {
                const Rgb g =
                    gather.at(x, set.normal, (s << 40) ^ i, photometric(h, channels), local);
                for (int c = 0; c < 3; ++c) h[c] += g[c];
            }
            r.illuminance[i] = channels == 1 ? h[0] : luminance(h);
        });
        fill_sensor_statistics(r);
        out.push_back(std::move(r));
    }
    rays += ray_count.combine([](std::uint64_t a, std::uint64_t b) { return a + b; });
    return out;
}

}  // namespace radiant
