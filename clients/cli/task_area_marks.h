// What a plan shows of an EN 12464-1 task area: its outline, its surrounding band, the observers
// that rate its glare, and a line per requirement check, passed or failed.
#pragma once

#include <cstddef>

#include "radiant/picture/sensor_plan.h"
#include "radiant/result.h"
#include "radiant/scene.h"

namespace radiant::cli {

/// Adds the marks of sensor set `set` of `scene` (expanded, as solved) to `plan`, from `result`;
/// a set without a requirement gets none.
void add_task_area_marks(const Scene& scene, const Result& result, std::size_t set,
                         picture::SensorPlan& plan);

}  // namespace radiant::cli
