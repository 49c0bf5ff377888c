// Turning arbitrary planar polygons into convex pieces, and cutting convex pieces by planes.
#pragma once

#include <span>
#include <vector>

#include "radiant/vec3.h"

namespace radiant {

/// True when the planar polygon (normal `n`) is strictly convex up to collinear vertices.
bool is_convex(std::span<const Vec3> polygon, const Vec3& n);

/// Triangulates a simple planar polygon with normal `n` by ear clipping (orientation kept).
/// Non-planar input is triangulated in its projection; each triangle is planar by nature.
std::vector<std::vector<Vec3>> triangulate(std::span<const Vec3> polygon, const Vec3& n);

/// Convex pieces of a simple polygon: itself when convex and planar, else its triangles.
std::vector<std::vector<Vec3>> convex_pieces(std::span<const Vec3> polygon, const Vec3& n,
                                             double planarity_tolerance);

/// Splits a convex polygon by the plane {p : m·(p − o) = 0}. Returns the two sides (either may
/// be empty). Vertices within `eps` of the plane count as on it.
std::pair<std::vector<Vec3>, std::vector<Vec3>> split_by_plane(std::span<const Vec3> polygon,
                                                               const Vec3& o, const Vec3& m,
                                                               double eps);

/// Removes consecutive duplicate and collinear vertices (within `eps`).
std::vector<Vec3> simplify_polygon(std::span<const Vec3> polygon, double eps);

}  // namespace radiant
