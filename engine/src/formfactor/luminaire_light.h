// Direct light from point luminaires: exact (intensity · cos / d², one shadow ray per point),
// shared by the patch transport, the hierarchical solver and the sensors.
#pragma once

#include <cstdint>
#include <functional>
#include <span>

#include "formfactor/quadrature.h"
#include "scene/prepared_scene.h"
#include "visibility/visibility.h"

namespace radiant {

/// Luminous intensity (cd per lm of the luminaire's flux) toward the unit direction `u`.
double intensity_per_lm(const PreparedLuminaire& luminaire, const Vec3& u);

/// Fraction of the luminaire's flux that falls on a convex polygon, unoccluded: exact for the
/// isotropic and lambertian distributions; for a photometric table, the intensity integrated over
/// the polygon's solid angle on spherical triangles of at most a few degrees.
double flux_fraction_on(const PreparedLuminaire& luminaire, std::span<const Vec3> polygon);

/// Direct irradiance at point x (unit normal n) per lumen of the luminaire's flux, unoccluded:
/// I(toward x)/lm · cos / d²; 0 where the luminaire is behind x or at it.
double direct_kernel_per_lm(const PreparedLuminaire& luminaire, const Vec3& x, const Vec3& n);

/// Irradiance (lux, per channel) from every luminaire at point x with unit normal n, unoccluded.
Rgb unoccluded_luminaire_irradiance_at(const PreparedScene& scene, const Vec3& x, const Vec3& n);

/// Irradiance (lux, per channel) from one luminaire at point x with unit normal n, with one
/// shadow ray when it is in front of x. Counts rays into `rays`.
Rgb luminaire_irradiance_from(const PreparedLuminaire& luminaire, const Visibility& visibility,
                              const Vec3& x, const Vec3& n, std::uint64_t& rays);

/// Irradiance (lux, per channel) from every luminaire at point x with unit normal n, with one
/// shadow ray per luminaire in front of x. Counts rays into `rays`.
Rgb luminaire_irradiance_at(const PreparedScene& scene, const Visibility& visibility, const Vec3& x,
                            const Vec3& n, std::uint64_t& rays);

/// Area-average irradiance (lux, per channel) on a convex polygon of area `area_m2` and unit
/// normal n from every luminaire in front of it: the flux falling on it (flux_fraction_on), times
/// the share of the direct kernel I·cos/d² over `points` that shadow rays find unoccluded. Rays
/// are cast only for luminaires that `maybe_blocked` does not clear. Counts rays into `rays`.
Rgb luminaire_irradiance_on_polygon(
    const PreparedScene& scene, const Visibility& visibility, std::span<const Vec3> polygon,
    const Vec3& n, double area_m2, std::span<const QuadraturePoint> points,
    const std::function<bool(const PreparedLuminaire&)>& maybe_blocked, std::uint64_t& rays);

}  // namespace radiant
