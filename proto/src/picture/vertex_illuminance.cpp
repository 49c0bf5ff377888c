#include "radiant/picture/vertex_illuminance.h"

#include <map>
#include <string>

namespace radiant::picture {
namespace {

/// Below this radiosity (lm/m²) a surface is taken as black: its Ē/B̄ would be noise.
constexpr double kBlackRadiosity = 1e-9;

/// Per result surface: the factor Ē/B̄ from radiosity to illuminance, or 0 where the surface's
/// average illuminance is shown flat.
std::vector<double> illuminance_factors(const Result& result, const Scene& scene) {
    std::map<std::string, bool> material_emits;
    for (const Material& m : scene.materials) material_emits[m.name] = m.emission.has_value();
    std::map<std::string, bool> surface_emits;
    for (const Surface& s : scene.surfaces) surface_emits[s.name] = material_emits[s.material];
    std::vector<double> factor(result.surfaces.size(), 0);
    for (std::size_t s = 0; s < result.surfaces.size(); ++s) {
        const SurfaceResult& surface = result.surfaces[s];
        const auto emits = surface_emits.find(surface.name);
        // Unknown names (imported sub-surfaces) are treated as emitting: flat, never wrong.
        const bool flat = emits == surface_emits.end() || emits->second;
        if (!flat && surface.average_radiosity > kBlackRadiosity) {
            factor[s] = surface.average_irradiance / surface.average_radiosity;
        }
    }
    return factor;
}

}  // namespace

std::vector<double> vertex_illuminance(const Result& result, const Scene& scene) {
    const SolvedMesh& mesh = *result.mesh;
    const std::vector<double> factor = illuminance_factors(result, scene);
    std::vector<double> lux(mesh.vertices.size(), 0);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto s = static_cast<std::size_t>(mesh.triangle_surface[t]);
        for (const int v : mesh.triangles[t]) {
            const auto vi = static_cast<std::size_t>(v);
            // Vertices are never shared between surfaces, so each is written by one surface.
            lux[vi] = factor[s] > 0 ? factor[s] * mesh.vertex_radiosity[vi]
                                    : result.surfaces[s].average_irradiance;
        }
    }
    return lux;
}

}  // namespace radiant::picture
