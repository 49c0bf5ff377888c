// Sensor sets that face away from all the light: a work plane given "normal": [0, 0, -1] reads
// what the floor reflects up, a small fraction of what was meant, and solves without a hint.
#pragma once

#include <cstdint>
#include <vector>

#include "checks/modelling_checks.h"

namespace radiant {

/// sensor_faces_away for each planar sensor set facing down with a normal of its own (not a
/// work plane, nor the band around a task area) whose points receive, unoccluded, under
/// kAwayShare of the direct light they would facing the other way, unless most of them lie on a
/// surface they measure (a ceiling's points facing down under downlights): nothing lies within
/// kMeasuredGap behind them. Sets in `skip` (already warned about) are left out. Counts the rays
/// cast into `rays`.
void check_sensor_facing(const CheckedScene& input, const std::vector<bool>& skip,
                         std::vector<Warning>& out, std::uint64_t& rays);

inline constexpr double kAwayShare = 0.02;
inline constexpr double kMeasuredGap = 0.25;  ///< metres

}  // namespace radiant
