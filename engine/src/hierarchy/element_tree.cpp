#include "hierarchy/element_tree.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "formfactor/luminaire_light.h"
#include "formfactor/point_polygon.h"
#include "formfactor/quadrature.h"
#include "formfactor/receiver_rule.h"
#include "geometry/median_split.h"
#include "geometry/random.h"
#include "parallel/fork_join.h"
#include "parallel/per_thread.h"
#include "solution/surface_summary.h"

namespace radiant {
namespace {

// Receiver points of a cluster: enough to see whether light varies over it.
constexpr int kClusterSamples = 8;
// Deeper quadtrees than this only chase rounding.
constexpr int kMaxDepth = 14;
// The estimates add emitting root patches' direct light (unoccluded) only up to this many of
// them: it costs that many factors per element.
constexpr std::size_t kMaxEstimateEmitters = 64;

}  // namespace

double sample_kernel(const Vec3& x, const Vec3& n, const SamplePoint& y) {
    const Vec3 d = y.position - x;
    const double r2 = length_squared(d);
    if (!(r2 > 0)) return 0;
    const double r = std::sqrt(r2);
    const double cos_x = dot(n, d) / r, cos_y = -dot(y.normal, d) / r;
    if (cos_x <= 0 || cos_y <= 0) return 0;
    return y.weight * cos_x * cos_y / (std::numbers::pi * r2 + y.weight);
}

ElementTree::ElementTree(const PreparedScene& scene, const PatchMesh& patches,
                         const Visibility& visibility, double min_edge_m, std::uint64_t seed)
    : scene_(scene),
      patches_(patches),
      visibility_(visibility),
      min_edge_m_(min_edge_m),
      seed_(seed) {
    elements_.reserve(4 * patches.size() + 16);
    std::vector<int> roots;
    for (std::size_t i = 0; i < patches.size(); ++i) {
        const PatchGeometry& p = patches.patch(i);
        if (p.hidden) continue;
        roots.push_back(add_surface(p.vertices, p.normal, static_cast<int>(i), -1, 0));
    }
    if (roots.empty()) return;
    for (const int r : roots) {
        if (elements_[static_cast<std::size_t>(r)].emits) emitters_.push_back(r);
    }
    if (emitters_.size() > kMaxEstimateEmitters) emitters_.clear();
    top_ = build_clusters(roots, 0, roots.size());
}

int ElementTree::add_surface(std::vector<Vec3> polygon, const Vec3& normal, int patch, int parent,
                             int depth) {
    const PatchGeometry& p = patches_.patch(static_cast<std::size_t>(patch));
    const PreparedMaterial& m = scene_.materials[static_cast<std::size_t>(p.material)];
    Element e;
    e.polygon = std::move(polygon);
    e.normal = normal;
    e.area_m2 = polygon_area(e.polygon);
    e.patch = patch;
    e.parent = parent;
    e.depth = depth;
    e.reflectance = m.reflectance;
    if (!p.back_side) e.exitance = m.exitance_lm_m2;
    e.emits = !p.back_side && m.emits();
    for (const QuadraturePoint& q : polygon_quadrature(e.polygon, 2)) {
        e.samples.push_back({q.position, normal, q.weight});
    }
    fill_bounds(e);
    append(std::move(e));
    return static_cast<int>(elements_.size() - 1);
}

void ElementTree::fill_bounds(Element& e) const {
    e.lo = e.hi = e.polygon.empty() ? Vec3{} : e.polygon[0];
    for (const Vec3& v : e.polygon) {
        for (int a = 0; a < 3; ++a) {
            e.lo[a] = std::min(e.lo[a], v[a]);
            e.hi[a] = std::max(e.hi[a], v[a]);
        }
    }
    e.diameter_m = length(e.hi - e.lo);
}

// Median split along the longest axis of the centroids' bounds: O(k log k), balanced.
int ElementTree::build_clusters(std::vector<int>& items, std::size_t begin, std::size_t end) {
    if (end - begin == 1) return items[begin];
    Vec3 lo = elements_[static_cast<std::size_t>(items[begin])].lo, hi = lo;
    for (std::size_t i = begin; i < end; ++i) {
        const Element& e = elements_[static_cast<std::size_t>(items[i])];
        const Vec3 c = (e.lo + e.hi) * 0.5;
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], c[a]);
            hi[a] = std::max(hi[a], c[a]);
        }
    }
    const std::size_t mid = split_at_median(items, begin, end, hi - lo, [&](int i) {
        const Element& e = elements_[static_cast<std::size_t>(i)];
        return (e.lo + e.hi) * 0.5;
    });
    const int left = build_clusters(items, begin, mid);
    const int right = build_clusters(items, mid, end);

    Element c;
    c.cluster = true;
    c.children = {left, right};
    const std::size_t index = elements_.size();
    std::vector<int> contents;
    for (std::size_t i = begin; i < end; ++i) contents.push_back(items[i]);
    const Element& a = elements_[static_cast<std::size_t>(left)];
    const Element& b = elements_[static_cast<std::size_t>(right)];
    for (int k = 0; k < 3; ++k) {
        c.lo[k] = std::min(a.lo[k], b.lo[k]);
        c.hi[k] = std::max(a.hi[k], b.hi[k]);
        c.reflectance[k] = std::max(a.reflectance[k], b.reflectance[k]);
    }
    c.diameter_m = length(c.hi - c.lo);
    c.area_m2 = a.area_m2 + b.area_m2;
    c.emits = a.emits || b.emits;
    // Receiver points spread over the contents by area, stratified.
    std::vector<double> cdf;
    double total = 0;
    for (const int r : contents)
        cdf.push_back(total += elements_[static_cast<std::size_t>(r)].area_m2);
    SampleStream rng(seed_, 0x636c7573ull, index);
    for (int s = 0; s < kClusterSamples; ++s) {
        const double pick = (s + rng.next()) / kClusterSamples * total;
        const auto at = std::min<std::size_t>(
            static_cast<std::size_t>(std::upper_bound(cdf.begin(), cdf.end(), pick) - cdf.begin()),
            contents.size() - 1);
        const Element& r = elements_[static_cast<std::size_t>(contents[at])];
        const double u[2] = {rng.next(), rng.next()};
        const Vec3 x = stratified_points(r.polygon, 1, u).front();
        c.samples.push_back({x, r.normal, total / kClusterSamples, contents[at]});
    }
    append(std::move(c));
    elements_[static_cast<std::size_t>(left)].parent = static_cast<int>(index);
    elements_[static_cast<std::size_t>(right)].parent = static_cast<int>(index);
    return static_cast<int>(index);
}

void ElementTree::append(Element&& e) {
    footprint_ += sizeof(Element) + e.polygon.capacity() * sizeof(Vec3) +
                  e.samples.capacity() * sizeof(SamplePoint) + e.children.capacity() * sizeof(int);
    elements_.push_back(std::move(e));
}

bool ElementTree::can_subdivide(int e) const {
    const Element& x = elements_[static_cast<std::size_t>(e)];
    return x.cluster ? !x.children.empty()
                     : (!x.children.empty() || (x.diameter_m > min_edge_m_ && x.depth < kMaxDepth));
}

void ElementTree::subdivide(int e) {
    if (!elements_[static_cast<std::size_t>(e)].children.empty()) return;
    const Element parent = elements_[static_cast<std::size_t>(e)];  // copy: push_back reallocates
    std::vector<int> children;
    for (auto& part : split_in_four(parent.polygon)) {
        const int c =
            add_surface(std::move(part), parent.normal, parent.patch, e, parent.depth + 1);
        Element& child = elements_[static_cast<std::size_t>(c)];
        child.radiosity = parent.radiosity;
        child.radiosity_max = parent.radiosity_max;
        child.radiosity_min = parent.radiosity_min;
        children.push_back(c);
    }
    footprint_ += children.capacity() * sizeof(int);
    elements_[static_cast<std::size_t>(e)].children = std::move(children);
}

void ElementTree::light_from_luminaires(Element& e, std::uint64_t& rays) const {
    e.luminaire_irradiance = {0, 0, 0};
    if (scene_.luminaires.empty() || e.cluster) return;
    std::vector<QuadraturePoint> points;
    for (const SamplePoint& s : e.samples) points.push_back({s.position, s.weight});
    e.luminaire_irradiance = luminaire_irradiance_on_polygon(
        scene_, visibility_, e.polygon, e.normal, e.area_m2, points,
        [](const PreparedLuminaire&) { return true; }, rays);
}

std::uint64_t ElementTree::light_from(std::size_t first) {
    PerThread<std::uint64_t> rays([] { return std::uint64_t{0}; });
    parallel_for(first, elements_.size(),
                 [&](std::size_t i) { light_from_luminaires(elements_[i], rays.local()); });
    return rays.combine(std::plus<>());
}

// Direct light from the emitting root patches at a point, unoccluded.
Rgb ElementTree::emitter_light_at(const Vec3& x, const Vec3& n, int patch) const {
    Rgb h{0, 0, 0};
    for (const int k : emitters_) {
        const Element& s = elements_[static_cast<std::size_t>(k)];
        if (s.patch == patch) continue;
        const double f = std::max(0.0, front_point_to_polygon_factor(x, n, s.polygon, s.normal));
        for (int c = 0; c < 3; ++c) h[c] += f * s.exitance[c];
    }
    return h;
}

// The estimate of a leaf: its emission plus the reflected luminaire light, emitters' direct
// light and the ambient guess. Its range over the leaf's points bounds how far the leaf's
// radiosity strays from its mean where the direct light falls off across it, which the linking
// oracle needs before the leaf is ever split (see link_refinement).
void ElementTree::estimate_from(std::size_t first, double ambient_irradiance, int channels) {
    parallel_for(first, elements_.size(), [&](std::size_t i) {
        Element& e = elements_[i];
        if (e.cluster) return;
        const bool lit = photometric(e.luminaire_irradiance, channels) > 0;
        auto radiosity = [&](const Rgb& direct) {
            Rgb b;
            for (int c = 0; c < 3; ++c)
                b[c] = e.exitance[c] + e.reflectance[c] * (direct[c] + ambient_irradiance);
            return b;
        };
        Rgb emitted{0, 0, 0};
        double lo = 1e300, hi = 0, weights = 0;
        for (const SamplePoint& x : e.samples) {
            const Rgb g = emitter_light_at(x.position, e.normal, e.patch);
            Rgb direct = g;
            if (lit) {
                const Rgb l = unoccluded_luminaire_irradiance_at(scene_, x.position, e.normal);
                for (int c = 0; c < 3; ++c) direct[c] += l[c];
            }
            const double b = photometric(radiosity(direct), channels);
            lo = std::min(lo, b);
            hi = std::max(hi, b);
            for (int c = 0; c < 3; ++c) emitted[c] += x.weight * g[c];
            weights += x.weight;
        }
        // The luminaires' light is the exact (and shadowed) area average.
        Rgb direct = e.luminaire_irradiance;
        for (int c = 0; c < 3; ++c) direct[c] += weights > 0 ? emitted[c] / weights : 0;
        e.radiosity = radiosity(direct);
        const double b = photometric(e.radiosity, channels);
        e.radiosity_max = std::max(b, weights > 0 ? hi : b);
        e.radiosity_min = std::min(b, weights > 0 ? lo : b);
    });
    if (first == 0 && top_ >= 0) pull(top_, channels, true);
}

void ElementTree::pull_up(int channels) {
    if (top_ >= 0) pull(top_, channels, false);
}

void ElementTree::pull(int e, int channels, bool keep_leaf_range) {
    Element& x = elements_[static_cast<std::size_t>(e)];
    if (x.children.empty()) {
        if (!keep_leaf_range)
            x.radiosity_max = x.radiosity_min = photometric(x.radiosity, channels);
        return;
    }
    Rgb sum{0, 0, 0};
    double area = 0, most = 0, least = 1e300;
    for (const int c : x.children) {
        pull(c, channels, keep_leaf_range);
        const Element& y = elements_[static_cast<std::size_t>(c)];
        for (int k = 0; k < 3; ++k) sum[k] += y.area_m2 * y.radiosity[k];
        area += y.area_m2;
        most = std::max(most, y.radiosity_max);
        least = std::min(least, y.radiosity_min);
    }
    Element& z = elements_[static_cast<std::size_t>(e)];
    for (int k = 0; k < 3; ++k) z.radiosity[k] = area > 0 ? sum[k] / area : 0;
    z.radiosity_max = most;
    z.radiosity_min = least;
}

std::size_t ElementTree::leaf_count() const {
    return static_cast<std::size_t>(std::count_if(elements_.begin(), elements_.end(),
                                                  [](const Element& e) { return e.leaf(); }));
}

}  // namespace radiant
