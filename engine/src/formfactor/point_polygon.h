// Exact point-to-polygon factors (Lambert's contour integral) and polygon solid angles.
#pragma once

#include <span>
#include <vector>

#include "radiant/vec3.h"

namespace radiant {

/// Form factor from a differential area at `x` with unit normal `n` to the planar polygon
/// `polygon` (any orientation, convex or not, ≥ 3 vertices), unoccluded. The polygon is first
/// clipped to the half-space n·(p − x) ≥ 0. Result in [0, 1]; 0 for degenerate input. Exact up
/// to rounding (Lambert 1760 / Nusselt; atan2 form for accuracy at small angles).
double point_to_polygon_factor(const Vec3& x, const Vec3& n, std::span<const Vec3> polygon);

/// point_to_polygon_factor for a one-sided emitter with unit normal `polygon_normal`: 0 for a
/// point behind its plane, even when part of the polygon is in front of the point.
double front_point_to_polygon_factor(const Vec3& x, const Vec3& n, std::span<const Vec3> polygon,
                                     const Vec3& polygon_normal);

/// Solid angle (sr) subtended by the planar polygon at `x` (Van Oosterom & Strackee 1983 over a
/// triangle fan). Always ≥ 0.
double polygon_solid_angle(const Vec3& x, std::span<const Vec3> polygon);

/// The part of `polygon` on the side n·(p − origin) ≥ 0 (Sutherland–Hodgman against one plane).
std::vector<Vec3> clip_to_halfspace(std::span<const Vec3> polygon, const Vec3& origin,
                                    const Vec3& n);

}  // namespace radiant
