// Sensor illuminance from the solved hierarchy by a final gather that descends the tree only
// where it matters: a node whose largest radiosity times an upper bound of its form factor is
// below the budget contributes as a whole; otherwise its children are visited, down to the
// leaves, which contribute exactly (Lambert's factor × sampled visibility). Luminaires are exact.
#pragma once

#include <cstdint>
#include <vector>

#include "hierarchy/element_tree.h"
#include "radiant/result.h"
#include "scene/prepared_scene.h"
#include "visibility/visibility.h"

namespace radiant {

struct GatherCriteria {
    double irradiance_epsilon = 0;  ///< lux a node may contribute without being opened
    std::uint64_t seed = 1;
    int rays_per_point = 4;
    int emitter_rays_per_point = 16;
    /// Views of leaves seen in part get up to this many rays, until the sampled visibility's
    /// standard deviation is at most noise_share × the point's illuminance (0: never).
    int max_rays_per_point = 256;
    double noise_share = 0;
    bool unoccluded = false;      ///< nothing can block (see nothing_can_occlude): no shadow rays
    bool with_luminaires = true;  ///< false: the tree's light only
};

/// Illuminance (lux; luminance of the RGB irradiance for colour scenes) at every sensor point.
/// Parallel over points; deterministic.
std::vector<SensorResult> gather_sensors_from_tree(const PreparedScene& scene,
                                                   const ElementTree& tree,
                                                   const Visibility& visibility,
                                                   const GatherCriteria& criteria, int channels,
                                                   std::uint64_t& rays);

}  // namespace radiant
