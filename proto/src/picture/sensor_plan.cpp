#include "radiant/picture/sensor_plan.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "picture/text.h"
#include "radiant/picture/false_colour.h"

namespace radiant::picture {
namespace {

constexpr Rgb kPaper{255, 255, 255};
constexpr Rgb kInk{20, 20, 20};

/// An in-plane basis seen from above the plane: `right` as close to +x as the plane allows.
struct PlaneAxes {
    Vec3 right, up;
};

PlaneAxes plane_axes(const Vec3& normal) {
    const Vec3 n = normalized(normal);
    Vec3 right = Vec3{1, 0, 0} - dot(Vec3{1, 0, 0}, n) * n;
    if (length(right) < 1e-6) right = Vec3{0, 1, 0} - dot(Vec3{0, 1, 0}, n) * n;
    right = normalized(right);
    return {right, cross(n, right)};
}

/// Points whose nearest neighbour typical_spacing measures: each search is O(points), so a
/// sample keeps a million-point work plane at a fraction of a second.
constexpr std::size_t kSpacingSamples = 256;
/// Cells may cover the map this many times over (a grid covers it once).
constexpr double kMostMapsFilled = 4;

/// The median distance from a point to its nearest neighbour (over an even sample of the
/// points): the cell pitch of a grid, and a sensible dot size for scattered points.
double typical_spacing(const std::vector<double>& u, const std::vector<double>& v) {
    std::vector<double> nearest;
    const std::size_t stride = std::max<std::size_t>(1, u.size() / kSpacingSamples);
    for (std::size_t i = 0; i < u.size(); i += stride) {
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < u.size(); ++j) {
            const double d = std::hypot(u[i] - u[j], v[i] - v[j]);
            if (j != i && d > 0) best = std::min(best, d);
        }
        if (std::isfinite(best)) nearest.push_back(best);
    }
    if (nearest.empty()) return 1;
    std::nth_element(nearest.begin(), nearest.begin() + static_cast<long>(nearest.size() / 2),
                     nearest.end());
    return nearest[nearest.size() / 2];
}

bool dark(Rgb c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b < 110; }

}  // namespace

SensorPlan sensor_plan_of(const std::string& scene_name, const SensorResult& set, double max_lux) {
    return {scene_name + " - " + set.name, set.points, set.normal, set.illuminance, max_lux};
}

Image draw_sensor_plan(const SensorPlan& plan, int map_pixels) {
    if (plan.points.empty()) throw std::invalid_argument("the sensor set has no points");
    if (plan.points.size() != plan.lux.size())
        throw std::invalid_argument("one illuminance value per sensor point is needed");
    const PlaneAxes axes = plane_axes(plan.normal);
    std::vector<double> u, v;
    for (const Vec3& p : plan.points) {
        u.push_back(dot(p, axes.right));
        v.push_back(dot(p, axes.up));
    }
    const double cell = typical_spacing(u, v);
    const auto [u_lo, u_hi] = std::minmax_element(u.begin(), u.end());
    const auto [v_lo, v_hi] = std::minmax_element(v.begin(), v.end());
    const double extent_u = *u_hi - *u_lo + cell;
    const double extent_v = *v_hi - *v_lo + cell;
    const double pixels_per_unit = map_pixels / std::max(extent_u, extent_v);
    const int map_w = std::max(1, static_cast<int>(std::lround(extent_u * pixels_per_unit)));
    const int map_h = std::max(1, static_cast<int>(std::lround(extent_v * pixels_per_unit)));

    const int scale = std::max(1, map_pixels / 300);
    const int margin = 10 * scale;
    const int header = 2 * 12 * scale;
    const double max = plan.max_lux > 0
                           ? plan.max_lux
                           : round_scale_max(*std::max_element(plan.lux.begin(), plan.lux.end()));
    Image image(map_w + legend_width(max, scale) + 3 * margin,
                std::max(map_h, 150 * scale) + header + 2 * margin, kPaper);

    const double sum = std::accumulate(plan.lux.begin(), plan.lux.end(), 0.0);
    const auto [lux_lo, lux_hi] = std::minmax_element(plan.lux.begin(), plan.lux.end());
    const double average = sum / static_cast<double>(plan.lux.size());
    const auto ratio = [](double a, double b) { return b > 0 ? a / b : 0.0; };
    draw_text(image, margin, margin, plan.title, kInk, scale);
    draw_text(image, margin, margin + 12 * scale,
              "Eavg " + short_number(average) + " lx   Emin " + short_number(*lux_lo) + "   Emax " +
                  short_number(*lux_hi) + "   U0 " + short_number(ratio(*lux_lo, average)) +
                  "   Ud " + short_number(ratio(*lux_lo, *lux_hi)),
              kInk, scale);

    const int top = margin + header;
    // Cells of many points at one place would overlap: their area together stays within a few
    // maps, so that drawing costs O(pixels), whatever the points.
    const double most_half_cell =
        0.5 * map_pixels * std::sqrt(kMostMapsFilled / static_cast<double>(plan.points.size()));
    const int half_cell = std::max(
        1, static_cast<int>(std::lround(std::min(0.5 * cell * pixels_per_unit, most_half_cell))));
    for (std::size_t i = 0; i < plan.points.size(); ++i) {
        const int cx =
            margin + static_cast<int>(std::lround((u[i] - *u_lo + 0.5 * cell) * pixels_per_unit));
        // Image rows grow downwards; the plane's `up` axis points up on the page.
        const int cy =
            top + static_cast<int>(std::lround((*v_hi - v[i] + 0.5 * cell) * pixels_per_unit));
        const Rgb colour = false_colour(plan.lux[i], max);
        image.fill(cx - half_cell, cy - half_cell, cx + half_cell, cy + half_cell, colour);
        const std::string label = short_number(plan.lux[i]);
        if (text_width(label, scale) + 4 * scale <= 2 * half_cell && 10 * scale <= 2 * half_cell) {
            draw_text(image, cx - text_width(label, scale) / 2, cy - 3 * scale, label,
                      dark(colour) ? kPaper : kInk, scale);
        }
    }
    draw_legend(image, margin + map_w + 2 * margin, top, image.height() - top - margin, max, "lux",
                scale);
    return image;
}

}  // namespace radiant::picture
