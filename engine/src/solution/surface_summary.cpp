#include "solution/surface_summary.h"

namespace radiant {

SurfaceSummary summarise_surfaces(const PreparedScene& scene,
                                  const std::vector<SolvedElement>& elements, int channels) {
    SurfaceSummary out;
    const std::size_t count = scene.surface_names.size();
    std::vector<double> area(count, 0.0), sum_h(count, 0.0), sum_b(count, 0.0);
    for (const SolvedElement& e : elements) {
        const PreparedMaterial& m = scene.materials[static_cast<std::size_t>(e.material)];
        Rgb absorbed{0, 0, 0}, emitted{0, 0, 0};
        for (int c = 0; c < channels; ++c) {
            const auto ci = static_cast<std::size_t>(c);
            absorbed[ci] = e.area_m2 * (1 - m.reflectance[ci]) * e.irradiance[ci];
            emitted[ci] = e.back_side || e.hidden ? 0 : e.area_m2 * m.exitance_lm_m2[ci];
        }
        out.absorbed_flux_lm += photometric(absorbed, channels);
        out.emitted_flux_lm += photometric(emitted, channels);
        if (e.back_side) continue;
        const auto s = static_cast<std::size_t>(e.surface);
        area[s] += e.area_m2;
        sum_h[s] += e.area_m2 * photometric(e.irradiance, channels);
        sum_b[s] += e.area_m2 * photometric(e.radiosity, channels);
    }
    for (const PreparedLuminaire& l : scene.luminaires) {
        out.emitted_flux_lm += photometric(l.flux_lm, channels);
    }
    for (std::size_t s = 0; s < count; ++s) {
        SurfaceResult r;
        r.name = scene.surface_names[s];
        r.area_m2 = scene.surface_area_m2[s];
        r.average_irradiance = area[s] > 0 ? sum_h[s] / area[s] : 0;
        r.average_radiosity = area[s] > 0 ? sum_b[s] / area[s] : 0;
        out.surfaces.push_back(std::move(r));
    }
    return out;
}

}  // namespace radiant
