// A top-down false-colour map of one sensor set: every point as a cell coloured by its lux (with
// the number when the cell is large enough), the set's metrics, and a legend.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "radiant/picture/image.h"
#include "radiant/result.h"
#include "radiant/vec3.h"

namespace radiant::picture {

/// A line of an EN 12464-1 verdict under the title, coloured by how it went.
struct PlanVerdict {
    enum class Mark { pass, fail, unknown };
    std::string text;
    Mark mark = Mark::unknown;
};

struct SensorPlan {
    std::string title;
    std::vector<Vec3> points;  ///< any consistent length unit
    Vec3 normal{0, 0, 1};      ///< the map looks down this normal
    std::vector<double> lux;   ///< one per point
    double max_lux = 0;        ///< top of the scale; 0 = the largest value, rounded up
    /// A task area: its outline (corner, side, side), drawn over the cells.
    std::optional<std::array<Vec3, 3>> task_area;
    /// Its immediate surrounding band's points and lux, drawn on the same scale, hatched.
    std::vector<Vec3> band_points;
    std::vector<double> band_lux;
    /// Observers' eyes, drawn as rings.
    std::vector<Vec3> observers;
    std::vector<PlanVerdict> verdicts;
};

/// The plan of one sensor set of a result, titled "SCENE - SET" (no task area marks).
SensorPlan sensor_plan_of(const std::string& scene_name, const SensorResult& set, double max_lux);

/// Throws std::invalid_argument when there are no points or lux and points differ in count
/// (for the set or its band).
Image draw_sensor_plan(const SensorPlan& plan, int map_pixels);

}  // namespace radiant::picture
