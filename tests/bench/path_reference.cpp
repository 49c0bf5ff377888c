#include "path_reference.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "geometry/cosine_direction.h"
#include "geometry/random.h"
#include "montecarlo/channel_product.h"
#include "montecarlo/element_mesh.h"
#include "montecarlo/light_sources.h"
#include "parallel/fork_join.h"
#include "reference_csv_file.h"
#include "scene/prepared_scene.h"
#include "solution/surface_summary.h"
#include "visibility/visibility.h"

namespace radiant::bench {
namespace {

constexpr std::uint64_t kPathStream = 0x70617468ull;
// Every bounce is followed for this many bounces; beyond them a path goes on with the
// probability of its surface's largest reflectance and is weighed up by it (Russian roulette:
// no bias, and no path ends early in a furnace-like cove).
constexpr int kSureBounces = 2;
// Paths end after this many bounces: what they would add beyond is ρ^10000 of the light,
// 4.5·10⁻⁵ of it at ρ 0.999.
constexpr int kMaxBounces = 10000;
// The first round's paths per point; each round doubles them.
constexpr long kFirstPaths = 1024;

std::string percent(double share) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g %%", 100 * share);
    return buf;
}

struct PointTally {
    double sum = 0, squares = 0;
    long paths = 0;
    double mean() const { return paths > 0 ? sum / static_cast<double>(paths) : 0.0; }
    /// Of the mean.
    double variance() const {
        if (paths < 2) return 0;
        const auto n = static_cast<double>(paths);
        return std::max(0.0, squares / n - mean() * mean()) / (n - 1);
    }
};

// The geometry and light as the tracer reads them: elements as large as the pieces allow (the
// mesh is only the ray tracer's triangles and each landing's side and reflectance).
class PathTracer {
public:
    explicit PathTracer(const PreparedScene& scene)
        : scene_(scene),
          mesh_(scene, {.max_edge_m = scene.diagonal_m + 1}),
          visibility_(make_embree_visibility(mesh_.triangles())),
          sources_(scene, visibility_->epsilon()),
          ray_length_(4 * scene.diagonal_m + 1) {}

    /// One path's irradiance at x with unit normal n (lux): the direct light there, plus at
    /// every landing of a cosine-distributed walk the light it reflects, through the
    /// reflectances before it.
    double path(const Vec3& x0, const Vec3& n0, SampleStream& rng) const {
        std::uint64_t rays = 0;
        Rgb total = sources_.direct_at(x0, n0, *visibility_, rng, rays);
        Rgb through{1, 1, 1};
        Vec3 x = x0, n = n0;
        const double eps = visibility_->epsilon();
        for (int bounce = 0; bounce < kMaxBounces; ++bounce) {
            const Vec3 from = x + n * eps;
            const Vec3 d = cosine_direction(n, rng.next(), rng.next());
            const RayHit hit = visibility_->intersect(from, d, ray_length_);
            const int side = hit.triangle < 0 ? -1 : mesh_.side_hit(hit.triangle, d);
            if (side < 0) break;
            const MeshElement& e = mesh_[static_cast<std::size_t>(hit.triangle)];
            Rgb rho = scene_.materials[static_cast<std::size_t>(e.material)].reflectance;
            if (bounce >= kSureBounces) {
                const double survive = std::min(1.0, std::max({rho[0], rho[1], rho[2]}));
                if (!(rng.next() < survive)) break;
                for (double& c : rho) c /= survive;
            }
            through = times(through, rho);
            x = from + d * hit.t;
            n = mesh_.side_normal(side);
            const Rgb direct = sources_.direct_at(x, n, *visibility_, rng, rays);
            for (int c = 0; c < 3; ++c) total[c] += through[c] * direct[c];
        }
        return photometric(total, scene_.channels);
    }

private:
    const PreparedScene& scene_;
    ElementMesh mesh_;
    std::unique_ptr<Visibility> visibility_;
    LightSources sources_;
    double ray_length_;
};

}  // namespace

bool write_path_reference(const Scene& scene, const std::filesystem::path& csv,
                          const PathReferenceOptions& options, std::ostream& out,
                          std::ostream& log) {
    const PreparedScene prepared = prepare_scene(scene);
    if (prepared.sensors.empty()) {
        log << "radiant-bench: " << scene.name << " has no sensor set to trace\n";
        return false;
    }
    const PreparedSensorSet& set = prepared.sensors.front();
    if (set.points.empty()) {
        log << "radiant-bench: sensor set \"" << set.name << "\" has no points\n";
        return false;
    }
    if (set.kind != SensorKind::planar && set.kind != SensorKind::vertical) {
        log << "radiant-bench: sensor set \"" << set.name
            << "\" is cylindrical or semi-cylindrical; the path reference traces planar and "
               "vertical sets\n";
        return false;
    }
    const auto start = std::chrono::steady_clock::now();
    std::vector<PointTally> tally(set.points.size());
    double relative = std::numeric_limits<double>::infinity();
    run_with_threads(options.threads, [&] {
        const PathTracer tracer(prepared);
        for (long paths = kFirstPaths; relative > options.relative_error;) {
            parallel_for(0, tally.size(), [&](std::size_t i) {
                PointTally& t = tally[i];
                // Path k of point i draws the same numbers in every round: the rounds only add.
                for (long k = t.paths; k < paths; ++k) {
                    SampleStream rng(options.seed, kPathStream, i, static_cast<std::uint64_t>(k));
                    const double v = tracer.path(set.points[i], set.normal, rng);
                    t.sum += v;
                    t.squares += v * v;
                }
                t.paths = paths;
            });
            double mean = 0, variance = 0;
            for (const PointTally& t : tally) {
                mean += t.mean();
                variance += t.variance();
            }
            relative = mean > 0 ? std::sqrt(variance / static_cast<double>(tally.size())) /
                                      (mean / static_cast<double>(tally.size()))
                                : 0.0;
            out << "radiant-bench: " << paths << " paths per point: RMS standard error "
                << percent(relative) << " of the mean\n"
                << std::flush;  // a long trace shows its progress even into a file
            if (paths >= options.max_paths) break;
            paths = std::min(options.max_paths, 2 * paths);
        }
    });
    std::ofstream csv_out(csv);
    csv_out << testing::kReferenceCsvHeaderWithError << '\n';
    double overall = 0;
    for (std::size_t i = 0; i < tally.size(); ++i) {
        const Vec3 p = set.points[i] + prepared.world_origin;
        char buf[200];
        std::snprintf(buf, sizeof buf, "%.6f,%.6f,%.6f,%.6f,%.6f\n", p[0], p[1], p[2],
                      tally[i].mean(), std::sqrt(tally[i].variance()));
        csv_out << buf;
        overall += tally[i].mean() / static_cast<double>(tally.size());
    }
    if (!csv_out) {
        log << "radiant-bench: cannot write " << csv << '\n';
        return false;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char summary[200];
    std::snprintf(summary, sizeof summary,
                  " points, %ld paths each in %.1f s; standard error: RMS %s of the mean "
                  "illuminance (%.4g lx)\n",
                  tally.front().paths, seconds, percent(relative).c_str(), overall);
    out << "radiant-bench: wrote " << csv.string() << ": sensor set \"" << set.name << "\", "
        << tally.size() << summary;
    return true;
}

}  // namespace radiant::bench
