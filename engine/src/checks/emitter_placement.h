// Emitting surfaces that face a surface right in front of them: a ceiling panel wound to face
// up, a centimetre under the ceiling, or an LED strip under a wall cabinet facing into it. Their
// light meets that surface at once and little of it gets out (an emitter's own front is usually
// black), so the room reads dark, and a solve spends long on what leaks from the gap.
#pragma once

#include <cstdint>
#include <vector>

#include "checks/modelling_checks.h"

namespace radiant {

/// A surface is named when at least kTrappedShare of its light first meets another surface
/// nearer than kNearGapShare of its size (the square root of its area): a flipped panel sends
/// almost all of it there; a lamp's bulb in its shade, or a cove light beside the wall it
/// washes, next to none. Light that meets the emitter itself (a glowing room, a furnace) is
/// what it encloses, not a mistake.
inline constexpr double kNearGapShare = 0.05;
inline constexpr double kTrappedShare = 0.5;

/// A surface is named when at least kBehindShare of its light first meets the black back of a
/// one-sided surface that is not the room, and none leaves the model: it lies inside a closed
/// object (a cove's LED strip sunk into its shelf) or behind a surface, where its light is lost.
inline constexpr double kBehindShare = 0.5;

/// emitter_behind_surface or emitter_faces_surface for each emitting surface whose light
/// mostly meets a black back or a surface near it as above, probed by up to 64
/// cosine-distributed rays from points of its front. Counts the rays cast into `rays`. Returns
/// the engine surfaces named emitter_behind_surface: their lost light is explained.
std::vector<bool> check_emitter_placement(const CheckedScene& input, std::vector<Warning>& out,
                                          std::uint64_t& rays);

}  // namespace radiant
