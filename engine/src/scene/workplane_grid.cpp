// EN 12464-1 work-plane grids over named floors (expand_workplanes, declared in radiant/scene.h).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "radiant/scene.h"
#include "scene/floor_plan.h"

namespace radiant {
namespace {

// The wall zone EN 12464-1 leaves along the walls.
constexpr double kDefaultBorderM = 0.5;

struct Expansion {
    std::vector<Vec3> points;
    SensorGrid grid;
    std::string problem;  ///< empty when the grid is usable
};

Expansion expand(const Scene& scene, const Workplane& w, std::size_t max_points) {
    Expansion out;
    const double m = meters_per_unit(scene.units);
    const double height = w.height.value_or(kWorkplaneHeightM / m);
    const double border = w.border.value_or(kDefaultBorderM / m);
    auto planned = FloorPlan::of(scene, w.surfaces);
    if (auto* problem = std::get_if<std::string>(&planned)) {
        out.problem = std::move(*problem);
        return out;
    }
    const FloorPlan& plan = std::get<FloorPlan>(planned);
    const double a = plan.u1() - plan.u0() - 2 * border, b = plan.v1() - plan.v0() - 2 * border;
    if (!(a > 0 && b > 0)) {
        out.problem = "the border leaves no area on the floor";
        return out;
    }
    // EN 12464-1: p = 0.2·5^log10(d), d the longer side of the area in metres.
    const double spacing =
        w.spacing.value_or(0.2 * std::pow(5.0, std::log10(std::max(a, b) * m)) / m);
    const double cells_u = std::ceil(a / spacing - 1e-9), cells_v = std::ceil(b / spacing - 1e-9);
    if (cells_u * cells_v > static_cast<double>(max_points)) {
        out.problem = "the grid has " + std::to_string(cells_u * cells_v) +
                      " cells, over the limit of " + std::to_string(max_points) + " points";
        return out;
    }
    const int nu = static_cast<int>(cells_u), nv = static_cast<int>(cells_v);
    for (int iv = 0; iv < nv; ++iv) {
        for (int iu = 0; iu < nu; ++iu) {
            const double u = plan.u0() + border + (iu + 0.5) * a / nu;
            const double v = plan.v0() + border + (iv + 0.5) * b / nv;
            const std::optional<double> z = plan.height_at(u, v);
            if (!z || plan.near_outline(u, v, border)) continue;
            const Vec3 x = plan.point(u, v, *z + height);
            if (plan.in_furniture(x)) continue;
            out.points.push_back(x);
            out.grid.cells.push_back({iu, iv});
        }
    }
    if (out.points.empty()) {
        out.problem = "no grid point lies on the floor outside furniture";
        return out;
    }
    out.grid.nu = nu;
    out.grid.nv = nv;
    out.grid.spacing = spacing;
    out.grid.origin = plan.point(plan.u0() + border, plan.v0() + border, plan.z() + height);
    out.grid.u = plan.u_axis() * a;
    out.grid.v = plan.v_axis() * b;
    return out;
}

}  // namespace

std::vector<Problem> expand_workplanes(Scene& scene, const SceneLimits& limits) {
    std::vector<Problem> problems;
    std::size_t total = 0;
    for (const SensorSet& s : scene.sensors) total += s.workplane ? 0 : s.points.size();
    for (std::size_t i = 0; i < scene.sensors.size(); ++i) {
        SensorSet& s = scene.sensors[i];
        if (!s.workplane) continue;
        const std::size_t room =
            limits.max_sensor_points - std::min(total, limits.max_sensor_points);
        Expansion e = expand(scene, *s.workplane, room);
        if (!e.problem.empty()) {
            problems.push_back({"/sensors/" + std::to_string(i) + "/workplane", e.problem});
            continue;
        }
        total += e.points.size();
        e.grid.points = e.points;
        s.points = std::move(e.points);
        s.grid = std::move(e.grid);
    }
    return problems;
}

}  // namespace radiant
