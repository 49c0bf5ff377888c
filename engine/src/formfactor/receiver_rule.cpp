#include "formfactor/receiver_rule.h"

#include <algorithm>
#include <cmath>

#include "geometry/median_split.h"
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

// The rule only distinguishes ratios below 0.5, below 1.5 and above: a neighbour further than
// this many diameters away cannot change it.
constexpr double kFarthestThatMatters = 2.0;
// Patches per leaf of the centroid tree.
constexpr std::size_t kLeafPatches = 8;

// The patches in a k-d tree of their centroids (median splits along the longest axis), each node
// with its centroids' bounds and its patches' largest radius, so that nearness() visits only the
// nodes that can hold a patch nearer than the nearest found so far. A sweep along x with the
// scene's largest patch as its reach visited a fifth of the furnished office's 140 000 patches
// for each of them (16 s).
class CentroidTree {
public:
    explicit CentroidTree(const PatchMesh& patches) : patches_(patches), order_(patches.size()) {
        for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = i;
        if (!order_.empty()) build(0, order_.size());
    }

    /// Calls `visit(j)` for the patches j whose distance |Δc| − radius_j from `c` may be below
    /// `bound()`, which may shrink as they are visited.
    template <class Visit, class Bound>
    void visit_near(const Vec3& c, Visit&& visit, Bound&& bound) const {
        if (!nodes_.empty()) visit_node(0, c, visit, bound);
    }

private:
    struct Node {
        Vec3 lo, hi;
        double max_radius = 0;
        std::size_t begin = 0, end = 0;
        std::size_t left = 0, right = 0;  // 0: a leaf (the root is never a child)
    };

    const Vec3& centroid(std::size_t k) const { return patches_.patch(order_[k]).centroid; }

    std::size_t build(std::size_t begin, std::size_t end) {
        const std::size_t at = nodes_.size();
        nodes_.emplace_back();
        Node node;
        node.begin = begin;
        node.end = end;
        node.lo = node.hi = centroid(begin);
        for (std::size_t k = begin; k < end; ++k) {
            const PatchGeometry& p = patches_.patch(order_[k]);
            for (int a = 0; a < 3; ++a) {
                node.lo[a] = std::min(node.lo[a], p.centroid[a]);
                node.hi[a] = std::max(node.hi[a], p.centroid[a]);
            }
            node.max_radius = std::max(node.max_radius, 0.5 * p.diameter_m);
        }
        if (end - begin > kLeafPatches) {
            const std::size_t mid =
                split_at_median(order_, begin, end, node.hi - node.lo,
                                [&](std::size_t i) { return patches_.patch(i).centroid; });
            node.left = build(begin, mid);
            node.right = build(mid, end);
        }
        nodes_[at] = node;
        return at;
    }

    // Distance from c to the node's centroid bounds.
    static double box_distance(const Node& n, const Vec3& c) {
        double d2 = 0;
        for (int a = 0; a < 3; ++a) {
            const double d = std::max({n.lo[a] - c[a], 0.0, c[a] - n.hi[a]});
            d2 += d * d;
        }
        return std::sqrt(d2);
    }

    template <class Visit, class Bound>
    void visit_node(std::size_t at, const Vec3& c, Visit& visit, Bound& bound) const {
        const Node& n = nodes_[at];
        if (box_distance(n, c) - n.max_radius >= bound()) return;
        if (n.left == 0) {
            for (std::size_t k = n.begin; k < n.end; ++k) visit(order_[k]);
            return;
        }
        const bool left_first = box_distance(nodes_[n.left], c) <= box_distance(nodes_[n.right], c);
        visit_node(left_first ? n.left : n.right, c, visit, bound);
        visit_node(left_first ? n.right : n.left, c, visit, bound);
    }

    const PatchMesh& patches_;
    std::vector<std::size_t> order_;
    std::vector<Node> nodes_;
};

// Size of patch i over its distance to the nearest patch it exchanges light with at an angle.
// Neighbours within ~25° of coplanar (facets of a curved surface) see each other at grazing
// angles only, so they do not call for the fine rule the kernel singularity of a corner needs.
// Only neighbours nearer than kFarthestThatMatters diameters are looked for; when there is none
// the ratio is below 1 / kFarthestThatMatters either way.
double nearness(const PatchMesh& patches, const CentroidTree& tree, std::size_t i) {
    const PatchGeometry& p = patches.patch(i);
    if (!(p.diameter_m > 0)) return 0;
    // A margin keeps rounding on the safe side.
    double nearest = kFarthestThatMatters * p.diameter_m * 1.001;
    tree.visit_near(
        p.centroid,
        [&](std::size_t j) {
            if (j == i) return;
            const PatchGeometry& q = patches.patch(j);
            if (dot(q.normal, p.normal) > 0.9) return;
            if (dot(q.centroid - p.centroid, p.normal) <= 1e-9 * p.diameter_m ||
                dot(p.centroid - q.centroid, q.normal) <= 1e-9 * p.diameter_m) {
                return;
            }
            const double d = length(q.centroid - p.centroid) - 0.5 * q.diameter_m;
            nearest = std::min(nearest, std::max(d, 1e-300));
        },
        [&] { return nearest; });
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
    const CentroidTree tree(patches);
    parallel_for(0, patches.size(), [&](std::size_t i) {
        const auto& poly = patches.patch(i).vertices;
        const double ratio = nearness(patches, tree, i);
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
