#include "checks/sensor_placement.h"

#include <algorithm>

#include "checks/side_hit.h"
#include "checks/warning_text.h"
#include "parallel/fork_join.h"

namespace radiant {
namespace {

// Points checked in all: six rays each, a few hundred thousand rays at most.
constexpr std::size_t kMaxCheckedPoints = 16384;
constexpr double kOutsideMargin = 1e-6;  ///< of the model's diagonal, as for luminaires
const Vec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

enum class Place { fine, outside, inside_solid };

// Along the six axes: a point that meets black backs and nothing that reflects is outside the
// model (looking at a room's outside); one that meets black backs all round is inside a solid,
// and so is one that meets them on four sides and nothing else (a desk's bottom and back lie on
// the floor and against a wall, whose fronts a ray may meet first). The rays start where the
// gather's do, lifted off the point along the sensor's normal: a point on a desk's top (a work
// plane at the desks' height) measures the room above it, although rays along the top meet the
// desk's sides there.
Place place_of(const CheckedScene& input, const Box& bounds, const Vec3& point, const Vec3& normal,
               std::uint64_t& rays) {
    if (distance_outside(bounds, point) > kOutsideMargin * input.prepared.diagonal_m)
        return Place::outside;
    const Vec3 x = point + normal * input.visibility.epsilon();
    int black = 0, lit = 0, escaped = 0;
    for (const Vec3& axis : kAxes) {
        ++rays;
        const SideHit hit = side_hit(input, x, axis);
        if (hit.black) {
            ++black;
        } else if (hit.escaped()) {
            ++escaped;
        } else {
            ++lit;
        }
    }
    if (black >= 4 && escaped == 0) return Place::inside_solid;
    return black > 0 && lit == 0 ? Place::outside : Place::fine;
}

}  // namespace

std::vector<bool> check_sensor_placement(const CheckedScene& input, std::vector<Warning>& out,
                                         std::uint64_t& rays) {
    const PreparedScene& prepared = input.prepared;
    std::size_t total = 0;
    for (const PreparedSensorSet& set : prepared.sensors) total += set.points.size();
    const std::size_t stride = stride_for(total, kMaxCheckedPoints);
    const Box bounds = model_bounds(prepared);
    std::vector<bool> warned(prepared.sensors.size(), false);
    for (std::size_t s = 0; s < prepared.sensors.size(); ++s) {
        const std::vector<Vec3>& points = prepared.sensors[s].points;
        const std::size_t checked = (points.size() + stride - 1) / stride;
        std::vector<Place> places(checked, Place::fine);
        std::vector<std::uint64_t> point_rays(checked, 0);
        parallel_for(0, checked, [&](std::size_t k) {
            places[k] = place_of(input, bounds, points[k * stride], prepared.sensors[s].normal,
                                 point_rays[k]);
        });
        for (const std::uint64_t r : point_rays) rays += r;
        const SensorSet& given = input.scene.sensors[s];
        const std::string pointer = "/sensors/" + std::to_string(s);
        for (const auto& [place, code, where] :
             {std::tuple{Place::outside, "sensor_outside_model", "outside the model"},
              std::tuple{Place::inside_solid, "sensor_inside_solid", "inside a closed solid"}}) {
            const auto first = std::find(places.begin(), places.end(), place);
            if (first == places.end()) continue;
            const auto count =
                static_cast<std::size_t>(std::count(places.begin(), places.end(), place));
            const std::size_t index = static_cast<std::size_t>(first - places.begin()) * stride;
            std::string message =
                "sensor set " + quoted(given.name) + ": " + std::to_string(count) + " of " +
                std::to_string(checked) + (stride > 1 ? " points checked" : " points") +
                (count == 1 ? " lies " : " lie ") + where + " (point " + std::to_string(index) +
                ", at " + point_text(given.points[index]) + ")";
            out.push_back({code, std::move(message), pointer});
            warned[s] = true;
        }
    }
    return warned;
}

}  // namespace radiant
