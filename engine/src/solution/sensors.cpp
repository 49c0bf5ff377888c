#include "solution/sensors.h"

#include <algorithm>

#include "parallel/fork_join.h"
#include "parallel/per_thread.h"
#include "solution/surface_summary.h"

namespace radiant {

void fill_sensor_statistics(SensorResult& r) {
    if (r.illuminance.empty()) return;
    const auto [lo, hi] = std::minmax_element(r.illuminance.begin(), r.illuminance.end());
    r.min = *lo;
    r.max = *hi;
    double sum = 0;
    for (const double e : r.illuminance) sum += e;
    r.average = sum / static_cast<double>(r.illuminance.size());
    r.uniformity = r.average > 0 ? r.min / r.average : 0;
    r.u0 = r.uniformity;
    r.ud = r.max > 0 ? r.min / r.max : 0;
}

SensorResult sensor_result_for(const PreparedSensorSet& set, const Vec3& world_origin) {
    SensorResult r;
    r.name = set.name;
    r.points.reserve(set.points.size());
    for (const Vec3& p : set.points) r.points.push_back(p + world_origin);
    r.normal = set.normal;
    r.grid = set.grid;
    r.illuminance.resize(set.points.size());
    return r;
}

std::vector<SensorResult> gather_sensors(const PreparedScene& scene, const Transport& transport,
                                         const std::array<std::vector<double>, 3>& radiosity,
                                         int channels, double noise_share, std::uint64_t& rays) {
    std::vector<SensorResult> results;
    PerThread<std::uint64_t> ray_count([] { return std::uint64_t{0}; });
    const std::size_t n = transport.patches().size();
    for (std::size_t s = 0; s < scene.sensors.size(); ++s) {
        const PreparedSensorSet& set = scene.sensors[s];
        SensorResult r = sensor_result_for(set, scene.world_origin);
        parallel_for(0, set.points.size(), [&](std::size_t k) {
            std::uint64_t& local_rays = ray_count.local();
            const Vec3& x = set.points[k];
            const std::uint64_t key = (static_cast<std::uint64_t>(s) << 40) ^ (k << 1) ^ 1u;
            Rgb e = transport.luminaire_irradiance_at(x, set.normal, key, local_rays);
            SampledViews views;
            for (std::size_t j = 0; j < n; ++j) {
                Rgb b{0, 0, 0};
                for (int c = 0; c < channels; ++c) b[c] = radiosity[static_cast<std::size_t>(c)][j];
                if (!(std::max({b[0], b[1], b[2]}) > 0)) continue;
                const PointView v = transport.point_view(x, set.normal, j, key, local_rays);
                Rgb light{0, 0, 0};
                for (int c = 0; c < channels; ++c) {
                    light[c] = v.factor * b[c];
                    e[c] += light[c] * v.fraction;
                }
                if (v.rays > 0) {
                    const PatchGeometry& p = transport.patches().patch(j);
                    views.add({p.vertices, p.centroid, p.normal, j, light,
                               photometric(light, channels), v.fraction, v.rays});
                }
            }
            transport.resample(views, x, set.normal, noise_share * photometric(e, channels), key, e,
                               local_rays);
            r.illuminance[k] = channels == 1 ? e[0] : luminance(e);
        });
        fill_sensor_statistics(r);
        results.push_back(std::move(r));
    }
    rays += ray_count.combine([](std::uint64_t a, std::uint64_t b) { return a + b; });
    return results;
}

}  // namespace radiant
