#include "montecarlo/light_tree.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>

#include "geometry/median_split.h"

namespace radiant {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// A cluster that straddles x's horizon has its centre below it more often than not; some of it
// is above, so it keeps a little importance.
constexpr double kMinClusterCosine = 0.05;

// Whether no point of `b` lies strictly in front of the plane through x with normal n: the
// box's highest corner above the plane, from its centre and half extents (cheaper than eight).
bool below_horizon(const Box& b, const Vec3& x, const Vec3& n) {
    const Vec3 half = 0.5 * b.size();
    return dot(n, b.centre() - x) + std::abs(n.x) * half.x + std::abs(n.y) * half.y +
               std::abs(n.z) * half.z <=
           0;
}

double squared_distance(const Box& b, const Vec3& x) {
    double d2 = 0;
    for (int a = 0; a < 3; ++a) {
        const double d = std::max({b.lo[a] - x[a], 0.0, x[a] - b.hi[a]});
        d2 += d * d;
    }
    return d2;
}

// The axis of the cone of fronts of sources [begin, end) of `order`: their mean front, or zero
// where one may face any way or they cancel.
Vec3 front_cone_axis(const std::vector<std::size_t>& order, std::size_t begin, std::size_t end,
                     std::span<const LightTreeSource> sources) {
    Vec3 sum{0, 0, 0};
    for (std::size_t i = begin; i < end; ++i) {
        const Vec3& f = sources[order[i]].normal;
        if (length_squared(f) == 0) return {0, 0, 0};
        sum += f;
    }
    const double l = length(sum);
    return l > 1e-9 * static_cast<double>(end - begin) ? sum / l : Vec3{0, 0, 0};
}

// The cosine of the cone's half angle about `axis` that holds every front; −1 without an axis.
double front_cone_cosine(const std::vector<std::size_t>& order, std::size_t begin, std::size_t end,
                         std::span<const LightTreeSource> sources, const Vec3& axis) {
    if (length_squared(axis) == 0) return -1;
    double lowest = 1;
    for (std::size_t i = begin; i < end; ++i)
        lowest = std::min(lowest, dot(axis, sources[order[i]].normal));
    return lowest;
}

}  // namespace

LightTree::LightTree(std::span<const LightTreeSource> sources) {
    leaf_of_.assign(sources.size(), -1);
    if (sources.empty()) return;
    std::vector<std::size_t> order(sources.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    nodes_.reserve(2 * sources.size());
    build(order, 0, order.size(), sources, -1);
}

int LightTree::build(std::vector<std::size_t>& order, std::size_t begin, std::size_t end,
                     std::span<const LightTreeSource> sources, int parent) {
    const int index = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    Node node;
    node.parent = parent;
    Box centres;
    Vec3 weighted{0, 0, 0};
    for (std::size_t i = begin; i < end; ++i) {
        const LightTreeSource& s = sources[order[i]];
        node.bounds.add(s.bounds.lo);
        node.bounds.add(s.bounds.hi);
        centres.add(s.bounds.centre());
        weighted += s.bounds.centre() * s.power;
        node.power += s.power;
        node.peak_cd += s.peak_cd;
    }
    node.centre = node.power > 0 ? weighted / node.power : centres.centre();
    node.axis = front_cone_axis(order, begin, end, sources);
    node.cos_spread = front_cone_cosine(order, begin, end, sources, node.axis);
    node.sin_spread = std::sqrt(std::max(0.0, 1 - node.cos_spread * node.cos_spread));
    node.sphere_radius = 0.5 * length(node.bounds.size());
    if (end - begin == 1) {
        node.source = order[begin];
        leaf_of_[node.source] = index;
        nodes_[static_cast<std::size_t>(index)] = node;
        return index;
    }
    const std::size_t middle =
        split_at_median(order, begin, end, centres.size(),
                        [&](std::size_t i) { return sources[i].bounds.centre(); });
    node.left = build(order, begin, middle, sources, index);
    node.right = build(order, middle, end, sources, index);
    nodes_[static_cast<std::size_t>(index)] = node;
    return index;
}

double LightTree::facing(const Node& node, const Vec3& x) const {
    if (node.cos_spread <= -1) return 1;
    const Vec3 to_x = x - node.bounds.centre();
    const double d = length(to_x);
    const double r = node.sphere_radius;
    if (!(d > r)) return 1;
    // The least angle between any front and any direction from the node to x: the angle from
    // the axis to x, less the cone's half angle and the angle the bounds' sphere spans from x —
    // its cosine by the difference formulas, without an inverse trigonometric function.
    const double cos_axis = std::clamp(dot(node.axis, to_x) / d, -1.0, 1.0);
    if (cos_axis >= node.cos_spread) return 1;
    const double sin_axis = std::sqrt(1 - cos_axis * cos_axis);
    const double cos_beyond = cos_axis * node.cos_spread + sin_axis * node.sin_spread;
    const double sin_beyond = sin_axis * node.cos_spread - cos_axis * node.sin_spread;
    const double sin_seen = r / d, cos_seen = std::sqrt(1 - sin_seen * sin_seen);
    if (cos_beyond >= cos_seen) return 1;
    return std::max(0.0, cos_beyond * cos_seen + sin_beyond * sin_seen);
}

double LightTree::bound(const Node& node, const Vec3& x, const Vec3& n) const {
    if (below_horizon(node.bounds, x, n)) return 0;
    const double d2 = squared_distance(node.bounds, x);
    // A Lambertian front's intensity falls as the cosine from its peak.
    return d2 > 0 ? node.peak_cd * facing(node, x) / d2 : kInf;
}

double LightTree::cluster_importance(const Node& node, const Vec3& x, const Vec3& n) const {
    if (below_horizon(node.bounds, x, n)) return 0;
    const double front = facing(node, x);
    if (!(front > 0)) return 0;
    const Vec3 d = node.centre - x;
    const double d2 = length_squared(d);
    const double r2 = 0.25 * length_squared(node.bounds.size());
    const double cosine = d2 > r2 ? std::max(kMinClusterCosine, dot(n, d) / std::sqrt(d2)) : 1.0;
    return node.power * front * cosine / std::max(d2, r2);
}

LightCut LightTree::cut(const Vec3& x, const Vec3& n, double relative_bound, std::size_t max_nodes,
                        std::size_t max_seen_nodes, const std::function<bool(int)>& seen) const {
    LightCut cut;
    if (leaf_of_.size() <= max_nodes) {
        for (std::size_t s = 0; s < leaf_of_.size(); ++s) cut.sources.push_back(s);
        return cut;
    }
    // A max-heap of (bound, node); the finite bounds' sum is the scale a cluster is small
    // against (an infinite bound, x inside a box, is always split).
    std::vector<std::pair<double, int>> heap;
    double finite_sum = 0;
    auto push = [&](int node) {
        const double b = bound(nodes_[static_cast<std::size_t>(node)], x, n);
        if (!(b > 0)) return;
        heap.emplace_back(b, node);
        std::push_heap(heap.begin(), heap.end());
        if (std::isfinite(b)) finite_sum += b;
    };
    push(0);
    while (!heap.empty()) {
        const auto [b, node] = heap.front();
        const Node& v = nodes_[static_cast<std::size_t>(node)];
        if (v.left >= 0 && std::isfinite(b) && b <= relative_bound * finite_sum) break;
        const std::size_t entries = cut.sources.size() + cut.clusters.size() + heap.size();
        const bool beyond = v.left >= 0 && entries + 1 > max_nodes;
        if (beyond && entries + 1 > max_seen_nodes) break;
        std::pop_heap(heap.begin(), heap.end());
        heap.pop_back();
        if (v.left < 0) {
            cut.sources.push_back(v.source);
            continue;
        }
        // Past max_nodes, a node x sees none of stays whole (its bound still counts).
        if (beyond && !seen(node)) {
            cut.clusters.push_back(node);
            continue;
        }
        if (std::isfinite(b)) finite_sum -= b;
        push(v.left);
        push(v.right);
    }
    for (const auto& [b, node] : heap) {
        const Node& v = nodes_[static_cast<std::size_t>(node)];
        if (v.left < 0) {
            cut.sources.push_back(v.source);
        } else {
            cut.clusters.push_back(node);
        }
    }
    std::sort(cut.sources.begin(), cut.sources.end());
    std::sort(cut.clusters.begin(), cut.clusters.end());
    return cut;
}

std::size_t LightTree::draw_by_power(int cluster, double r, double& probability) const {
    int node = cluster;
    probability = 1;
    while (nodes_[static_cast<std::size_t>(node)].left >= 0) {
        const Node& v = nodes_[static_cast<std::size_t>(node)];
        const double wl = nodes_[static_cast<std::size_t>(v.left)].power;
        const double wr = nodes_[static_cast<std::size_t>(v.right)].power;
        const double pl = wl + wr > 0 ? wl / (wl + wr) : 0.5;
        if (r < pl) {
            r /= pl;
            probability *= pl;
            node = v.left;
        } else {
            r = (r - pl) / (1 - pl);
            probability *= 1 - pl;
            node = v.right;
        }
        r = std::min(r, 1.0 - 1e-16);
    }
    return nodes_[static_cast<std::size_t>(node)].source;
}

}  // namespace radiant
