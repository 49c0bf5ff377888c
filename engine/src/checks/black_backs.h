// Light lost into the black backs of one-sided surfaces: a ceiling wound the wrong way, desks
// modelled as boxes that face in (rooms) instead of out (objects).
#pragma once

#include <vector>

#include "checks/light_paths.h"

namespace radiant {

/// Shares of the emitted light lost into one surface's black back above which it is named.
/// A modelled room loses next to nothing there: light meets the backs of surfaces only where
/// the model has a mistake, or a one-sided shortcut (a thin shelf) that could be two-sided.
inline constexpr double kLostShare = 0.05;
inline constexpr double kLostShareWhenMuchIsLost = 0.01;  ///< while all backs lose kMuchLost
inline constexpr double kMuchLost = 0.10;

/// box_faces_in for each box facing in that lies inside another room (a box facing in around
/// it) or loses light on its outside; back_face_light for every other surface that loses a
/// share of the light as above, the largest first.
/// The light of luminaires marked in `misplaced` and of emitting surfaces (engine index) marked
/// in `misplaced_emitters` is left out: their warnings explain it.
void check_black_backs(const CheckedScene& input, const LightPaths& paths,
                       const std::vector<bool>& misplaced,
                       const std::vector<bool>& misplaced_emitters, std::vector<Warning>& out);

}  // namespace radiant
