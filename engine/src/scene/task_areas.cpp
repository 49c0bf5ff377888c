// Task areas (expand_task_areas, declared in radiant/scene.h): the immediate surrounding band
// of every sensor set with a requirement, and the standard UGR observers where none are given.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "design/requirements.h"
#include "radiant/scene.h"
#include "scene/floor_plan.h"

namespace radiant {
namespace {

// EN 12464-1: the immediate surrounding is a band at least 0.5 m wide around the task area.
constexpr double kBandM = 0.5;
// Seated observers' eyes are 1.2 m above the floor (CIE 117, EN 12464-1), at the middle of
// each wall; this far in from it, so that their rays start inside the room.
constexpr double kEyeHeightM = 1.2, kWallGapM = 0.01;
// A task area counts as horizontal when its sides rise less than this share of their length.
constexpr double kHorizontal = 1e-6;

struct Area {
    Vec3 origin, u, v;
};

/// (s, t) of x in origin + s·u + t·v, from the normal equations of the two sides.
std::pair<double, double> coordinates(const Area& a, const Vec3& x) {
    const Vec3 d = x - a.origin;
    const double uu = dot(a.u, a.u), uv = dot(a.u, a.v), vv = dot(a.v, a.v);
    const double du = dot(d, a.u), dv = dot(d, a.v);
    const double det = uu * vv - uv * uv;
    if (!(std::abs(det) > 0)) return {-1, -1};
    return {(du * vv - dv * uv) / det, (dv * uu - du * uv) / det};
}

/// The band's grid: cells of the rectangle grown by the band's width that lie outside the task
/// area (and, over a floor, on it and outside furniture). Spacing by EN 12464-1's formula on the
/// grown rectangle, at most the band's width, so that a row of points lies in it.
SensorGrid band_grid(const Area& task, double band, double meters_per_unit, const FloorPlan* plan,
                     double height) {
    const Vec3 eu = normalized(task.u), ev = normalized(task.v);
    SensorGrid grid;
    grid.origin = task.origin - eu * band - ev * band;
    grid.u = task.u + eu * (2 * band);
    grid.v = task.v + ev * (2 * band);
    const double longer = std::max(length(grid.u), length(grid.v));
    grid.spacing =
        std::min(0.2 * std::pow(5.0, std::log10(longer * meters_per_unit)) / meters_per_unit, band);
    grid.nu = static_cast<int>(std::ceil(length(grid.u) / grid.spacing - 1e-9));
    grid.nv = static_cast<int>(std::ceil(length(grid.v) / grid.spacing - 1e-9));
    for (int iv = 0; iv < grid.nv; ++iv) {
        for (int iu = 0; iu < grid.nu; ++iu) {
            Vec3 x =
                grid.origin + grid.u * ((iu + 0.5) / grid.nu) + grid.v * ((iv + 0.5) / grid.nv);
            const auto [s, t] = coordinates(task, x);
            if (s > 0 && s < 1 && t > 0 && t < 1) continue;
            if (plan) {
                const double pu = dot(x, plan->u_axis()), pv = dot(x, plan->v_axis());
                const std::optional<double> z = plan->height_at(pu, pv);
                if (!z) continue;
                x = plan->point(pu, pv, *z + height);
                if (plan->in_furniture(x)) continue;
            }
            grid.points.push_back(x);
            grid.cells.push_back({iu, iv});
        }
    }
    return grid;
}

/// Four observers at the middle of the rectangle's sides, looking across it.
void add_standard_observers(Scene& scene, const std::string& task, const Vec3& origin,
                            const Vec3& u, const Vec3& v, double gap, double eye_z) {
    const Vec3 eu = normalized(u), ev = normalized(v);
    const struct {
        Vec3 at, view;
    } sides[] = {{origin + u * 0.5 + ev * gap, ev},
                 {origin + u * 0.5 + v - ev * gap, -ev},
                 {origin + v * 0.5 + eu * gap, eu},
                 {origin + v * 0.5 + u - eu * gap, -eu}};
    for (std::size_t k = 0; k < 4; ++k) {
        Observer o;
        o.name = task + " observer " + std::to_string(k + 1);
        o.position = Vec3{sides[k].at.x, sides[k].at.y, eye_z};
        o.view = sides[k].view;
        o.task = task;
        o.standard = true;
        scene.observers.push_back(std::move(o));
    }
}

}  // namespace

std::vector<Problem> expand_task_areas(Scene& scene, const SceneLimits& limits) {
    std::vector<Problem> problems;
    const double m = meters_per_unit(scene.units);
    std::size_t total = 0;
    for (const SensorSet& s : scene.sensors) total += s.points.size();
    const std::size_t sets = scene.sensors.size();
    for (std::size_t i = 0; i < sets; ++i) {
        const SensorSet task = scene.sensors[i];
        if (!task.requirement || task.surrounding_of) continue;
        const bool expanded =
            std::any_of(scene.sensors.begin(), scene.sensors.end(),
                        [&](const SensorSet& s) { return s.surrounding_of == i; });
        if (expanded) continue;
        const std::string pointer = "/sensors/" + std::to_string(i);
        if (!task.grid && !task.grid_area) continue;  // check_scene refuses it
        const Area area = task.grid
                              ? Area{task.grid->origin, task.grid->u, task.grid->v}
                              : Area{task.grid_area->origin, task.grid_area->u, task.grid_area->v};
        std::optional<FloorPlan> plan;
        double height = 0;
        if (task.workplane) {
            auto planned = FloorPlan::of(scene, task.workplane->surfaces);
            if (auto* floor = std::get_if<FloorPlan>(&planned)) plan = std::move(*floor);
            height = task.workplane->height.value_or(kWorkplaneHeightM / m);
        }
        const AppliedRequirement applied = apply_requirement(*task.requirement);

        SensorGrid grid = band_grid(area, kBandM / m, m, plan ? &*plan : nullptr, height);
        if (grid.points.size() >
            limits.max_sensor_points - std::min(total, limits.max_sensor_points)) {
            problems.push_back({pointer + "/requirement",
                                "the surrounding band's " + std::to_string(grid.points.size()) +
                                    " points take the scene over the limit of " +
                                    std::to_string(limits.max_sensor_points) + " sensor points"});
            continue;
        }
        if (!grid.points.empty()) {
            total += grid.points.size();
            const AppliedRequirement around = surrounding_requirement(applied);
            SensorSet band;
            band.name = task.name + " surrounding";
            band.normal = task.normal;
            band.points = grid.points;
            band.grid = std::move(grid);
            band.requirement =
                Requirement{std::nullopt, around.em_lx, around.u0, std::nullopt, std::nullopt};
            band.surrounding_of = i;
            scene.sensors.push_back(std::move(band));
        }

        if (!applied.ugr_l) continue;
        const bool observed =
            std::any_of(scene.observers.begin(), scene.observers.end(),
                        [&](const Observer& o) { return !o.task || *o.task == task.name; });
        if (observed) continue;
        if (plan) {
            // The walls: the floor's outline rectangle in its own frame.
            const Vec3 origin = plan->point(plan->u0(), plan->v0(), 0);
            add_standard_observers(scene, task.name, origin,
                                   plan->u_axis() * (plan->u1() - plan->u0()),
                                   plan->v_axis() * (plan->v1() - plan->v0()), kWallGapM / m,
                                   plan->z() + kEyeHeightM / m);
        } else if (std::abs(area.u.z) <= kHorizontal * length(area.u) &&
                   std::abs(area.v.z) <= kHorizontal * length(area.v)) {
            // A grid's floor is taken a desk's height below it.
            add_standard_observers(scene, task.name, area.origin, area.u, area.v, kWallGapM / m,
                                   area.origin.z + (kEyeHeightM - kWorkplaneHeightM) / m);
        } else {
            problems.push_back({pointer + "/requirement",
                                "the standard observers stand around a horizontal task area; "
                                "this grid is not horizontal: give observers"});
        }
    }
    return problems;
}

}  // namespace radiant
