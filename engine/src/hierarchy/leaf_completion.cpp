#include "hierarchy/leaf_completion.h"

#include <algorithm>

namespace radiant {
namespace {

// The inherited light changes by at most this factor either way; a leaf that would need more
// (its inherited links carry little of its light, or its own links alone exceed the sum) has the
// rest spread over all its links alike.
constexpr double kMaxInheritedChange = 2;

// The sum a leaf's factors are completed to: the share of its hemisphere that ends on surface
// fronts. The rays' share is known far better than the links' sum, except where little of the
// hemisphere is covered (its error relative to the share grows), so a leaf that sees mostly
// nothing keeps its own sum. No leaf's may exceed 1 — light from everything it sees is at most
// all its hemisphere — though a cluster's disk kernels, or a near-singular source, can make it
// look so, and a sum above 1/ρ would let light grow unbounded.
double target_sum(double front_share, double factor_sum) {
    if (completes_leaf(front_share, factor_sum)) return front_share;
    return std::min(factor_sum, 1.0);
}

struct Scales {
    double own, inherited;
};

// Scales that make `own` + `inherited` sum to `target`, changing the inherited part first.
Scales split(double target, double own, double inherited) {
    if (!(inherited > 0)) return {own > 0 ? target / own : 1.0, 1.0};
    const double wanted = (target - own) / inherited;
    const double bounded = std::clamp(wanted, 1 / kMaxInheritedChange, kMaxInheritedChange);
    const double rest = target / (own + bounded * inherited);
    return {rest, bounded * rest};
}

}  // namespace

LeafCompletion complete_leaves(const ElementTree& tree, std::span<const double> front_share) {
    const std::size_t n = tree.size();
    LeafCompletion out;
    out.own_scale.assign(n, 1.0);
    out.inherited_scale.assign(n, 1.0);
    out.factor_sum.assign(n, 0.0);
    out.completed_sum.assign(n, 0.0);
    out.weight.assign(n, 0.0);
    // Each surface element's inherited sum: its ancestors' factors (a parent comes before its
    // children).
    std::vector<double> inherited(n, 0.0);
    for (std::size_t e = 0; e < n; ++e) {
        const Element& x = tree[e];
        if (x.cluster || x.depth == 0) continue;
        const auto p = static_cast<std::size_t>(x.parent);
        inherited[e] = inherited[p] + tree[p].link_factor_sum;
    }
    for (std::size_t e = n; e-- > 0;) {
        const Element& x = tree[e];
        if (x.cluster) continue;
        double passed_up = out.weight[e];
        if (x.leaf()) {
            const double own = x.link_factor_sum, sum = own + inherited[e];
            const Scales s = split(target_sum(front_share[static_cast<std::size_t>(x.patch)], sum),
                                   own, inherited[e]);
            out.own_scale[e] = s.own;
            out.inherited_scale[e] = s.inherited;
            out.factor_sum[e] = sum;
            out.completed_sum[e] = s.own * own + s.inherited * inherited[e];
            out.weight[e] = x.area_m2 * s.own;
            passed_up = x.area_m2 * s.inherited;
        }
        if (x.depth > 0) out.weight[static_cast<std::size_t>(x.parent)] += passed_up;
    }
    return out;
}

}  // namespace radiant
