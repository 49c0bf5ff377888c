// A binary tree over the light sources (luminaires and emitting pieces), so that the light at a
// point is found from the few sources that matter in O(log n) instead of by visiting every
// source of a floor of many rooms. Two uses:
//   draw   one source in rough proportion to what it sends to the point, by descending the tree
//          (after Conty Estevez & Kulla 2018, "Importance sampling of many lights with adaptive
//          tree splitting"), with the probability of any source found by walking up;
//   cut    the sources near enough to matter, each on its own, and clusters whose bound on the
//          unoccluded light they could send is small, each to be sampled by power (after
//          Walter et al. 2005, "Lightcuts").
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "radiant/box.h"
#include "radiant/vec3.h"

namespace radiant {

/// What the tree knows of one source.
struct LightTreeSource {
    Box bounds;          ///< every point that emits
    double power = 0;    ///< photometric lm
    double peak_cd = 0;  ///< the largest photometric intensity toward any direction (cd)
    /// An emitting piece's front (unit): it sends light only to the side it faces; zero for a
    /// source that may send light any way (a luminaire).
    Vec3 normal{0, 0, 0};
};

/// The sources near a point, each on its own, and the clusters (tree nodes) of the others.
struct LightCut {
    std::vector<std::size_t> sources;  ///< ascending
    std::vector<int> clusters;
};

class LightTree {
public:
    LightTree() = default;
    explicit LightTree(std::span<const LightTreeSource> sources);

    /// The cut at point x with unit normal n: a node is split while its bound on the unoccluded
    /// illuminance at x (peak intensity over the squared distance to its box) exceeds
    /// `relative_bound` times the sum of the bounds over the cut, and the cut has fewer than
    /// `max_nodes` entries, or fewer than `max_seen_nodes` and `seen(node)` says x sees some of
    /// the node's sources (a lamp's bulb beside x is worth a shadow ray per piece, the panels of
    /// rooms behind walls are not); boxes wholly behind x's tangent plane are left out (they send
    /// nothing). With at most `max_nodes` sources every source is on its own.
    LightCut cut(const Vec3& x, const Vec3& n, double relative_bound, std::size_t max_nodes,
                 std::size_t max_seen_nodes = 0, const std::function<bool(int)>& seen = {}) const;

    /// A source of `cluster` drawn by power from uniform r, and its probability within it.
    std::size_t draw_by_power(int cluster, double r, double& probability) const;

    /// A source drawn from uniform r with the probability of each step in proportion to the
    /// children's importance at (x, n): `leaf(source)` for sources, a rough estimate for
    /// clusters. Returns false where every way down has no importance.
    template <class Leaf>
    bool draw(const Vec3& x, const Vec3& n, double r, const Leaf& leaf, std::size_t& source,
              double& probability) const;

    /// The probability that draw() returns `source` at (x, n).
    template <class Leaf>
    double probability(std::size_t source, const Vec3& x, const Vec3& n, const Leaf& leaf) const;

private:
    struct Node {
        Box bounds;
        Vec3 centre;  ///< power-weighted
        double power = 0;
        double peak_cd = 0;
        /// The cone of its sources' fronts: an axis and the cosine of its half angle (−1: they
        /// may face any way).
        Vec3 axis{0, 0, 0};
        double cos_spread = -1;
        double sin_spread = 0;
        /// The radius of the bounds' sphere, kept for facing(), which every draw and cut calls
        /// at each node.
        double sphere_radius = 0;
        int left = -1, right = -1;  ///< children; both -1 for a source's leaf
        int parent = -1;
        std::size_t source = 0;  ///< a leaf's source
    };
    int build(std::vector<std::size_t>& order, std::size_t begin, std::size_t end,
              std::span<const LightTreeSource> sources, int parent);
    double bound(const Node& node, const Vec3& x, const Vec3& n) const;
    /// The largest cosine between any source's front in `node` and the direction to x: 1 where
    /// their fronts may face any way or x is within the bounds' sphere, 0 where all face away.
    double facing(const Node& node, const Vec3& x) const;
    double cluster_importance(const Node& node, const Vec3& x, const Vec3& n) const;
    template <class Leaf>
    double importance(int node, const Vec3& x, const Vec3& n, const Leaf& leaf) const {
        const Node& v = nodes_[static_cast<std::size_t>(node)];
        return v.left < 0 ? leaf(v.source) : cluster_importance(v, x, n);
    }

    std::vector<Node> nodes_;  ///< the root first
    std::vector<int> leaf_of_;
};

template <class Leaf>
bool LightTree::draw(const Vec3& x, const Vec3& n, double r, const Leaf& leaf, std::size_t& source,
                     double& probability) const {
    int node = 0;
    probability = 1;
    while (nodes_[static_cast<std::size_t>(node)].left >= 0) {
        const Node& v = nodes_[static_cast<std::size_t>(node)];
        const double wl = importance(v.left, x, n, leaf), wr = importance(v.right, x, n, leaf);
        if (!(wl + wr > 0)) return false;
        const double pl = wl / (wl + wr);
        if (r < pl) {
            r /= pl;
            probability *= pl;
            node = v.left;
        } else {
            r = pl < 1 ? (r - pl) / (1 - pl) : 0.0;
            probability *= 1 - pl;
            node = v.right;
        }
        r = std::min(r, 1.0 - 1e-16);
    }
    source = nodes_[static_cast<std::size_t>(node)].source;
    return probability > 0;
}

template <class Leaf>
double LightTree::probability(std::size_t source, const Vec3& x, const Vec3& n,
                              const Leaf& leaf) const {
    double p = 1;
    for (int node = leaf_of_[source]; nodes_[static_cast<std::size_t>(node)].parent >= 0;) {
        const int up = nodes_[static_cast<std::size_t>(node)].parent;
        const Node& u = nodes_[static_cast<std::size_t>(up)];
        const int sibling = u.left == node ? u.right : u.left;
        const double w = importance(node, x, n, leaf), ws = importance(sibling, x, n, leaf);
        if (!(w > 0)) return 0;
        p *= w / (w + ws);
        node = up;
    }
    return p;
}

}  // namespace radiant
