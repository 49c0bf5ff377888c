// Sensor points that measure nothing the author meant: outside the model (a grid larger than the
// room, a point in the wrong units) or inside a closed solid (a grid through the desks).
#pragma once

#include <cstdint>
#include <vector>

#include "checks/modelling_checks.h"

namespace radiant {

/// Up to one sensor_outside_model and one sensor_inside_solid warning per sensor set, each with
/// how many of its points are affected and the first of them. Sets with very many points are
/// checked at evenly spaced points. Counts the rays cast into `rays`. Returns which sets it
/// warned about.
std::vector<bool> check_sensor_placement(const CheckedScene& input, std::vector<Warning>& out,
                                         std::uint64_t& rays);

}  // namespace radiant
