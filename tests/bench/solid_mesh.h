// Building blocks of the generated furniture, appended to a MeshGeometry as triangles: closed
// solids whose faces point out (boxes, slanted boxes, prisms and cones — legs, columns, pots) and
// open leaves for two-sided materials. Every vertex is snapped to a 0.1 mm grid, so a scene
// written as JSON is short and reads back to exactly the same numbers.
#pragma once

#include "radiant/scene.h"

namespace radiant::bench {

/// `p` rounded to the 0.1 mm grid of the generated scenes (metres).
Vec3 snapped(Vec3 p);

/// The closed parallelepiped origin + [0,1]·a + [0,1]·b + [0,1]·c: 8 vertices, 12 triangles
/// facing out whatever the handedness of a, b, c.
void add_parallelepiped(MeshGeometry& mesh, Vec3 origin, Vec3 a, Vec3 b, Vec3 c);

/// The closed axis-aligned box [lo, hi], 12 triangles facing out.
void add_box(MeshGeometry& mesh, Vec3 lo, Vec3 hi);

/// A closed box `size` (length, width, height) standing on `base_centre` (the middle of its
/// bottom face), turned by `yaw_rad` about the vertical: its length runs along
/// (cos yaw, sin yaw, 0).
void add_turned_box(MeshGeometry& mesh, Vec3 base_centre, Vec3 size, double yaw_rad);

/// A closed frustum of a regular `sides`-gon (a prism when the radii are equal): radius
/// `base_radius` around `base`, `top_radius` around base + axis. 2·sides vertices and
/// 4·sides − 4 triangles, facing out. `phase_rad` turns the polygon about the axis.
void add_frustum(MeshGeometry& mesh, Vec3 base, Vec3 axis, double base_radius, double top_radius,
                 int sides, double phase_rad = 0);

/// Triangles add_frustum makes for `sides`.
constexpr int frustum_triangles(int sides) { return 4 * sides - 4; }

/// A leaf: a midrib from `base` along `direction` that droops under its own weight, a blade
/// widest in the middle, folded along the midrib. Open, so its material must be two-sided.
struct LeafShape {
    Vec3 base;
    Vec3 direction{1, 0, 0};  ///< where the leaf points at its base; need not be unit
    double length_m = 0.15;
    double width_m = 0.06;
    double droop = 0.3;     ///< how far the tip falls below the straight midrib, × length
    double fold_rad = 0.3;  ///< each half-blade lifted by this angle about the midrib
    double roll_rad = 0;    ///< the blade turned about its midrib
    int segments = 4;       ///< along the midrib, ≥ 2
};

/// Appends `leaf`: 3·segments − 1 vertices and 4·segments − 4 triangles.
void add_leaf(MeshGeometry& mesh, const LeafShape& leaf);

/// Triangles add_leaf makes for `segments`.
constexpr int leaf_triangles(int segments) { return 4 * segments - 4; }

}  // namespace radiant::bench
