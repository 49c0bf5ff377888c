// Direct light from point luminaires: exact (intensity · cos / d², one shadow ray per point),
// shared by the patch transport, the hierarchical solver and the sensors.
#pragma once

#include <cstdint>
#include <span>

#include "scene/prepared_scene.h"
#include "visibility/visibility.h"

namespace radiant {

/// Luminous intensity (cd per lm of the luminaire's flux) toward the unit direction `u`.
double intensity_per_lm(const PreparedLuminaire& luminaire, const Vec3& u);

/// Fraction of the luminaire's flux that falls on a polygon, unoccluded (exact).
double flux_fraction_on(const PreparedLuminaire& luminaire, std::span<const Vec3> polygon);

/// Irradiance (lux, per channel) from every luminaire at point x with unit normal n, with one
/// shadow ray per luminaire in front of x. Counts rays into `rays`.
Rgb luminaire_irradiance_at(const PreparedScene& scene, const Visibility& visibility, const Vec3& x,
                            const Vec3& n, std::uint64_t& rays);

}  // namespace radiant
