// The radiosity methods' lighting-design results: one light component (monte_carlo_only_reason
// sends scenes with more to the Monte Carlo method), so maintained values are the solved ones
// times its factor; UGR observers read their background from the solved mesh.
#include <cmath>

#include "design/glare.h"
#include "design/lighting_assembly.h"
#include "geometry/cosine_direction.h"
#include "geometry/random.h"
#include "radiant/mesh_ray_caster.h"
#include "solver/pipeline.h"

namespace radiant {
namespace {

// Rays per eye: 64 × 64 strata of the cosine-weighted hemisphere about the line of sight.
constexpr int kEyeStrata = 64;
constexpr std::uint64_t kEyeStream = 0x6579652d6d657368ull;
// The rays' standard error counts this many times, like the Monte Carlo method's noise parts.
constexpr double kNoiseMargin = 1.5;

struct EyeLight {
    double indirect_lx = 0;  ///< E_ind = π · mean radiance seen
    double error_lx = 0;     ///< the rays' noise
};

/// The light the eye receives from the solved surfaces (the luminaires' own light is rated as
/// glare, apart): cosine rays about the line of sight, each reading the radiosity B of the front
/// side it hits (a back side reflects nothing); E_ind = mean B, as π · L with L = B/π.
EyeLight eye_light(const MeshRayCaster& caster, const SolvedMesh& mesh, const Vec3& eye,
                   const Vec3& view, std::uint64_t key, std::uint64_t& rays) {
    SampleStream rng(1, kEyeStream, key);
    double sum = 0, sum2 = 0;
    const int n = kEyeStrata * kEyeStrata;
    for (int k = 0; k < n; ++k) {
        const Vec3 d = cosine_direction(view, (k / kEyeStrata + rng.next()) / kEyeStrata,
                                        (k % kEyeStrata + rng.next()) / kEyeStrata);
        ++rays;
        const auto hit = caster.intersect(eye, d);
        if (!hit) continue;
        const auto& t = mesh.triangles[static_cast<std::size_t>(hit->triangle)];
        const Vec3 normal = cross(mesh.vertices[static_cast<std::size_t>(t[1])] -
                                      mesh.vertices[static_cast<std::size_t>(t[0])],
                                  mesh.vertices[static_cast<std::size_t>(t[2])] -
                                      mesh.vertices[static_cast<std::size_t>(t[0])]);
        if (dot(normal, d) >= 0) continue;
        const double b = mesh.triangle_radiosity[static_cast<std::size_t>(hit->triangle)];
        sum += b;
        sum2 += b * b;
    }
    const double mean = sum / n;
    const double variance = std::max(0.0, sum2 / n - mean * mean) / (n - 1);
    return {mean, kNoiseMargin * std::sqrt(variance)};
}

}  // namespace

void Pipeline::finish_lighting(const PreparedSolve& prepared, Result& result) {
    const PreparedScene& scene = prepared.scene;
    const auto& components = scene.components.components;
    const double mf = components.size() == 1 ? components.front().maintenance_factor : 1.0;
    ComponentValues values;
    for (const SensorResult& set : result.sensors) {
        values.sets.push_back(set.illuminance);
        values.set_error_lx.push_back(result.stats.error_estimate * set.average);
    }
    std::unique_ptr<MeshRayCaster> caster;
    if (!scene.observers.empty() && final_mesh_)
        caster = std::make_unique<MeshRayCaster>(*final_mesh_);
    for (std::size_t k = 0; k < scene.observers.size(); ++k) {
        const PreparedObserver& o = scene.observers[k];
        const EyeLight eye = caster ? eye_light(*caster, *final_mesh_,
                                                o.position + scene.world_origin, o.view, k, rays_)
                                    : EyeLight{};
        values.eye_indirect_lx.push_back(eye.indirect_lx);
        values.eye_indirect_error_lx.push_back(eye.error_lx +
                                               result.stats.error_estimate * eye.indirect_lx);
        values.glare_sums.push_back(glare_sum(scene, o, *prepared.visibility, -1, rays_));
    }
    assemble_lighting(
        scene_, scene,
        std::vector<ComponentValues>(std::max<std::size_t>(components.size(), 1), values), result);
    result.stats.rays = rays_;
    if (mf == 1) return;
    for (SurfaceResult& s : result.surfaces) {
        s.average_irradiance *= mf;
        s.average_radiosity *= mf;
    }
    result.stats.emitted_flux_lm *= mf;
    result.stats.absorbed_flux_lm *= mf;
    const auto scaled = [mf](SolvedMesh mesh) {
        for (double& b : mesh.triangle_radiosity) b *= mf;
        for (double& b : mesh.vertex_radiosity) b *= mf;
        return mesh;
    };
    if (result.mesh) result.mesh = scaled(std::move(*result.mesh));
    if (final_mesh_) final_mesh_ = std::make_shared<const SolvedMesh>(scaled(*final_mesh_));
}

}  // namespace radiant
