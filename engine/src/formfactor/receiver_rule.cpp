#include "formfactor/receiver_rule.h"

#include <algorithm>

#include "parallel/fork_join.h"

namespace radiant {
namespace {

// Points of a rule of `degree` with positive weights only (some triangle rules of degree 3 have
// a negative weight, which could make a form factor negative).
std::vector<QuadraturePoint> positive_rule(const std::vector<Vec3>& polygon, int degree) {
    for (int d = degree; d <= 5; ++d) {
        auto rule = polygon_quadrature(polygon, d);
        if (std::all_of(rule.begin(), rule.end(),
                        [](const QuadraturePoint& q) { return q.weight > 0; })) {
            return rule;
        }
    }
    return polygon_quadrature(polygon, 1);
}

// Patches sorted by centroid x, so that the neighbours that can matter to nearness() are found
// without visiting every patch (O(n²) for a scene of 100 000 patches).
struct SweepOrder {
    std::vector<std::size_t> order;
    std::vector<double> x;  // centroid x, in `order`
    double max_diameter = 0;

    explicit SweepOrder(const PatchMesh& patches) : order(patches.size()) {
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return patches.patch(a).centroid.x < patches.patch(b).centroid.x;
        });
        x.reserve(order.size());
        for (const std::size_t i : order) {
            x.push_back(patches.patch(i).centroid.x);
            max_diameter = std::max(max_diameter, patches.patch(i).diameter_m);
        }
    }
};

// The rule only distinguishes ratios below 0.5, below 1.5 and above: a neighbour further than
// this many diameters away cannot change it.
constexpr double kFarthestThatMatters = 2.0;

// Size of patch i over its distance to the nearest patch it exchanges light with at an angle.
// Neighbours within ~25° of coplanar (facets of a curved surface) see each other at grazing
// angles only, so they do not call for the fine rule the kernel singularity of a corner needs.
// Only neighbours that can be nearer than kFarthestThatMatters diameters are visited; when there
// is none the ratio is below 1 / kFarthestThatMatters either way.
double nearness(const PatchMesh& patches, const SweepOrder& sweep, std::size_t i) {
    const PatchGeometry& p = patches.patch(i);
    // d = |Δc| − q.diameter/2 ≥ |Δx| − max_diameter/2; a margin keeps rounding on the safe side.
    const double reach = (kFarthestThatMatters * p.diameter_m + 0.5 * sweep.max_diameter) * 1.001;
    const auto lo = std::lower_bound(sweep.x.begin(), sweep.x.end(), p.centroid.x - reach);
    const auto hi = std::upper_bound(sweep.x.begin(), sweep.x.end(), p.centroid.x + reach);
    double nearest = 1e300;
    for (auto it = lo; it != hi; ++it) {
        const std::size_t j = sweep.order[static_cast<std::size_t>(it - sweep.x.begin())];
        if (j == i) continue;
        const PatchGeometry& q = patches.patch(j);
        if (dot(q.normal, p.normal) > 0.9) continue;
        if (dot(q.centroid - p.centroid, p.normal) <= 1e-9 * p.diameter_m ||
            dot(p.centroid - q.centroid, q.normal) <= 1e-9 * p.diameter_m) {
            continue;
        }
        const double d = length(q.centroid - p.centroid) - 0.5 * q.diameter_m;
        nearest = std::min(nearest, std::max(d, 1e-300));
    }
    return p.diameter_m / nearest;
}

}  // namespace

std::vector<std::vector<Vec3>> split_in_four(const std::vector<Vec3>& v) {
    if (v.size() == 4) {
        const Vec3 c = (v[0] + v[1] + v[2] + v[3]) * 0.25;
        const Vec3 m01 = (v[0] + v[1]) * 0.5, m12 = (v[1] + v[2]) * 0.5;
        const Vec3 m23 = (v[2] + v[3]) * 0.5, m30 = (v[3] + v[0]) * 0.5;
        return {{v[0], m01, c, m30}, {m01, v[1], m12, c}, {c, m12, v[2], m23}, {m30, c, m23, v[3]}};
    }
    if (v.size() == 3) {
        const Vec3 a = (v[0] + v[1]) * 0.5, b = (v[1] + v[2]) * 0.5, c = (v[2] + v[0]) * 0.5;
        return {{v[0], a, c}, {a, v[1], b}, {c, b, v[2]}, {a, b, c}};
    }
    const Vec3 c = polygon_centroid(v);
    std::vector<std::vector<Vec3>> out;
    for (std::size_t i = 0; i < v.size(); ++i) out.push_back({c, v[i], v[(i + 1) % v.size()]});
    return out;
}

std::vector<std::vector<QuadraturePoint>> receiver_rules(const PatchMesh& patches) {
    std::vector<std::vector<QuadraturePoint>> rules(patches.size());
    const SweepOrder sweep(patches);
    parallel_for(0, patches.size(), [&](std::size_t i) {
        const auto& poly = patches.patch(i).vertices;
        const double ratio = nearness(patches, sweep, i);
        if (ratio < 0.5) {
            rules[i] = positive_rule(poly, 2);
        } else if (ratio < 1.5) {
            rules[i] = positive_rule(poly, 5);
        } else {
            for (const auto& part : split_in_four(poly)) {
                for (const auto& q : positive_rule(part, 5)) rules[i].push_back(q);
            }
        }
    });
    return rules;
}

}  // namespace radiant
