// Linking the element hierarchy (Hanrahan, Salzman & Aupperle 1991, with clusters after Smits,
// Arvo & Greenberg 1994): starting from the top cluster's link to itself, a pair of elements is
// linked when the light it carries is known well enough, otherwise the larger one is split and
// its children are tried. The oracle works in power: the spread of the kernel over the
// receiver's points (and partial visibility) times the source's radiosity times the receiver's
// area, and the spread of the kernel over the source's points times the range of its radiosity
// times its area, against a fraction of the scene's emitted power, raised where the receiver
// matters little to the sensors (importance). Links are made lazily, when their sources are
// about to shoot (see RefinementCriteria::ready_source): pairs whose sources are not ready wait.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "hierarchy/element_tree.h"
#include "visibility/visibility.h"

namespace radiant {

/// Irradiance on `receiver` = factor × radiosity of `source` (area averages over both). Where the
/// source has children, its radiosity is theirs weighted by `child_share` (see handed_radiosity).
struct Link {
    int receiver;
    int source;
    float factor;
    /// Each child's share of the factor, in 255ths; all 0: the children's area shares.
    std::array<std::uint8_t, 4> child_share{};
    /// Σ child_share; 0 when the children hand on light by their areas.
    int share_total() const {
        return child_share[0] + child_share[1] + child_share[2] + child_share[3];
    }
};

/// The radiosity `link` hands on, from `value(element)` (its radiosity, or what it has not shot
/// yet): the source's children's weighted by their shares of the factor where they are set, so
/// that a source lit unevenly (the floor under a panel, brightest where the panel sees it best)
/// hands on the light the receiver sees of it, not its mean.
template <class Value>
Rgb handed_radiosity(const Link& link, const ElementTree& tree, const Value& value) {
    const int total = link.share_total();
    if (total == 0) return value(link.source);
    const std::vector<int>& children = tree[static_cast<std::size_t>(link.source)].children;
    Rgb b{0, 0, 0};
    for (std::size_t c = 0; c < children.size(); ++c) {
        const Rgb& v = value(children[c]);
        for (std::size_t k = 0; k < 3; ++k) b[k] += link.child_share[c] * v[k];
    }
    for (double& x : b) x /= total;
    return b;
}

/// Two elements whose exchange of light is still to be judged: `receiver` from `source`.
struct ElementPair {
    int receiver;
    int source;
};

struct RefinementCriteria {
    double power_epsilon_lm = 0;  ///< a link may carry at most this much uncertain power
    /// Mean radiosity of all surfaces (first guess): the light a closed receiver's factor-sum
    /// completion spreads over an error in a factor, whatever the source's own radiosity.
    double mean_radiosity = 0;
    int rays_per_point = 4;   ///< shadow rays per receiver point toward a surface source
    bool unoccluded = false;  ///< nothing can block (see nothing_can_occlude): no shadow rays
    std::uint64_t seed = 1;
    double ambient_irradiance = 0;  ///< guess of the reflected light, for new elements' estimates
    int channels = 1;
    /// Memory budget of the tree, the links and what the solve will hold per element once they
    /// are made (`later_bytes_per_element`: the linked system's arrays, leaf meshes, summaries);
    /// 0: none.
    std::size_t max_bytes = 0;
    std::size_t later_bytes_per_element = 0;
    /// Root patches whose factor sums the solver completes (see HierarchicalSystem): their
    /// near-singular links keep the mean over their points, which completion assumes.
    std::span<const char> completed_patch;
    /// Per root patch, in (0, 1]: its share of the sensors' importance (see sensor_importance.h);
    /// links into it may carry power_epsilon_lm / weight uncertain. Empty: all 1.
    std::span<const double> receiver_weight;
    /// Per root patch: whether links from it are made now. A pair whose source holds no ready
    /// patch waits (RefinementOutcome::deferred); a cluster is judged once any patch in it is
    /// (its link carries the light of all its parts). Empty: every patch is ready.
    std::span<const char> ready_source;
    std::function<bool()> should_stop;  ///< polled between rounds and pairs, from any thread
    /// Told after each round: rounds done, rays cast and links made so far.
    std::function<void(int rounds, std::uint64_t rays, std::size_t links)> on_round;
};

struct RefinementOutcome {
    std::vector<Link> links;            ///< sorted by receiver, then source
    std::vector<ElementPair> deferred;  ///< pairs whose sources were not ready (see resume_links)
    int rounds = 0;                     ///< rounds of refinement so far
    std::uint64_t rays = 0;
    bool stopped = false;         ///< cancelled or out of time: pairs were left unlinked
    bool budget_reached = false;  ///< elements stopped splitting at the memory budget
};

/// Links every pair of elements that exchange light and whose source is ready (see
/// RefinementCriteria::ready_source). Splits elements of `tree` as it goes (and lights the new
/// ones); uses `radiosity_max` and `radiosity_min` of the elements as the source estimate.
/// Once the tree and links would outgrow `max_bytes`, pairs link where they stand instead.
/// Links from sources that ended up with children get the children's shares (see Link).
/// Parallel over candidate pairs; deterministic for any thread count.
RefinementOutcome refine_links(ElementTree& tree, const Visibility& visibility,
                               const RefinementCriteria& criteria);

/// Goes on with `outcome.deferred` as refine_links does, now that `criteria` may have more
/// sources ready, adding to `outcome.links` (still sorted, every link's shares made anew).
void resume_links(RefinementOutcome& outcome, ElementTree& tree, const Visibility& visibility,
                  const RefinementCriteria& criteria);

}  // namespace radiant
