// Per-surface averages and the energy balance, from the final elements of either solver path.
#pragma once

#include <vector>

#include "radiant/result.h"
#include "scene/prepared_scene.h"

namespace radiant {

/// One solved element (a patch or a hierarchy leaf) as the summaries need it.
struct SolvedElement {
    int surface = 0;
    int material = 0;
    double area_m2 = 0;
    bool back_side = false;
    bool hidden = false;  ///< under a coplanar overlay: no light, but its area counts
    Rgb irradiance{0, 0, 0};
    Rgb radiosity{0, 0, 0};
};

struct SurfaceSummary {
    std::vector<SurfaceResult> surfaces;
    double emitted_flux_lm = 0;   ///< emitting surfaces and luminaires
    double absorbed_flux_lm = 0;  ///< Σ A (1−ρ) H over every element
};

/// Photometric value of a per-channel quantity: the channel itself for gray scenes.
inline double photometric(const Rgb& value, int channels) {
    return channels == 1 ? value[0] : luminance(value);
}

SurfaceSummary summarise_surfaces(const PreparedScene& scene,
                                  const std::vector<SolvedElement>& elements, int channels);

}  // namespace radiant
