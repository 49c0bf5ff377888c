// The modelling-check stage: what a scene that solves may still get wrong (docs/warnings.md).
// Each check is cheap next to a solve: it reads the scene, or casts a few thousand rays through
// the ray tracer the solve builds anyway.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "radiant/box.h"
#include "radiant/warnings.h"
#include "scene/prepared_scene.h"
#include "visibility/visibility.h"

namespace radiant {

/// What every check may look at: the scene as given (names, units, boxes), as prepared (metres,
/// local frame, convex pieces), and a ray tracer over the prepared pieces.
struct CheckedScene {
    const Scene& scene;
    const PreparedScene& prepared;
    const Visibility& visibility;
    std::span<const Triangle> triangles;  ///< the ray tracer's triangles
    std::span<const int> triangle_piece;  ///< piece of each triangle
    std::uint64_t seed = 1;
};

/// The bounding box of every piece (local frame, metres).
Box model_bounds(const PreparedScene& prepared);

/// Whether a box of `size` (metres) holds half the volume of `model`: it is the model's room, not
/// an object in it (a room box faced the wrong way, not a desk).
bool is_room_sized(const Vec3& size, const Box& model);

/// How far `x` lies outside `box` (metres; 0 inside or on it).
double distance_outside(const Box& box, const Vec3& x);

/// The stride that takes at most `most` of `count` items, evenly spaced (at least 1).
std::size_t stride_for(std::size_t count, std::size_t most);

/// The photometric flux (lm) the scene emits: from luminaires, and from emitting surfaces.
struct EmittedLight {
    double luminaires_lm = 0;
    double surfaces_lm = 0;
    double total_lm() const { return luminaires_lm + surfaces_lm; }
};
EmittedLight emitted_light(const PreparedScene& prepared);
/// The emitted light spread evenly over every surface (lux; 0 without area).
double mean_surface_lux(const PreparedScene& prepared, const EmittedLight& emitted);
/// Under this mean the light fits no interior in any unit (units_suspect); between it and a
/// furnished room's least, a flux in the wrong unit is likelier (flux_suspect).
inline constexpr double kLeastPlausibleMeanLux = 0.01;

/// Every pre-solve check, in a fixed order. Counts the rays cast into `rays`. Deterministic in
/// the seed, whatever the number of threads.
std::vector<Warning> modelling_warnings(const CheckedScene& input, std::uint64_t& rays);

}  // namespace radiant
