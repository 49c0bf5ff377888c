// The radiosity methods' lighting-design results: one light component (monte_carlo_only_reason
// sends scenes with more to the Monte Carlo method), so maintained values are the solved ones
// times its factor.
#include "design/lighting_assembly.h"
#include "solver/pipeline.h"

namespace radiant {

void Pipeline::finish_lighting(const PreparedSolve& prepared, Result& result) {
    const PreparedScene& scene = prepared.scene;
    const auto& components = scene.components.components;
    const double mf = components.size() == 1 ? components.front().maintenance_factor : 1.0;
    ComponentValues values;
    for (const SensorResult& set : result.sensors) {
        values.sets.push_back(set.illuminance);
        values.set_error_lx.push_back(result.stats.error_estimate * set.average);
    }
    assemble_lighting(scene_, scene,
                      std::vector<ComponentValues>(std::max<std::size_t>(components.size(), 1),
                                                   values),
                      result);
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
