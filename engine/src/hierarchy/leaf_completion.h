// How the hierarchical solver completes each leaf's factor sum. In a closed enclosure a leaf sees
// surfaces over all its hemisphere, so its factors should sum to 1; its links' sum is off by a few
// per cent, and through the links it inherits: an ancestor's link averages the kernel over the
// ancestor's points, which for a leaf by a wall see the far surfaces more and the wall less than
// the leaf does (an edge leaf of a cube's ceiling: 1.18). The leaf's own links average the kernel
// over its own points, so the completion changes the inherited light first.
#pragma once

#include <span>
#include <vector>

#include "hierarchy/element_tree.h"

namespace radiant {

/// The solver completes the factor sums of a patch whose hemisphere ends on surface fronts
/// over at least this share of it (see complete_leaves).
constexpr double kMinFrontShare = 0.5;
inline bool completes(double front_share) { return front_share >= kMinFrontShare; }
/// Whether a leaf whose factors sum to `factor_sum` is completed to its patch's front share
/// (otherwise it keeps its sum, at most 1).
inline bool completes_leaf(double front_share, double factor_sum) {
    return factor_sum > 0 && completes(front_share);
}

struct LeafCompletion {
    std::vector<double> own_scale;        ///< leaves: the light through their own links × this
    std::vector<double> inherited_scale;  ///< leaves: the light through their ancestors' × this
    std::vector<double> factor_sum;       ///< leaves: their and their ancestors' factors' sum
    std::vector<double> completed_sum;    ///< leaves: what those factors sum to once scaled
    /// Per element, the light per unit irradiance its links pass on to its leaves: a leaf's area ×
    /// its own scale; an interior element's, Σ over its leaves of area × their inherited scale.
    std::vector<double> weight;
};

/// Completes every leaf's factors (element e's own sum in `tree[e].link_factor_sum`) to sum to
/// the share of its patch's hemisphere that ends on surface fronts (`front_share`, 1 where
/// enclosed) where that share completes(); no leaf's may exceed 1.
LeafCompletion complete_leaves(const ElementTree& tree, std::span<const double> front_share);

}  // namespace radiant
