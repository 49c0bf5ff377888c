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

/// emitter_faces_surface for each emitting surface whose light mostly meets a surface as
/// above, probed by up to 64 cosine-distributed rays from points of its front. Counts the
/// rays cast into `rays`.
void check_emitter_placement(const CheckedScene& input, std::vector<Warning>& out,
                             std::uint64_t& rays);

}  // namespace radiant
