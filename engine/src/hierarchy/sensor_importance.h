// Importance (Smits, Arvo & Salesin 1992): how much each surface's radiosity adds to what the
// sensors read, directly or after reflections — the adjoint of light transport, W = g + Mᵀ W.
// Linking uses it to leave alone what the sensors cannot see: a link's allowed power error is
// divided by its receiver's weight, so a room no sensor looks into stays coarse, while
// everything the sensors see directly or by a reflection keeps the full accuracy.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "hierarchy/element_tree.h"
#include "meshing/patch_mesh.h"
#include "scene/prepared_scene.h"
#include "visibility/visibility.h"

namespace radiant {

struct ImportanceEstimate {
    /// Per root patch: importance per unit area (expected visits per walk and m²); all 0 without
    /// sensors.
    std::vector<double> per_area;
    /// Per root patch, in [kMinRefinementWeight, 1]: the share of the full accuracy linking owes
    /// light arriving on it. All 1 without sensors.
    std::vector<double> refinement_weight;
    std::uint64_t rays = 0;
};

/// Weight of a patch the sensors cannot see at all: its links may carry 4× the uncertain power,
/// not more, since surfaces' averages are reported too (at 1/16, a wall of a sealed room came
/// out 0.6 % bright at tolerance 0.01, a bias the estimate's check did not see).
inline constexpr double kMinRefinementWeight = 1.0 / 4;

/// Walks leave the sensor points in cosine-distributed directions (as the light they measure
/// arrives) and bounce off surfaces as diffuse light does, going on with each reflectance's
/// probability: the expected visits of a walk to a root patch (`roots`, the elements of `tree`
/// at depth 0) are that patch's importance per unit radiosity. A patch's refinement weight is its
/// importance per area against the mean over all root patches, with a margin (what a sensor sees
/// directly or by one reflection stays at 1). About `walks_per_patch` walks per root patch, at
/// least one per sensor point; deterministic in `seed` for any thread count.
ImportanceEstimate estimate_sensor_importance(const PreparedScene& scene, const PatchMesh& roots,
                                              const ElementTree& tree, const Visibility& visibility,
                                              std::span<const int> triangle_piece,
                                              std::uint64_t seed,
                                              const std::function<bool()>& should_stop = {},
                                              int walks_per_patch = 16);

}  // namespace radiant
