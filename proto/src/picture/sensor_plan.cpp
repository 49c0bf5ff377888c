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
constexpr Rgb kPass{0, 130, 40}, kFail{200, 20, 20}, kUnknown{110, 110, 110};
constexpr Rgb kBandEdge{120, 120, 120};

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
    SensorPlan plan;
    plan.title = scene_name + " - " + set.name;
    plan.points = set.points;
    plan.normal = set.normal;
    plan.lux = set.illuminance;
    plan.max_lux = max_lux;
    return plan;
}

Image draw_sensor_plan(const SensorPlan& plan, int map_pixels) {
    if (plan.points.empty()) throw std::invalid_argument("the sensor set has no points");
    if (plan.points.size() != plan.lux.size() || plan.band_points.size() != plan.band_lux.size())
        throw std::invalid_argument("one illuminance value per sensor point is needed");
    const PlaneAxes axes = plane_axes(plan.normal);
    const auto flat = [&](const std::vector<Vec3>& points, std::vector<double>& u,
                          std::vector<double>& v) {
        for (const Vec3& p : points) {
            u.push_back(dot(p, axes.right));
            v.push_back(dot(p, axes.up));
        }
    };
    std::vector<double> u, v, band_u, band_v, eye_u, eye_v;
    flat(plan.points, u, v);
    flat(plan.band_points, band_u, band_v);
    flat(plan.observers, eye_u, eye_v);
    const double cell = typical_spacing(u, v);
    const double band_cell = band_u.empty() ? cell : typical_spacing(band_u, band_v);
    // The map spans the points, the band and the eyes, each cell whole.
    double u_lo = 1e300, u_hi = -1e300, v_lo = 1e300, v_hi = -1e300;
    const auto span = [&](const std::vector<double>& us, const std::vector<double>& vs,
                          double half) {
        for (std::size_t i = 0; i < us.size(); ++i) {
            u_lo = std::min(u_lo, us[i] - half), u_hi = std::max(u_hi, us[i] + half);
            v_lo = std::min(v_lo, vs[i] - half), v_hi = std::max(v_hi, vs[i] + half);
        }
    };
    span(u, v, 0.5 * cell);
    span(band_u, band_v, 0.5 * band_cell);
    span(eye_u, eye_v, 0.25 * cell);
    const double extent_u = u_hi - u_lo, extent_v = v_hi - v_lo;
    const double pixels_per_unit = map_pixels / std::max(extent_u, extent_v);
    const int map_w = std::max(1, static_cast<int>(std::lround(extent_u * pixels_per_unit)));
    const int map_h = std::max(1, static_cast<int>(std::lround(extent_v * pixels_per_unit)));

    const int scale = std::max(1, map_pixels / 300);
    const int margin = 10 * scale;
    const int line = 12 * scale;
    const int header = (2 + static_cast<int>(plan.verdicts.size())) * line;
    double largest = *std::max_element(plan.lux.begin(), plan.lux.end());
    for (const double e : plan.band_lux) largest = std::max(largest, e);
    const double max = plan.max_lux > 0 ? plan.max_lux : round_scale_max(largest);
    const double sum = std::accumulate(plan.lux.begin(), plan.lux.end(), 0.0);
    const auto [lux_lo, lux_hi] = std::minmax_element(plan.lux.begin(), plan.lux.end());
    const double average = sum / static_cast<double>(plan.lux.size());
    const auto ratio = [](double a, double b) { return b > 0 ? a / b : 0.0; };
    const std::string metrics = "Eavg " + short_number(average) + " lx   Emin " +
                                short_number(*lux_lo) + "   Emax " + short_number(*lux_hi) +
                                "   U0 " + short_number(ratio(*lux_lo, average)) + "   Ud " +
                                short_number(ratio(*lux_lo, *lux_hi));
    // Wide enough for the map and its legend, and for every line of text.
    int width = map_w + legend_width(max, scale) + 3 * margin;
    for (const std::string& text : {plan.title, metrics})
        width = std::max(width, text_width(text, scale) + 2 * margin);
    for (const PlanVerdict& verdict : plan.verdicts)
        width = std::max(width, text_width(verdict.text, scale) + 2 * margin);
    Image image(width, std::max(map_h, 150 * scale) + header + 2 * margin, kPaper);
    draw_text(image, margin, margin, plan.title, kInk, scale);
    draw_text(image, margin, margin + line, metrics, kInk, scale);
    for (std::size_t k = 0; k < plan.verdicts.size(); ++k) {
        const PlanVerdict& verdict = plan.verdicts[k];
        draw_text(image, margin, margin + static_cast<int>(k + 2) * line, verdict.text,
                  verdict.mark == PlanVerdict::Mark::pass   ? kPass
                  : verdict.mark == PlanVerdict::Mark::fail ? kFail
                                                            : kUnknown,
                  scale);
    }

    const int top = margin + header;
    // Image rows grow downwards; the plane's `up` axis points up on the page.
    const auto px = [&](double pu) {
        return margin + static_cast<int>(std::lround((pu - u_lo) * pixels_per_unit));
    };
    const auto py = [&](double pv) {
        return top + static_cast<int>(std::lround((v_hi - pv) * pixels_per_unit));
    };
    const auto cells = [&](const std::vector<double>& us, const std::vector<double>& vs,
                           const std::vector<double>& lux, double pitch, bool band) {
        // Cells of many points at one place would overlap: their area together stays within a
        // few maps, so that drawing costs O(pixels), whatever the points.
        const double most_half =
            0.5 * map_pixels * std::sqrt(kMostMapsFilled / static_cast<double>(us.size()));
        const int half = std::max(
            1, static_cast<int>(std::lround(std::min(0.5 * pitch * pixels_per_unit, most_half))));
        for (std::size_t i = 0; i < us.size(); ++i) {
            const int cx = px(us[i]), cy = py(vs[i]);
            const Rgb colour = false_colour(lux[i], max);
            image.fill(cx - half, cy - half, cx + half, cy + half, colour);
            if (band) {
                // Hatched: the band is the task's surrounding, not the task.
                const int period = std::max(4, 3 * scale);
                for (int y = std::max(0, cy - half); y < std::min(image.height(), cy + half); ++y) {
                    for (int x = std::max(0, cx - half); x < std::min(image.width(), cx + half);
                         ++x) {
                        if ((x + y) % period == 0) image.set(x, y, kPaper);
                    }
                }
                image.outline(cx - half, cy - half, cx + half, cy + half, kBandEdge);
            }
            const std::string label = short_number(lux[i]);
            if (text_width(label, scale) + 4 * scale <= 2 * half && 10 * scale <= 2 * half) {
                draw_text(image, cx - text_width(label, scale) / 2, cy - 3 * scale, label,
                          dark(colour) && !band ? kPaper : kInk, scale);
            }
        }
    };
    cells(u, v, plan.lux, cell, false);
    cells(band_u, band_v, plan.band_lux, band_cell, true);
    if (plan.task_area) {
        // The task area's outline, two pixels per scale step wide.
        const auto& [origin, su, sv] = *plan.task_area;
        const Vec3 corners[] = {origin, origin + su, origin + su + sv, origin + sv};
        for (int k = 0; k < 4; ++k) {
            const Vec3& a = corners[k];
            const Vec3& b = corners[(k + 1) % 4];
            const int steps = 4 * map_pixels;
            for (int t = 0; t <= steps; ++t) {
                const Vec3 p = a + (b - a) * (static_cast<double>(t) / steps);
                const int x = px(dot(p, axes.right)), y = py(dot(p, axes.up));
                image.fill(x - scale, y - scale, x + scale + 1, y + scale + 1, kInk);
            }
        }
    }
    for (std::size_t i = 0; i < eye_u.size(); ++i) {
        const int x = px(eye_u[i]), y = py(eye_v[i]), r = 4 * scale;
        image.outline(x - r, y - r, x + r, y + r, kInk);
        image.fill(x - scale, y - scale, x + scale, y + scale, kInk);
    }
    draw_legend(image, margin + map_w + 2 * margin, top, image.height() - top - margin, max, "lux",
                scale);
    return image;
}

}  // namespace radiant::picture
