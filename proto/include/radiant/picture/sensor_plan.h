// A top-down false-colour map of one sensor set: every point as a cell coloured by its lux (with
// the number when the cell is large enough), the set's metrics, and a legend.
#pragma once

#include <string>
#include <vector>

#include "radiant/picture/image.h"
#include "radiant/result.h"
#include "radiant/vec3.h"

namespace radiant::picture {

struct SensorPlan {
    std::string title;
    std::vector<Vec3> points;  ///< any consistent length unit
    Vec3 normal{0, 0, 1};      ///< the map looks down this normal
    std::vector<double> lux;   ///< one per point
    double max_lux = 0;        ///< top of the scale; 0 = the largest value, rounded up
};

/// The plan of one sensor set of a result, titled "SCENE - SET".
SensorPlan sensor_plan_of(const std::string& scene_name, const SensorResult& set, double max_lux);

/// Throws std::invalid_argument when there are no points or lux and points differ in count.
Image draw_sensor_plan(const SensorPlan& plan, int map_pixels);

}  // namespace radiant::picture
