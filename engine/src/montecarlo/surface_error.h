// How far a Monte Carlo answer's surface means may be from the truth: a scene without sensors
// states its error on its surfaces (result_difference.h), and the photon field's batches measure
// their noise. They have no discretisation part: photons reflect from where they land, so the
// light a surface receives does not depend on how it is cut into elements.
#pragma once

#include <vector>

#include "montecarlo/monte_carlo_error.h"
#include "montecarlo/photon_field.h"
#include "scene/prepared_scene.h"

namespace radiant {

/// One light component's photons, weighted by its maintenance factor; `component` −1 is every
/// source (a scene without groups).
struct WeightedField {
    const PhotonField* field = nullptr;
    double factor = 1;
    int component = -1;
};

/// The RMS, over the counted surfaces' mean irradiance and mean radiosity, of their noise
/// relative to themselves (or to a tenth of their kind's mean where darker), as the sum of the
/// fields' each weighted by its factor: per surface Σ factor × standard error over
/// Σ factor × mean, a bound for any correlation between the fields. In `photon_noise` and
/// `total`.
MonteCarloError surface_error(const PreparedScene& scene, const std::vector<WeightedField>& fields);

}  // namespace radiant
